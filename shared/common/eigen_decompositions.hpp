#pragma once
// Eigen's decompositions that several files use — of an Eigen::MatrixXd, and SparseLU of a
// SparseMatrix<double> — compiled once, in eigen_decompositions.cpp, instead of in every
// file that uses one: a file that includes this header and constructs one from a MatrixXd
// calls that copy. Instantiated and optimised at -O3 in place, each took 5–7 s of a file's
// compile time (issue #38, the clean build; docs/performance.md, "Build and test time").
// Constructed from any other expression type, a decomposition is still instantiated in
// place.
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#ifdef ALTFEM_DEFINE_EIGEN_DECOMPOSITIONS
#define ALTFEM_EIGEN_DECOMPOSITION_EXTERN
#else
#define ALTFEM_EIGEN_DECOMPOSITION_EXTERN extern
#endif

namespace Eigen {

ALTFEM_EIGEN_DECOMPOSITION_EXTERN template class SelfAdjointEigenSolver<MatrixXd>;
ALTFEM_EIGEN_DECOMPOSITION_EXTERN template SelfAdjointEigenSolver<MatrixXd>::SelfAdjointEigenSolver(
    const EigenBase<MatrixXd>&, int);
ALTFEM_EIGEN_DECOMPOSITION_EXTERN template SelfAdjointEigenSolver<MatrixXd>& SelfAdjointEigenSolver<MatrixXd>::compute(
    const EigenBase<MatrixXd>&, int);

ALTFEM_EIGEN_DECOMPOSITION_EXTERN template class LLT<MatrixXd>;
ALTFEM_EIGEN_DECOMPOSITION_EXTERN template LLT<MatrixXd>::LLT(const EigenBase<MatrixXd>&);
ALTFEM_EIGEN_DECOMPOSITION_EXTERN template LLT<MatrixXd>& LLT<MatrixXd>::compute(const EigenBase<MatrixXd>&);

ALTFEM_EIGEN_DECOMPOSITION_EXTERN template class HouseholderQR<MatrixXd>;
ALTFEM_EIGEN_DECOMPOSITION_EXTERN template HouseholderQR<MatrixXd>::HouseholderQR(const EigenBase<MatrixXd>&);
ALTFEM_EIGEN_DECOMPOSITION_EXTERN template HouseholderQR<MatrixXd>& HouseholderQR<MatrixXd>::compute(
    const EigenBase<MatrixXd>&);

ALTFEM_EIGEN_DECOMPOSITION_EXTERN template class ColPivHouseholderQR<MatrixXd>;
ALTFEM_EIGEN_DECOMPOSITION_EXTERN template ColPivHouseholderQR<MatrixXd>::ColPivHouseholderQR(
    const EigenBase<MatrixXd>&);
ALTFEM_EIGEN_DECOMPOSITION_EXTERN template ColPivHouseholderQR<MatrixXd>& ColPivHouseholderQR<MatrixXd>::compute(
    const EigenBase<MatrixXd>&);

ALTFEM_EIGEN_DECOMPOSITION_EXTERN template class SparseLU<SparseMatrix<double>>;

}  // namespace Eigen

#undef ALTFEM_EIGEN_DECOMPOSITION_EXTERN
