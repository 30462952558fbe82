#include "dg/warped_dg_discretization.hpp"

#include <omp.h>

#include <Eigen/LU>
#include <algorithm>
#include <span>

#include "dg/exact_element_matrices.hpp"
#include "shared/assembly/parallel_loops.hpp"
#include "shared/material/best_fit_rotation.hpp"
#include "shared/quadrature/polyhedron_rule.hpp"
#include "shared/solve/process_ranks.hpp"

namespace altfem::dg {

struct WarpedDgDiscretization::Parts {
  std::vector<Block> blocks;
  Eigen::SparseMatrix<double> penalty;
  Eigen::SparseMatrix<double> stiffness;  // K on the union of the blocks' and K_3's patterns
  std::vector<Eigen::MatrixXd> affine_fit;
  std::vector<DirichletFace> dirichlet_faces;
};

namespace {

// 3 × n: row d holds ∂/∂x_d of the L2(K) projection of each φ_a onto the affine fields
// {1, ξ, η, ζ} (ξ = (x − c)/s, the basis's own linear monomials): P = M₁₁⁻¹ M₁ with M the
// element mass matrix, so ∇(fit of u) = Σ_a u_a ⊗ row(P)/s (Kaufmann et al. 2009 §6.1,
// "fitting an affine transformation ... in the least squares sense").
Eigen::MatrixXd affine_fit_gradients(const Eigen::MatrixXd& mass, const MonomialBasis& basis) {
  const int affine[4] = {0, monomial_index(1, 0, 0), monomial_index(0, 1, 0), monomial_index(0, 0, 1)};
  Eigen::Matrix4d affine_mass;
  Eigen::MatrixXd mixed(4, mass.cols());
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) affine_mass(i, j) = mass(affine[i], affine[j]);
    mixed.row(i) = mass.row(affine[i]);
  }
  const Eigen::MatrixXd projection = affine_mass.inverse() * mixed;  // 4 × n
  return projection.bottomRows(3) / basis.scale();
}

// ρ ∫ φ_a φ_b over `cell` (#functions square) from the system's mass (DOF 3a + i): the
// affine fit's projection does not depend on the density.
Eigen::MatrixXd cell_mass(const Eigen::SparseMatrix<double>& mass, const DgLinearSystem& system, int cell) {
  const int first = system.offset(cell), count = system.offset(cell + 1) - first;
  Eigen::MatrixXd result(count, count);
  for (int b = 0; b < count; ++b)
    for (int a = 0; a < count; ++a) result(a, b) = mass.coeff(3 * (first + a), 3 * (first + b));
  return result;
}

// The block's DOFs as a list.
template <typename Ranges>
std::vector<int> dofs_of(const Ranges& ranges) {
  std::vector<int> dofs;
  for (const auto& range : ranges)
    for (int k = 0; k < range.count; ++k) dofs.push_back(range.first + k);
  return dofs;
}

}  // namespace

WarpedDgDiscretization::WarpedDgDiscretization(const DgLinearSystem& system, const DgSettings& settings,
                                               Eigen::VectorXd function_integrals,
                                               std::vector<std::vector<int>> element_dofs,
                                               std::function<Eigen::VectorXd(double)> penalty_data_load,
                                               ConditionTrajectory trajectory)
    : WarpedDgDiscretization(warped_parts(system, settings), system, std::move(function_integrals),
                             std::move(element_dofs), std::move(penalty_data_load), std::move(trajectory)) {}

