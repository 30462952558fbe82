#include "dg/dg_discretization.hpp"

#include <algorithm>
#include <span>
#include <stdexcept>

#include "shared/solve/additive_schwarz_preconditioner.hpp"
#include "shared/solve/block_relaxation_preconditioner.hpp"
#include "shared/solve/process_ranks.hpp"
#include "shared/solve/two_level_preconditioner.hpp"

namespace altfem::dg {

namespace {

// Whether every entry of `inner`'s pattern is in `outer`'s (both compressed, sorted).
bool pattern_contains(const Eigen::SparseMatrix<double>& outer, const Eigen::SparseMatrix<double>& inner) {
  for (Eigen::Index column = 0; column < inner.outerSize(); ++column) {
    const int* begin = outer.innerIndexPtr() + outer.outerIndexPtr()[column];
    const int* end = outer.innerIndexPtr() + outer.outerIndexPtr()[column + 1];
    for (Eigen::SparseMatrix<double>::InnerIterator entry(inner, column); entry; ++entry)
      if (!std::binary_search(begin, end, static_cast<int>(entry.row()))) return false;
  }
  return true;
}

// `matrix` on the union of its pattern and `other`'s: the integrators add value arrays
// of the Hessian and the mass, so both must share one pattern (explicit zeros kept).
Eigen::SparseMatrix<double> on_union_pattern(const Eigen::SparseMatrix<double>& matrix,
                                             const Eigen::SparseMatrix<double>& other) {
  Eigen::SparseMatrix<double> result = matrix + 0.0 * other;
  result.makeCompressed();
  return result;
}

// ω of the two-level V-cycle's block Jacobi smoother: undamped (ω = 1) it does not contract
// in the energy norm on DG (λ_max(SA) > 2) and PCG needs 160-200 iterations on the 10³ grid of
// bench_dg_table1; ω = 0.5, 0.6, 0.7, 0.8, 0.9 took 13, 11, 10, 10, 15 iterations (k = 1) and
// 66, 60, 55, 52, 50 (k = 2).
constexpr double two_level_smoother_damping = 0.8;

// The first DOF of every element and the end of the last: DG's element blocks are
// consecutive DOF ranges (cell c's [3 offset(c), 3 offset(c + 1))), as block relaxation needs.
std::vector<int> element_starts(const std::vector<std::vector<int>>& element_dofs) {
  std::vector<int> starts{0};
  for (const std::vector<int>& dofs : element_dofs) {
    for (size_t i = 0; i < dofs.size(); ++i)
      if (dofs[i] != starts.back() + static_cast<int>(i))
        throw std::logic_error("dg: the element blocks are not consecutive DOF ranges in cell order");
    starts.push_back(starts.back() + static_cast<int>(dofs.size()));
  }
  return starts;
}

// The fine-level smoother of the two-level and multilevel cycles: block Jacobi, each element
// block inverted by Cholesky (K is positive definite on the linear path these serve).
std::unique_ptr<Preconditioner> element_block_jacobi(const std::vector<int>& starts) {
  return std::make_unique<BlockRelaxationPreconditioner>(starts, BlockRelaxation::jacobi);
}

}  // namespace

LinearDgDiscretization::LinearDgDiscretization(Eigen::SparseMatrix<double> stiffness, Eigen::SparseMatrix<double> mass,
                                               Eigen::VectorXd function_integrals,
                                               std::vector<std::vector<int>> element_dofs,
                                               std::function<Eigen::VectorXd(double)> weak_condition_load,
                                               DirichletDofs strong, std::vector<int> share_row_owners)
    : function_integrals_(std::move(function_integrals)),
      element_dofs_(std::move(element_dofs)),
      weak_condition_load_(std::move(weak_condition_load)),
      strong_(std::move(strong)),
      preconditioner_(block_jacobi_factory(element_dofs_)),
      share_row_owners_(std::move(share_row_owners)) {
  // Swapped in: Eigen 3.4's SparseMatrix has no move constructor, std::move would copy.
  stiffness_.swap(stiffness);
  block_mass_.swap(mass);
  // K couples every pair of a cell's functions, so its pattern holds the mass's cell
  // blocks: no copy of K on a union pattern (issue #35: one stiffness fewer in memory).
  stiffness_.makeCompressed();
  block_mass_.makeCompressed();
  if (!pattern_contains(stiffness_, block_mass_)) stiffness_ = on_union_pattern(stiffness_, block_mass_);
}

const ExplicitMass& LinearDgDiscretization::explicit_mass() const {
  if (!explicit_mass_.has_value()) explicit_mass_.emplace(block_mass_, element_dofs_);
  return *explicit_mass_;
}

double LinearDgDiscretization::energy(const Eigen::VectorXd& u) const {
  const double energy = 0.5 * u.dot(stiffness_ * u);
  return share_row_owners_.empty() ? energy : ranks::sum(energy);
}

void LinearDgDiscretization::gradient(const Eigen::VectorXd& u, Eigen::VectorXd& gradient) const {
  gradient = stiffness_ * u;
  if (!share_row_owners_.empty()) ranks::sum(std::span<double>(gradient.data(), static_cast<size_t>(gradient.size())));
}

const Eigen::SparseMatrix<double>& LinearDgDiscretization::mass_matrix() const {
  if (!mass_.has_value()) {
    // K's pattern holds every cell's block (the constructor made sure).
    mass_.emplace(stiffness_);
    std::fill(mass_->valuePtr(), mass_->valuePtr() + mass_->nonZeros(), 0.0);
    add_mass(1.0, *mass_);
  }
  return *mass_;
}

void LinearDgDiscretization::add_mass(double factor, Eigen::SparseMatrix<double>& matrix) const {
  if (matrix.nonZeros() != stiffness_.nonZeros() || matrix.outerSize() != stiffness_.outerSize())
    throw std::logic_error("LinearDgDiscretization::add_mass: the matrix does not have the Hessian's pattern");
  if (mass_positions_.empty() && block_mass_.nonZeros() > 0) {
    mass_positions_.reserve(static_cast<std::size_t>(block_mass_.nonZeros()));
    for (Eigen::Index column = 0; column < block_mass_.outerSize(); ++column) {
      const int* begin = stiffness_.innerIndexPtr() + stiffness_.outerIndexPtr()[column];
      const int* end = stiffness_.innerIndexPtr() + stiffness_.outerIndexPtr()[column + 1];
      // A share adds only its own functions' blocks (−1: another rank's).
      const bool own = share_row_owners_.empty() || share_row_owners_[column / 3] == ranks::index();
      for (Eigen::SparseMatrix<double>::InnerIterator entry(block_mass_, column); entry; ++entry)
        mass_positions_.push_back(
            own ? std::lower_bound(begin, end, static_cast<int>(entry.row())) - stiffness_.innerIndexPtr() : -1);
    }
  }
  const double* mass = block_mass_.valuePtr();
  double* values = matrix.valuePtr();
  for (std::size_t k = 0; k < mass_positions_.size(); ++k)
    if (mass_positions_[k] >= 0) values[mass_positions_[k]] += factor * mass[k];
}

Eigen::VectorXd LinearDgDiscretization::body_force(const Eigen::Vector3d& acceleration) const {
  Eigen::VectorXd load(dof_count());
  for (Eigen::Index a = 0; a < function_integrals_.size(); ++a)
    load.segment<3>(3 * a) = function_integrals_[a] * acceleration;
  return load;
}

PreconditionerFactory block_jacobi_factory(std::vector<std::vector<int>> element_dofs) {
  return [blocks = std::move(element_dofs)]() -> std::unique_ptr<Preconditioner> {
    return std::make_unique<AdditiveSchwarzPreconditioner>(blocks);
  };
}

PreconditionerFactory two_level_factory(std::vector<std::vector<int>> element_dofs,
                                        Eigen::SparseMatrix<double> prolongation) {
  return [starts = element_starts(element_dofs),
          prolongation = std::move(prolongation)]() -> std::unique_ptr<Preconditioner> {
    return std::make_unique<TwoLevelPreconditioner>(element_block_jacobi(starts), prolongation,
                                                    TwoLevelCycle::multiplicative, two_level_smoother_damping);
  };
}

PreconditionerFactory multilevel_factory(std::vector<std::vector<int>> element_dofs,
                                         Eigen::SparseMatrix<double> vertex_prolongation,
                                         std::vector<Eigen::SparseMatrix<double>> grid_prolongations) {
  return [starts = element_starts(element_dofs), vertex_prolongation = std::move(vertex_prolongation),
          grid_prolongations = std::move(grid_prolongations)]() -> std::unique_ptr<Preconditioner> {
    // From the coarsest grid up: each level's cycle is the coarse solve of the one above.
    std::unique_ptr<Preconditioner> coarse;  // null: CHOLMOD on the coarsest level
    for (auto level = grid_prolongations.rbegin(); level != grid_prolongations.rend(); ++level) {
      std::vector<int> vertex_blocks(static_cast<size_t>(level->rows() / 3 + 1));
      for (size_t v = 0; v < vertex_blocks.size(); ++v) vertex_blocks[v] = 3 * static_cast<int>(v);
      auto smoother = std::make_unique<BlockRelaxationPreconditioner>(std::move(vertex_blocks),
                                                                      BlockRelaxation::symmetric_gauss_seidel);
      coarse = std::make_unique<TwoLevelPreconditioner>(std::move(smoother), *level, TwoLevelCycle::multiplicative, 1.0,
                                                        std::move(coarse));
    }
    return std::make_unique<TwoLevelPreconditioner>(element_block_jacobi(starts), vertex_prolongation,
                                                    TwoLevelCycle::multiplicative, two_level_smoother_damping,
                                                    std::move(coarse));
  };
}

}  // namespace altfem::dg
