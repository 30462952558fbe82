#pragma once
// The per-element kernels of ElasticAssembler (internal header). Templated on the
// number of basis functions so the common elements (Tet4/10/20, Hex8/20/27) run on
// fixed-size, stack-allocated Eigen matrices; N = Eigen::Dynamic serves the rest
// (DG monomials, harmonic bases) with scratch allocated once per thread.
#include <Eigen/Core>
#include <cmath>

#include "shared/assembly/local_matrices.hpp"
#include "shared/assembly/tabulated_elements.hpp"
#include "shared/material/material.hpp"

namespace altfem::kernel {

template <int N>
using TangentRows = Eigen::Matrix<double, dofs_of(N), 9>;  // 3#basis × 9

/// u_a for the element's basis functions (#basis × 3).
template <int N>
void gather(const ElementView& element, const Eigen::VectorXd& u, NodeMatrix<N>& local) {
  gather<N>(element.basis, u, local);
}

/// Point q's gradients (#basis × 3) with a compile-time row count where N is fixed,
/// so the small products below are unrolled instead of going to Eigen's general
/// matrix-product code.
template <int N>
auto gradients_at(const ElementView& element, int q) {
  if constexpr (N == Eigen::Dynamic) return element.gradients_at(q);
  else return Eigen::Map<const Eigen::Matrix<double, N, 3, Eigen::RowMajor>>(element.gradients + q * N * 3);
}

/// G_ij = Σ_a u_ai ∂_j N_a, plus shifts[q] (9 values, column-major) when the element's
/// points carry a constant shift (`shifts` non-null: DG's lifted Dirichlet data). The
/// deformation gradient is F = I + G; the materials take G (Material::energy_at) so that
/// small strains keep their digits.
template <int N, typename Gradients>
Eigen::Matrix3d displacement_gradient(const NodeMatrix<N>& u, const Gradients& g, const double* shifts, int q) {
  Eigen::Matrix3d G = u.transpose() * g;
  if (shifts) G += Eigen::Map<const Eigen::Matrix3d>(shifts + 9 * q);
  return G;
}

/// `shifts`: the element's first point's shift of F (9 per point) or nullptr for none.
template <int N>
double energy(const ElementView& element, const Material& material, const NodeMatrix<N>& u, const double* shifts) {
  double total = 0;
  for (int q = 0; q < element.point_count(); ++q)
    total += element.weights[q] * material.energy_at(displacement_gradient<N>(u, gradients_at<N>(element, q), shifts, q));
  return total;
}

/// Element forces f_ai = Σ_q w_q Σ_j P_ij ∂_j N_a into `forces` (#basis × 3).
template <int N>
void forces(const ElementView& element, const Material& material, const NodeMatrix<N>& u, NodeMatrix<N>& forces,
            const double* shifts) {
  forces.setZero();
  for (int q = 0; q < element.point_count(); ++q) {
    const auto g = gradients_at<N>(element, q);
    const Eigen::Matrix3d P = material.pk1_at(displacement_gradient<N>(u, g, shifts, q));
    forces.noalias() += element.weights[q] * g * P.transpose();
  }
}

/// Element stiffness into `stiffness` (3#basis × 3#basis, local DOF 3a+i).
/// Per point, with C = w ∂P/∂F (9 × 9, index i+3j): first T(3b+k, i+3j) =
/// Σ_l ∂_l N_b C(k+3l, i+3j) (81·#basis flops), then
/// K(3b+k, 3a+i) = Σ_j ∂_j N_a T(3b+k, i+3j) (27·#basis² flops): the sparsity of
/// ∂F/∂u is used instead of a dense Bᵀ C B (which costs three times more).
template <int N>
void stiffness(const ElementView& element, const Material& material, const NodeMatrix<N>& u, LocalMatrix<N>& stiffness,
               TangentRows<N>& t, const double* shifts = nullptr) {
  const int n = element.basis_count();
  stiffness.setZero();
  Eigen::Matrix3d P;
  Matrix9d C;
  for (int q = 0; q < element.point_count(); ++q) {
    const auto g = gradients_at<N>(element, q);
    material.pk1_and_tangent_at(displacement_gradient<N>(u, g, shifts, q), P, C);
    C *= element.weights[q];
    for (int b = 0; b < n; ++b)
      for (int k = 0; k < 3; ++k)
        t.row(3 * b + k) = g(b, 0) * C.row(k) + g(b, 1) * C.row(k + 3) + g(b, 2) * C.row(k + 6);
    for (int a = 0; a < n; ++a)
      stiffness.template middleCols<3>(3 * a).noalias() += g(a, 0) * t.template middleCols<3>(0) +
                                                           g(a, 1) * t.template middleCols<3>(3) +
                                                           g(a, 2) * t.template middleCols<3>(6);
  }
}

}  // namespace altfem::kernel