WarpedDgDiscretization::WarpedDgDiscretization(Parts parts, const DgLinearSystem& system,
                                               Eigen::VectorXd function_integrals,
                                               std::vector<std::vector<int>> element_dofs,
                                               std::function<Eigen::VectorXd(double)> penalty_data_load,
                                               ConditionTrajectory trajectory)
    : LinearDgDiscretization(parts.stiffness, system.mass(), std::move(function_integrals), std::move(element_dofs),
                             std::move(penalty_data_load), {}, system.share_row_owners()),
      divided_(ranks::distributed()),
      blocks_(std::move(parts.blocks)),
      trajectory_(std::move(trajectory)),
      affine_fit_(std::move(parts.affine_fit)) {
  if (trajectory_) {
    dirichlet_faces_ = std::move(parts.dirichlet_faces);
    data_moments_.resize(dirichlet_faces_.size());
    set_time(0);
  }
  const Eigen::SparseMatrix<double>& pattern = hessian_pattern();
  penalty_ = parts.penalty + 0.0 * pattern;  // on the pattern (explicit zeros kept)
  penalty_.makeCompressed();
  // Where each block column's ranges start in the pattern's value array: the block's
  // rows are all stored (its dense pattern is part of K's), so a range is contiguous.
  for (Block& block : blocks_) {
    for (int column : dofs_of(block.ranges))
      for (const DofRange& range : block.ranges) {
        const int* begin = pattern.innerIndexPtr() + pattern.outerIndexPtr()[column];
        const int* end = pattern.innerIndexPtr() + pattern.outerIndexPtr()[column + 1];
        block.value_index.push_back(
            static_cast<int>(std::lower_bound(begin, end, range.first) - pattern.innerIndexPtr()));
      }
  }
  std::vector<int> cell_dofs;  // each element's first DOF
  for (int cell = 0; cell < system.cell_count(); ++cell) cell_dofs.push_back(3 * system.offset(cell));
  // Scratch for as many threads as OpenMP has now; later loops never run on more.
  element_blocks_.resize(static_cast<size_t>(system.cell_count()));
  force_offsets_.push_back(0);
  Eigen::Index largest = 0;
  for (int b = 0; b < static_cast<int>(blocks_.size()); ++b) {
    int position = 0;
    for (int r = 0; r < static_cast<int>(blocks_[b].ranges.size()); ++r) {
      const DofRange& range = blocks_[b].ranges[r];
      const int element =
          static_cast<int>(std::upper_bound(cell_dofs.begin(), cell_dofs.end(), range.first) - cell_dofs.begin()) - 1;
      element_blocks_[element].push_back({b, r, position});
      position += range.count;
    }
    force_offsets_.push_back(force_offsets_.back() + position);
    largest = std::max(largest, blocks_[b].matrix.rows());
  }
  block_energies_.resize(blocks_.size());
  block_forces_.resize(force_offsets_.back());
  scratch_.resize(static_cast<size_t>(omp_get_max_threads()));
  for (Scratch& scratch : scratch_)
    for (Eigen::VectorXd* vector : {&scratch.rest, &scratch.z, &scratch.jump, &scratch.force}) vector->resize(largest);
  // X⁰ (§6.2): x = c·1 + s·ξ e_x + s·η e_y + s·ζ e_z in the centred, scaled monomials.
  rest_state_ = Eigen::VectorXd::Zero(dof_count());
  cell_offsets_.push_back(0);
  for (int cell = 0; cell < system.cell_count(); ++cell) {
    const MonomialBasis& basis = system.basis(cell);
    const int first = 3 * system.offset(cell);
    rest_state_.segment<3>(first) = basis.centre();
    for (int d = 0; d < 3; ++d) {
      const Eigen::Vector3i exponent = Eigen::Vector3i::Unit(d);
      rest_state_[first + 3 * monomial_index(exponent[0], exponent[1], exponent[2]) + d] = basis.scale();
    }
    cell_offsets_.push_back(system.offset(cell + 1));
  }
}

