#include "shared/assembly/elastic_assembler.hpp"

#include <omp.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "shared/assembly/elastic_kernel.hpp"
#include "shared/assembly/element_coloring.hpp"
#include "shared/assembly/parallel_loops.hpp"
#include "shared/common/error.hpp"
#include "shared/material/project_spd.hpp"

namespace altfem {

// Per-thread storage for elements whose size has no fixed-size kernel.
struct ElasticAssembler::Scratch {
  kernel::NodeMatrix<Eigen::Dynamic> u, forces;
  kernel::LocalMatrix<Eigen::Dynamic> stiffness;
  kernel::TangentRows<Eigen::Dynamic> tangent_rows;
};

namespace {

// Calls body.template operator()<N>() with the fixed size for common elements, else Dynamic.
template <typename Body>
void dispatch(int basis_count, Body&& body) {
  switch (basis_count) {
    case 4: body.template operator()<4>(); break;
    case 8: body.template operator()<8>(); break;
    case 10: body.template operator()<10>(); break;
    case 20: body.template operator()<20>(); break;
    case 27: body.template operator()<27>(); break;
    default: body.template operator()<Eigen::Dynamic>(); break;
  }
}

using parallel::FirstFailure;
using parallel::for_each_index;
using parallel::for_each_index_in_two_passes;

// Says why an element's stress or tangent is not finite: a non-finite displacement
// (a diverged run), or else a deformation the material rejects (det F <= 0), which only
// materials with a volume term can do.
[[noreturn]] void throw_non_finite(const ElementView& element, int index, const Eigen::VectorXd& displacement,
                                   const Material& material, const char* what) {
  bool finite = true;
  for (int basis : element.basis) finite = finite && displacement.segment<3>(3 * basis).allFinite();
  const std::string reason = !finite ? "its displacement is not finite (the run diverged)"
                             : material.is_linear()
                                 ? "the displacement is too large for floating point"
                                 : "inverted or degenerate element: det F <= 0, which this material rejects";
  throw NumericalError("element " + std::to_string(index) + ": non-finite " + what + " (" + reason + ")");
}

}  // namespace

ElasticAssembler::ElasticAssembler(const TabulatedElements& elements, std::vector<const Material*> materials,
                                   const BasisGroups& extra_couplings, std::span<const char> share)
    : elements_(elements),
      materials_(std::move(materials)),
      sparsity_(elements, extra_couplings, share),
      colors_(color_elements(elements)),
      incidence_(elements),
      element_forces_(static_cast<std::size_t>(3 * incidence_.slot_count())),
      element_energies_(static_cast<std::size_t>(elements.size())) {
  check_materials();
  if (!share.empty()) {
    assemble_only(std::vector<char>(share.begin(), share.begin() + elements.size()));
    share_pattern_ = true;
  }
  threads_ = omp_get_max_threads();
  scratch_ = std::make_unique<Scratch[]>(threads_);
  const int n = elements.max_element_basis();
  for (int t = 0; t < threads_; ++t) {
    scratch_[t].u.resize(n, 3);
    scratch_[t].forces.resize(n, 3);
    scratch_[t].stiffness.resize(3 * n, 3 * n);
    scratch_[t].tangent_rows.resize(3 * n, 9);
  }
}

ElasticAssembler::~ElasticAssembler() = default;

void ElasticAssembler::check_materials() const {
  for (int e = 0; e < elements_.size(); ++e) {
    const int id = elements_[e].material;
    if (id < 0 || id >= static_cast<int>(materials_.size()) || materials_[id] == nullptr)
      throw std::invalid_argument("ElasticAssembler: element " + std::to_string(e) + " has material id " +
                                  std::to_string(id) + " but only " + std::to_string(materials_.size()) +
                                  " materials were given");
  }
}

int ElasticAssembler::active_threads() const { return std::min(threads_, omp_get_max_threads()); }

template <typename Body>
void ElasticAssembler::for_each_colored_element(Body&& body) const {
  parallel::for_each_colored(colors_, static_cast<size_t>(elements_.size()), active_threads(), body);
}

void ElasticAssembler::set_deformation_shifts(std::span<const double> shifts) {
  if (!shifts.empty() && static_cast<long long>(shifts.size()) != 9 * elements_.whole_point_count())
    throw std::invalid_argument("ElasticAssembler: deformation shifts must hold 9 values per quadrature point");
  shifts_ = shifts.empty() ? nullptr : shifts.data();
}

void ElasticAssembler::assemble_only(const std::vector<char>& owned) {
  if (static_cast<int>(owned.size()) != elements_.size())
    throw std::invalid_argument("ElasticAssembler::assemble_only: one entry per element expected");
  owned_ = owned;
  owned_colors_.clear();
  for (const std::vector<int>& color : colors_) {
    std::vector<int> mine;
    for (int e : color)
      if (owned_[e]) mine.push_back(e);
    if (!mine.empty()) owned_colors_.push_back(std::move(mine));
  }
}

const double* ElasticAssembler::element_shifts(int element) const {
  return shifts_ ? shifts_ + 9 * elements_.whole_point_offset(element) : nullptr;
}

bool ElasticAssembler::is_linear() const {
  for (const Material* material : materials_)
    if (!material->is_linear()) return false;
  return true;
}

double ElasticAssembler::energy(const Eigen::VectorXd& displacement) const {
  // Sum per element first, then in element order: the total does not depend on the
  // thread count.
  std::vector<double>& per_element = element_energies_;
  for_each_index(elements_.size(), active_threads(), [&](size_t index) {
    const int e = static_cast<int>(index);
    if (!assembles(e)) {
      per_element[e] = 0;
      return;
    }
    const ElementView element = elements_[e];
    Scratch& scratch = scratch_[omp_get_thread_num()];
    dispatch(element.basis_count(), [&]<int N>() {
      if constexpr (N == Eigen::Dynamic) {
        scratch.u.conservativeResize(element.basis_count(), 3);
        kernel::gather<N>(element, displacement, scratch.u);
        per_element[e] = kernel::energy<N>(element, *materials_[element.material], scratch.u, element_shifts(e));
      } else {
        kernel::NodeMatrix<N> u;
        kernel::gather<N>(element, displacement, u);
        per_element[e] = kernel::energy<N>(element, *materials_[element.material], u, element_shifts(e));
      }
    });
  });
  double total = 0;
  for (double value : per_element) {
    if (std::isnan(value)) return std::numeric_limits<double>::infinity();
    total += value;
  }
  return total;
}

void ElasticAssembler::gradient(const Eigen::VectorXd& displacement, Eigen::VectorXd& gradient) const {
  // Two passes instead of colours: the forces of a cheap element cost about as much
  // as a barrier, and tets need ~30 colours of ~100 elements, so colour-by-colour
  // assembly stopped at 1.5-1.7x on 2 threads (issue #9). Here all elements write
  // their forces to their own slots, then each basis function sums its slots in
  // element order (same bits for any thread count), visiting the basis functions in
  // BasisIncidence::gather_order so that each thread mostly reads its own slots.
  FirstFailure failure;
  gradient.resize(dof_count());
  // Basis functions that only extra couplings use get no element force.
  gradient.tail(dof_count() - 3 * elements_.basis_count()).setZero();
  const auto element_forces = [&](size_t index) {
    const int e = static_cast<int>(index);
    const ElementView element = elements_[e];
    double* slots = element_forces_.data() + 3 * elements_.basis_offset(e);
    if (!assembles(e)) {
      std::fill_n(slots, 3 * element.basis_count(), 0.0);
      return;
    }
    dispatch(element.basis_count(), [&]<int N>() {
      const int n = element.basis_count();
      auto run = [&](kernel::NodeMatrix<N>& u, kernel::NodeMatrix<N>& forces) {
        kernel::gather<N>(element, displacement, u);
        kernel::forces<N>(element, *materials_[element.material], u, forces, element_shifts(e));
        if (!forces.allFinite()) failure.record(e);
        Eigen::Map<Eigen::Matrix<double, N, 3, Eigen::RowMajor>>(slots, n, 3) = forces;
      };
      if constexpr (N == Eigen::Dynamic) {
        Scratch& scratch = scratch_[omp_get_thread_num()];
        scratch.u.conservativeResize(n, 3);
        scratch.forces.conservativeResize(n, 3);
        run(scratch.u, scratch.forces);
      } else {
        kernel::NodeMatrix<N> u, forces;
        run(u, forces);
      }
    });
  };
  const auto sum_slots = [&](size_t position) {
    const int basis = incidence_.gather_order()[position];
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (long long slot : incidence_.slots(basis))
      sum += Eigen::Map<const Eigen::Vector3d>(element_forces_.data() + 3 * slot);
    gradient.segment<3>(3 * static_cast<Eigen::Index>(basis)) = sum;
  };
  for_each_index_in_two_passes(elements_.size(), element_forces, static_cast<size_t>(elements_.basis_count()),
                               sum_slots, active_threads());
  if (failure.item() >= 0)
    throw_non_finite(elements_[failure.item()], failure.item(), displacement,
                     *materials_[elements_[failure.item()].material], "stress");
}

void ElasticAssembler::hessian(const Eigen::VectorXd& displacement, SparseMatrix& hessian, bool project_spd) const {
  double* values = hessian.valuePtr();
  const int* outer = hessian.outerIndexPtr();
  std::fill_n(values, hessian.nonZeros(), 0.0);
  FirstFailure failure, projection_failure;
  // Every element, or this rank's (assemble_only).
  const auto& colors = owned_.empty() ? colors_ : owned_colors_;
  parallel::for_each_colored(colors, static_cast<size_t>(elements_.size()), active_threads(), [&](int e) {
    const ElementView element = elements_[e];
    Scratch& scratch = scratch_[omp_get_thread_num()];
    dispatch(element.basis_count(), [&]<int N>() {
      const int n = element.basis_count();
      auto run = [&](kernel::NodeMatrix<N>& u, kernel::LocalMatrix<N>& stiffness, kernel::TangentRows<N>& rows) {
        kernel::gather<N>(element, displacement, u);
        kernel::stiffness<N>(element, *materials_[element.material], u, stiffness, rows, element_shifts(e));
        if (!stiffness.allFinite()) {
          failure.record(e);
          return;
        }
        if (project_spd) {
          // An exception must not leave the OpenMP region (it would terminate the program).
          try {
            project_to_spd(stiffness);
          } catch (const NumericalError&) {
            projection_failure.record(e);
            return;
          }
        }
        kernel::scatter<N>(element.basis, sparsity_.pair_offsets(e), stiffness, outer, values);
      };
      if constexpr (N == Eigen::Dynamic) {
        scratch.u.conservativeResize(n, 3);
        scratch.stiffness.conservativeResize(3 * n, 3 * n);
        scratch.tangent_rows.conservativeResize(3 * n, 9);
        run(scratch.u, scratch.stiffness, scratch.tangent_rows);
      } else {
        kernel::NodeMatrix<N> u;
        kernel::LocalMatrix<N> stiffness;
        kernel::TangentRows<N> rows;
        run(u, stiffness, rows);
      }
    });
  });
  if (failure.item() >= 0)
    throw_non_finite(elements_[failure.item()], failure.item(), displacement,
                     *materials_[elements_[failure.item()].material], "tangent stiffness");
  if (projection_failure.item() >= 0)
    throw NumericalError("element " + std::to_string(projection_failure.item()) +
                         ": the eigen-solver of the SPD projection did not converge");
}

void ElasticAssembler::mass_matrix(SparseMatrix& mass) const { mass_matrix(element_masses(elements_), mass); }

void ElasticAssembler::mass_matrix(const ElementMasses& masses, SparseMatrix& mass) const {
  mass = pattern();
  add_mass(masses, 1.0, mass);
}

void ElasticAssembler::add_mass(const ElementMasses& masses, double factor, SparseMatrix& matrix) const {
  check_masses(masses);
  double* values = matrix.valuePtr();
  const int* outer = matrix.outerIndexPtr();
  // A share's pattern holds only its own elements' blocks.
  const auto& colors = share_pattern_ ? owned_colors_ : colors_;
  parallel::for_each_colored(colors, static_cast<size_t>(elements_.size()), active_threads(), [&](int e) {
    const Eigen::MatrixXd& element_mass = masses.matrices[e];
    if (element_mass.size() == 0) return;  // another rank's
    const ElementView element = elements_[e];
    const double scale = factor * materials_[element.material]->density();
    const int n = element.basis_count();
    const int* offsets = sparsity_.pair_offsets(e);
    for (int b = 0; b < n; ++b)
      for (int a = 0; a < n; ++a) {
        const double m = scale * element_mass(a, b);
        for (int k = 0; k < 3; ++k) values[outer[3 * element.basis[b] + k] + offsets[b * n + a] + k] += m;
      }
  });
}

Eigen::VectorXd ElasticAssembler::mass_times(const ElementMasses& masses, const Eigen::VectorXd& vector) const {
  check_masses(masses);
  Eigen::VectorXd product = Eigen::VectorXd::Zero(pattern().rows());
  for_each_colored_element([&](int e) {
    if (masses.matrices[e].size() == 0) return;  // another rank's
    const ElementView element = elements_[e];
    const int n = element.basis_count();
    // The element's nodal values, n × 3 (the mass acts alike on each component); per
    // thread, reallocated only when n changes.
    thread_local Eigen::MatrixX3d nodal, result;
    nodal.resize(n, 3);
    for (int a = 0; a < n; ++a) nodal.row(a) = vector.segment<3>(3 * element.basis[a]).transpose();
    result.noalias() = materials_[element.material]->density() * masses.matrices[e] * nodal;
    for (int a = 0; a < n; ++a) product.segment<3>(3 * element.basis[a]) += result.row(a).transpose();
  });
  return product;
}

Eigen::VectorXd ElasticAssembler::body_force(const Eigen::Vector3d& acceleration) const {
  return body_force(element_masses(elements_), acceleration);
}

Eigen::VectorXd ElasticAssembler::body_force(const ElementMasses& masses, const Eigen::Vector3d& acceleration) const {
  check_masses(masses);
  // Serial: it runs once per run, and elements sum into shared entries.
  Eigen::VectorXd force = Eigen::VectorXd::Zero(pattern().rows());
  for (int e = 0; e < elements_.size(); ++e) {
    if (masses.integrals[e].size() == 0) continue;  // another rank's
    const ElementView element = elements_[e];
    const double density = materials_[element.material]->density();
    for (int a = 0; a < element.basis_count(); ++a)
      force.segment<3>(3 * element.basis[a]) += density * masses.integrals[e][a] * acceleration;
  }
  return force;
}

Eigen::VectorXd ElasticAssembler::lumped_mass() const { return lumped_mass(element_masses(elements_)); }

Eigen::VectorXd ElasticAssembler::lumped_mass(const ElementMasses& masses) const {
  check_masses(masses);
  Eigen::VectorXd lumped = Eigen::VectorXd::Zero(pattern().rows());
  for (int e = 0; e < elements_.size(); ++e) {
    if (masses.matrices[e].size() == 0) continue;  // another rank's
    const ElementView element = elements_[e];
    const Eigen::VectorXd diagonal = masses.matrices[e].diagonal();
    const double scale = materials_[element.material]->density() * masses.volumes[e] / diagonal.sum();
    for (int a = 0; a < element.basis_count(); ++a)
      lumped.segment<3>(3 * element.basis[a]).array() += scale * diagonal[a];
  }
  return lumped;
}

Eigen::MatrixXd ElasticAssembler::mean_cauchy_stress(const Eigen::VectorXd& displacement) const {
  Eigen::MatrixXd stresses(elements_.size(), 9);
#pragma omp parallel for schedule(dynamic, 64)
  for (int e = 0; e < elements_.size(); ++e) {
    if (!elements_.holds(e)) {
      stresses.row(e).setZero();
      continue;
    }
    const ElementView element = elements_[e];
    const Material& material = *materials_[element.material];
    Eigen::MatrixX3d u(element.basis_count(), 3);
    for (int a = 0; a < element.basis_count(); ++a)
      u.row(a) = displacement.segment<3>(3 * element.basis[a]).transpose();
    Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
    double volume = 0;
    const double* shifts = element_shifts(e);
    for (int q = 0; q < element.point_count(); ++q) {
      Eigen::Matrix3d F = Eigen::Matrix3d::Identity() + u.transpose() * element.gradients_at(q);
      if (shifts) F += Eigen::Map<const Eigen::Matrix3d>(shifts + 9 * q);
      sum += element.weights[q] * material.pk1(F) * F.transpose() / F.determinant();
      volume += element.weights[q];
    }
    const Eigen::Matrix3d mean = sum / volume;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) stresses(e, 3 * i + j) = mean(i, j);
  }
  return stresses;
}

void ElasticAssembler::check_masses(const ElementMasses& masses) const {
  bool same = masses.size() == elements_.size();
  // An element another rank holds may have no mass here (element_masses of a share).
  for (int e = 0; same && e < elements_.size(); ++e)
    same = masses.matrices[e].rows() == elements_[e].basis_count() ||
           (masses.matrices[e].size() == 0 && !elements_.holds(e));
  if (!same)
    throw std::invalid_argument("ElasticAssembler: the element masses must be the elements', in the same order");
}

}  // namespace altfem
