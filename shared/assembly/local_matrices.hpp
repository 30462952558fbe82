#pragma once
// The element- and face-local matrix types of the assemblers, templated on the number
// of basis functions N: fixed-size and stack-allocated for the common sizes,
// Eigen::Dynamic (scratch allocated once per thread) for the rest.
#include <Eigen/Core>
#include <span>

namespace altfem::kernel {

constexpr int dofs_of(int n) { return n == Eigen::Dynamic ? Eigen::Dynamic : 3 * n; }

template <int N>
using NodeMatrix = Eigen::Matrix<double, N, 3>;  // #basis × 3 (displacements / forces per basis function)
template <int N>
using LocalMatrix = Eigen::Matrix<double, dofs_of(N), dofs_of(N)>;  // 3#basis × 3#basis, local DOF 3a+i

/// u_a for a list of global basis functions (#basis × 3).
template <int N>
void gather(std::span<const int> basis, const Eigen::VectorXd& u, NodeMatrix<N>& local) {
  for (size_t a = 0; a < basis.size(); ++a)
    local.row(static_cast<Eigen::Index>(a)) = u.segment<3>(3 * static_cast<Eigen::Index>(basis[a])).transpose();
}

/// Adds a local matrix to a compressed matrix's values at the block offsets of
/// BlockSparsity (#basis × #basis offsets, column-major by b).
template <int N>
void scatter(std::span<const int> basis, const int* offsets, const LocalMatrix<N>& local, const int* outer,
             double* values) {
  const int n = static_cast<int>(basis.size());
  for (int b = 0; b < n; ++b)
    for (int k = 0; k < 3; ++k) {
      double* column = values + outer[3 * basis[b] + k];
      for (int a = 0; a < n; ++a) {
        double* block = column + offsets[b * n + a];
        for (int i = 0; i < 3; ++i) block[i] += local(3 * a + i, 3 * b + k);
      }
    }
}

}  // namespace altfem::kernel