WarpedDgDiscretization::Parts WarpedDgDiscretization::warped_parts(const DgLinearSystem& system,
                                                                   const DgSettings& settings) {
  using Range = DofRange;
  Parts parts;
  std::vector<Eigen::Triplet<double>> penalty, pattern;
  const auto add = [&](std::vector<Range> ranges, int element, Eigen::MatrixXd matrix) {
    const std::vector<int> dofs = dofs_of(ranges);
    for (int row : dofs)
      for (int column : dofs) pattern.emplace_back(row, column, 0.0);
    parts.blocks.push_back({std::move(ranges), element, std::move(matrix), false, {}, {}});
  };
  const auto range_of = [&](int cell) {
    return Range{3 * system.offset(cell), 3 * (system.offset(cell + 1) - system.offset(cell))};
  };
  // Every cell's rotation (a face's block may take the other side's), from the mass every
  // rank holds whole; over several ranks only the rank's own cells' and faces' blocks.
  const Eigen::SparseMatrix<double> mass = system.mass();
  for (int cell = 0; cell < system.cell_count(); ++cell) {
    parts.affine_fit.push_back(affine_fit_gradients(cell_mass(mass, system, cell), system.basis(cell)));
    if (!system.owns_cell(cell)) continue;
    const DgMaterial material = system.material(cell);
    ElementMatrices matrices =
        exact_element_matrices(system.cell(cell), system.basis(cell), material.lambda, material.mu, 1.0);
    add({range_of(cell)}, cell, std::move(matrices.stiffness));  // eq. (29)
  }
  for (const DgFace& face : system.faces()) {
    if (face.plus < 0 && face.condition < 0) continue;  // a free boundary: no face term
    if (!system.owns_face(face)) continue;
    const MonomialBasis* plus = face.plus >= 0 ? &system.basis(face.plus) : nullptr;
    const DgMaterial minus_material = system.material(face.minus);
    const DgMaterial plus_material = face.plus >= 0 ? system.material(face.plus) : minus_material;
    FaceMatrixParts matrices = exact_face_matrix_parts(
        face.polygon, face.normal, system.basis(face.minus), plus, {minus_material.lambda, minus_material.mu},
        {plus_material.lambda, plus_material.mu}, system.face_penalty(face), settings.flux, face.components);
    std::vector<Range> ranges{range_of(face.minus)};
    if (face.plus >= 0) ranges.push_back(range_of(face.plus));
    const std::vector<int> dofs = dofs_of(ranges);
    for (size_t i = 0; i < dofs.size(); ++i)
      for (size_t j = 0; j < dofs.size(); ++j)
        if (matrices.penalty(i, j) != 0) penalty.emplace_back(dofs[i], dofs[j], matrices.penalty(i, j));
    if (settings.flux != Flux::interior_penalty) continue;
    if (face.plus < 0) {
      DirichletFace data{face.minus,
                         face.condition,
                         3 * system.offset(face.minus),
                         face.normal,
                         face.components,
                         minus_material.lambda,
                         minus_material.mu,
                         {},
                         {},
                         {}};
      const PolyhedronRule rule = polygon_rule(face.polygon, 2 * settings.degree + 2);  // as dirichlet_load's
      const MonomialBasis& basis = system.basis(face.minus);
      data.points = rule.points;
      data.weights = rule.weights;
      data.gradients.resize(rule.weights.size() * basis.size(), 3);
      Eigen::VectorXd phi;
      Eigen::MatrixXd gradients;
      for (Eigen::Index q = 0; q < rule.weights.size(); ++q) {
        basis.evaluate(rule.points.row(q).transpose(), phi, gradients);
        data.gradients.middleRows(q * basis.size(), basis.size()) = gradients;
      }
      parts.dirichlet_faces.push_back(std::move(data));
      add(ranges, face.minus, std::move(matrices.consistency[0]));
      Block& block = parts.blocks.back();
      block.dirichlet = true;
      block.symmetric = block.matrix + block.matrix.transpose();
      continue;
    }
    // §6.1: K_f1^± + K_f2^± warped with R_f^±, the rotation of the element whose strain they hold.
    for (int side : {0, 1})
      add(ranges, side == 0 ? face.minus : face.plus,
          matrices.consistency[side] + matrices.consistency[side].transpose());
  }
  const int size = system.dof_count();
  parts.penalty.resize(size, size);
  parts.penalty.setFromTriplets(penalty.begin(), penalty.end());
  Eigen::SparseMatrix<double> blocks_pattern(size, size);
  blocks_pattern.setFromTriplets(pattern.begin(), pattern.end());
  parts.stiffness = system.stiffness() + blocks_pattern + 0.0 * parts.penalty;
  parts.stiffness.makeCompressed();
  return parts;
}

