#include "shared/assembly/warped_linear_discretization.hpp"

#include <omp.h>

#include <stdexcept>

#include "shared/assembly/elastic_kernel.hpp"
#include "shared/assembly/element_coloring.hpp"
#include "shared/assembly/parallel_loops.hpp"
#include "shared/material/best_fit_rotation.hpp"
#include "shared/solve/process_ranks.hpp"

namespace altfem {

namespace {

// K_e = ∫ Bᵀ C B of a linear material: the tangent at rest (3n × 3n).
Eigen::MatrixXd rest_stiffness(const ElementView& element, const Material& material) {
  const int n = element.basis_count();
  const kernel::NodeMatrix<Eigen::Dynamic> rest = kernel::NodeMatrix<Eigen::Dynamic>::Zero(n, 3);
  kernel::LocalMatrix<Eigen::Dynamic> stiffness(3 * n, 3 * n);
  kernel::TangentRows<Eigen::Dynamic> tangent_rows(3 * n, 9);
  kernel::stiffness<Eigen::Dynamic>(element, material, rest, stiffness, tangent_rows);
  return stiffness;
}

// The shape-matching masses of the element's nodes: the diagonal of its consistent mass
// per unit density, Σ_q w_q N_a(x_q)², always positive (the HRZ lumping's proportions),
// where the plain integrals ∫ N_a may vanish or turn negative for non-Lagrange bases.
Eigen::VectorXd node_masses(const ElementView& element) {
  Eigen::VectorXd masses = Eigen::VectorXd::Zero(element.basis_count());
  for (int q = 0; q < element.point_count(); ++q)
    masses += element.weights[q] * element.values.row(q).transpose().cwiseAbs2();
  return masses;
}

int threads() { return omp_get_max_threads(); }

}  // namespace

namespace warped_linear {

LinearPart::LinearPart(DiscretizationParts parts) : materials(parts.materials) {
  if (!parts.terms.empty())
    throw std::invalid_argument("WarpedLinearDiscretization: extra energy terms are not warped");
  for (const Material* material : materials)
    if (material == nullptr || !material->is_linear())
      throw std::invalid_argument("WarpedLinearDiscretization: every material must be linear");
  linear = std::make_unique<TabulatedDiscretization>(std::move(parts));
}

}  // namespace warped_linear

WarpedLinearDiscretization::WarpedLinearDiscretization(DiscretizationParts parts, Eigen::MatrixX3d rest_positions)
    : LinearPart(std::move(parts)), ForwardingDiscretization(*linear), rest_(std::move(rest_positions)) {
  const TabulatedElements& elements = linear->elements();
  if (rest_.rows() < elements.basis_count())
    throw std::invalid_argument("WarpedLinearDiscretization: a rest position is needed for every basis function");
  stiffness_.resize(static_cast<size_t>(elements.size()));
  node_masses_.resize(static_cast<size_t>(elements.size()));
  parallel::for_each_index(static_cast<size_t>(elements.size()), threads(), [&](size_t e) {
    if (!elements.holds(static_cast<int>(e))) return;  // another rank's (keep_only)
    const ElementView element = elements[static_cast<int>(e)];
    stiffness_[e] = rest_stiffness(element, *materials[element.material]);
    node_masses_[e] = node_masses(element);
  });
  colors_ = color_elements(elements);
  scratch_.resize(static_cast<size_t>(threads()));
  rotations_.assign(static_cast<size_t>(elements.size()), Eigen::Matrix3d::Identity());
  const long long entries = 3 * elements.basis_offset(elements.size());
  corotated_.resize(static_cast<size_t>(entries));
  stiffness_forces_.resize(static_cast<size_t>(entries));
}

WarpedLinearDiscretization::~WarpedLinearDiscretization() = default;

void WarpedLinearDiscretization::warp(const Eigen::VectorXd& u, bool own_elements_only) const {
  const TabulatedElements& elements = linear->elements();
  const ElasticAssembler& assembler = linear->assembler();
  parallel::for_each_index(static_cast<size_t>(elements.size()), threads(), [&](size_t index) {
    const int e = static_cast<int>(index);
    if (!elements.holds(e) || (own_elements_only && !assembler.assembles(e))) return;
    const ElementView element = elements[e];
    const int n = element.basis_count();
    NodeScratch& scratch = scratch_[omp_get_thread_num()];
    scratch.rest.resize(n, 3);
    scratch.deformed.resize(n, 3);
    for (int a = 0; a < n; ++a) {
      scratch.rest.row(a) = rest_.row(element.basis[a]);
      scratch.deformed.row(a) = scratch.rest.row(a) + u.segment<3>(3 * element.basis[a]).transpose();
    }
    // Martin et al. 2008 §6: R_e by shape matching of the element's nodes, here the
    // rotation of the affine fit A = A_pq A_qq⁻¹ (Müller et al. 2005 §4.1) rather than
    // of A_pq alone: every element of an affine deformation x = A X + b then gets the
    // same R = polar(A), so the warped patch test stays exact.
    const Eigen::Matrix3d rotation = best_fit_rotation(scratch.rest, scratch.deformed, node_masses_[e]);
    rotations_[e] = rotation;
    // z_a = R_eᵀ x_a − X_a, packed node-major (local DOF 3a+i) like K_e's rows.
    Eigen::Map<Eigen::VectorXd> z(corotated_.data() + 3 * elements.basis_offset(e), 3 * n);
    for (int a = 0; a < n; ++a)
      z.segment<3>(3 * a) =
          rotation.transpose() * scratch.deformed.row(a).transpose() - scratch.rest.row(a).transpose();
    Eigen::Map<Eigen::VectorXd>(stiffness_forces_.data() + 3 * elements.basis_offset(e), 3 * n).noalias() =
        stiffness_[e] * z;
  });
}

// Over several ranks each warps and assembles the elements its linear part assembles
// (TabulatedDiscretization's partition), and the sums make the whole on every rank.
double WarpedLinearDiscretization::energy(const Eigen::VectorXd& u) const {
  const TabulatedElements& elements = linear->elements();
  const ElasticAssembler& assembler = linear->assembler();
  double total = 0;
  ranks::collectively([&] {
    warp(u, true);
    // In element order: the total does not depend on the thread count.
    for (int e = 0; e < elements.size(); ++e)
      if (assembler.assembles(e))
        for (long long i = 3 * elements.basis_offset(e); i < 3 * elements.basis_offset(e + 1); ++i)
          total += 0.5 * corotated_[i] * stiffness_forces_[i];
  });
  return ranks::sum(total);
}

void WarpedLinearDiscretization::gradient(const Eigen::VectorXd& u, Eigen::VectorXd& gradient) const {
  ranks::collectively([&] { warp(u, true); });
  const TabulatedElements& elements = linear->elements();
  gradient.setZero(dof_count());
  for (int e = 0; e < elements.size(); ++e) {
    if (!linear->assembler().assembles(e)) continue;
    const ElementView element = elements[e];
    const double* forces = stiffness_forces_.data() + 3 * elements.basis_offset(e);
    // f_a = R_e (K_e z_e)_a
    for (int a = 0; a < element.basis_count(); ++a)
      gradient.segment<3>(3 * element.basis[a]) += rotations_[e] * Eigen::Vector3d::Map(forces + 3 * a);
  }
  ranks::sum(std::span<double>(gradient.data(), static_cast<size_t>(gradient.size())));
}

void WarpedLinearDiscretization::hessian(const Eigen::VectorXd& u, Eigen::SparseMatrix<double>& hessian,
                                         bool /*project_spd*/) const {
  ranks::collectively([&] { warp(u, true); });
  const TabulatedElements& elements = linear->elements();
  const ElasticAssembler& assembler = linear->assembler();
  const BlockSparsity& sparsity = assembler.sparsity();
  std::fill(hessian.valuePtr(), hessian.valuePtr() + hessian.nonZeros(), 0.0);
  const int* outer = hessian.outerIndexPtr();
  double* values = hessian.valuePtr();
  parallel::for_each_colored(colors_, static_cast<size_t>(elements.size()), threads(), [&](int e) {
    if (!assembler.assembles(e)) return;
    const ElementView element = elements[e];
    const int n = element.basis_count();
    const int* offsets = sparsity.pair_offsets(e);
    const Eigen::Matrix3d& rotation = rotations_[e];
    for (int b = 0; b < n; ++b)
      for (int a = 0; a < n; ++a) {
        // Block (a, b) of R_e K_e R_eᵀ.
        const Eigen::Matrix3d block = rotation * stiffness_[e].block<3, 3>(3 * a, 3 * b) * rotation.transpose();
        for (int k = 0; k < 3; ++k) {
          double* column = values + outer[3 * element.basis[b] + k] + offsets[b * n + a];
          for (int i = 0; i < 3; ++i) column[i] += block(i, k);
        }
      }
  });
  // Left this rank's share, on its linear part's pattern, when the solver sums the shares.
  if (linear->matrix_share_owners().empty())
    ranks::sum(std::span<double>(hessian.valuePtr(), static_cast<size_t>(hessian.nonZeros())));
}

Eigen::MatrixXd WarpedLinearDiscretization::element_cauchy_stress(const Eigen::VectorXd& u) const {
  warp(u, false);
  const TabulatedElements& elements = linear->elements();
  Eigen::MatrixXd stresses = Eigen::MatrixXd::Zero(elements.size(), 9);
  for (int e = 0; e < elements.size(); ++e) {
    if (!elements.holds(e)) continue;
    const ElementView element = elements[e];
    const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>> z(
        corotated_.data() + 3 * elements.basis_offset(e), element.basis_count(), 3);
    Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
    double volume = 0;
    for (int q = 0; q < element.point_count(); ++q) {
      const Eigen::Matrix3d F = Eigen::Matrix3d::Identity() + z.transpose() * element.gradients_at(q);
      sum += element.weights[q] * materials[element.material]->pk1(F);
      volume += element.weights[q];
    }
    const Eigen::Matrix3d mean = rotations_[e] * (sum / volume) * rotations_[e].transpose();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) stresses(e, 3 * i + j) = mean(i, j);
  }
  elements.sum_over_ranks(std::span<double>(stresses.data(), static_cast<size_t>(stresses.size())));
  return stresses;
}

std::vector<Eigen::Matrix3d> WarpedLinearDiscretization::rotations(const Eigen::VectorXd& u) const {
  warp(u, false);
  return rotations_;
}

}  // namespace altfem