std::vector<Eigen::Matrix3d> WarpedDgDiscretization::rotations(const Eigen::VectorXd& u) const {
  std::vector<Eigen::Matrix3d> result(affine_fit_.size());
#pragma omp parallel for schedule(static)
  for (int cell = 0; cell < static_cast<int>(affine_fit_.size()); ++cell) {
    const int first = cell_offsets_[cell], count = cell_offsets_[cell + 1] - first;
    // u's coefficients of this cell as 3 × #functions (column a = u_a).
    const Eigen::Map<const Eigen::MatrixXd> coefficients(u.data() + 3 * first, 3, count);
    const Eigen::Matrix3d deformation_gradient =
        Eigen::Matrix3d::Identity() + coefficients * affine_fit_[cell].transpose();
    result[cell] = polar_rotation(deformation_gradient);
  }
  return result;
}

int WarpedDgDiscretization::threads() const {
  return std::min(omp_get_max_threads(), static_cast<int>(scratch_.size()));
}

double WarpedDgDiscretization::block_force(const Block& block, const Eigen::Matrix3d& rotation,
                                           const Eigen::VectorXd& u, Scratch& scratch) const {
  const auto n = block.matrix.rows();
  auto rest = scratch.rest.head(n), z = scratch.z.head(n), jump = scratch.jump.head(n), force = scratch.force.head(n);
  Eigen::Index position = 0;
  for (const DofRange& range : block.ranges) {
    rest.segment(position, range.count) = rest_state_.segment(range.first, range.count);
    jump.segment(position, range.count) = u.segment(range.first, range.count);
    position += range.count;
  }
  for (Eigen::Index a = 0; a < n; a += 3) {
    const Eigen::Vector3d rotated_rest = rotation.transpose() * rest.segment<3>(a);
    jump.segment<3>(a) = rotation.transpose() * jump.segment<3>(a);  // R_Sᵀ u_S
    z.segment<3>(a) = jump.segment<3>(a) + rotated_rest - rest.segment<3>(a);
  }
  force.noalias() = block.matrix * z;
  if (!block.dirichlet) return 0.5 * z.dot(force);
  const double energy = jump.dot(force);
  force.noalias() += block.matrix.transpose() * jump;
  return energy;
}

void WarpedDgDiscretization::set_time(double time) const {
  for (size_t f = 0; f < dirichlet_faces_.size(); ++f) {
    const DirichletFace& face = dirichlet_faces_[f];
    const Eigen::Index n = face.gradients.rows() / face.weights.size();
    Eigen::MatrixXd& moments = data_moments_[f];
    moments.setZero(3, 3 * n);
    for (Eigen::Index q = 0; q < face.weights.size(); ++q) {
      const Eigen::Vector3d g = face.weights[q] * trajectory_(face.condition, face.points.row(q).transpose(), time);
      for (Eigen::Index a = 0; a < n; ++a) moments.middleCols<3>(3 * a) += g * face.gradients.row(q * n + a);
    }
  }
}

double WarpedDgDiscretization::add_data_forces(const std::vector<Eigen::Matrix3d>& rotation, const Eigen::VectorXd& u,
                                               Eigen::VectorXd* gradient) const {
  double energy = 0;
  for (size_t f = 0; f < dirichlet_faces_.size(); ++f) {
    const DirichletFace& face = dirichlet_faces_[f];
    const Eigen::Matrix3d& R = rotation[face.element];
    const Eigen::Vector3d& n = face.normal;
    for (Eigen::Index a = 0; a < data_moments_[f].cols() / 3; ++a) {
      // H = ∫ (P R_Kᵀ g) ⊗ ∇φ_a; −∫ h·σ(φ_a e_i) n = −(μ (H n + tr H n) + λ Hᵀ n)_i
      // (DgLinearSystem::dirichlet_load's integrand for h = P R_Kᵀ g).
      Eigen::Matrix3d H = R.transpose() * data_moments_[f].middleCols<3>(3 * a);
      for (int i = 0; i < 3; ++i)
        if (!face.components[i]) H.row(i).setZero();
      const Eigen::Vector3d load = -R * (face.mu * (H * n + H.trace() * n) + face.lambda * H.transpose() * n);
      const int dof = face.first_dof + 3 * static_cast<int>(a);
      if (gradient) gradient->segment<3>(dof) -= load;
      energy -= u.segment<3>(dof).dot(load);
    }
  }
  return energy;
}

double WarpedDgDiscretization::energy(const Eigen::VectorXd& u) const {
  const std::vector<Eigen::Matrix3d> rotation = rotations(u);
  parallel::for_each_index(blocks_.size(), threads(), [&](size_t index) {
    const Block& block = blocks_[index];
    block_energies_[index] = block_force(block, rotation[block.element], u, scratch_[omp_get_thread_num()]);
  });
  double energy = 0.5 * u.dot(penalty_ * u) + add_data_forces(rotation, u, nullptr);
  for (double block_energy : block_energies_) energy += block_energy;
  return divided_ ? ranks::sum(energy) : energy;
}

void WarpedDgDiscretization::gradient(const Eigen::VectorXd& u, Eigen::VectorXd& gradient) const {
  const std::vector<Eigen::Matrix3d> rotation = rotations(u);
  gradient = penalty_ * u;
  parallel::for_each_index_in_two_passes(
      blocks_.size(),
      [&](size_t index) {
        const Block& block = blocks_[index];
        const Eigen::Matrix3d& R = rotation[block.element];
        Scratch& scratch = scratch_[omp_get_thread_num()];
        block_force(block, R, u, scratch);  // K_S z_S
        for (Eigen::Index a = 0; a < block.matrix.rows(); a += 3)
          block_forces_.segment<3>(force_offsets_[index] + a) = R * scratch.force.segment<3>(a);  // eq. (29)
      },
      element_blocks_.size(),
      [&](size_t element) {
        for (const BlockSide& side : element_blocks_[element]) {
          const DofRange& range = blocks_[side.block].ranges[side.range];
          gradient.segment(range.first, range.count) +=
              block_forces_.segment(force_offsets_[side.block] + side.position, range.count);
        }
      },
      threads());
  add_data_forces(rotation, u, &gradient);
  if (divided_) ranks::sum(std::span<double>(gradient.data(), static_cast<size_t>(gradient.size())));
}

void WarpedDgDiscretization::hessian(const Eigen::VectorXd& u, Eigen::SparseMatrix<double>& hessian, bool) const {
  const std::vector<Eigen::Matrix3d> rotation = rotations(u);
  if (hessian.nonZeros() != penalty_.nonZeros()) hessian = penalty_;
  Eigen::Map<Eigen::VectorXd> values(hessian.valuePtr(), hessian.nonZeros());
  values = Eigen::Map<const Eigen::VectorXd>(penalty_.valuePtr(), penalty_.nonZeros());
  // Each element fills its own columns: R_S K_S R_Sᵀ of every block on its side, 3 × 3
  // block by 3 × 3 block (§6.3).
  parallel::for_each_index(element_blocks_.size(), threads(), [&](size_t element) {
    for (const BlockSide& side : element_blocks_[element]) {
      const Block& block = blocks_[side.block];
      const Eigen::MatrixXd& matrix = block.dirichlet ? block.symmetric : block.matrix;
      const Eigen::Matrix3d& R = rotation[block.element];
      const auto ranges = static_cast<Eigen::Index>(block.ranges.size());
      const int columns_end = side.position + block.ranges[side.range].count;
      for (Eigen::Index column = side.position; column < columns_end; column += 3) {
        Eigen::Index row = 0;
        for (Eigen::Index r = 0; r < ranges; ++r)
          for (int k = 0; k < block.ranges[r].count; k += 3, row += 3) {
            const Eigen::Matrix3d rotated = R * matrix.block<3, 3>(row, column) * R.transpose();
            for (int j = 0; j < 3; ++j)
              values.segment<3>(block.value_index[(column + j) * ranges + r] + k) += rotated.col(j);
          }
      }
    }
  });
  // Each rank's blocks on the whole pattern, summed into every rank's copy, unless the
  // solver sums the shares (matrix_share_owners).
  if (divided_ && matrix_share_owners().empty()) ranks::sum(std::span<double>(values.data(), values.size()));
}

}  // namespace altfem::dg
