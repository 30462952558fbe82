#pragma once
// Eigen's dense decompositions of an Eigen::MatrixXd, compiled once, in
// dense_decompositions.cpp, instead of in every file that uses one: a file that includes
// this header and constructs one from a MatrixXd calls that copy. Instantiated and
// optimised at -O3 in place, each took 5–7 s of a file's compile time (issue #38, the clean
// build; docs/performance.md, "Build and test time"). Constructed from any other
// expression type, a decomposition is still instantiated in place.
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#ifdef ALTFEM_DEFINE_DENSE_DECOMPOSITIONS
#define ALTFEM_DENSE_DECOMPOSITION_EXTERN
#else
#define ALTFEM_DENSE_DECOMPOSITION_EXTERN extern
#endif

namespace Eigen {

ALTFEM_DENSE_DECOMPOSITION_EXTERN template class SelfAdjointEigenSolver<MatrixXd>;
ALTFEM_DENSE_DECOMPOSITION_EXTERN template SelfAdjointEigenSolver<MatrixXd>::SelfAdjointEigenSolver(
    const EigenBase<MatrixXd>&, int);
ALTFEM_DENSE_DECOMPOSITION_EXTERN template SelfAdjointEigenSolver<MatrixXd>& SelfAdjointEigenSolver<MatrixXd>::compute(
    const EigenBase<MatrixXd>&, int);

ALTFEM_DENSE_DECOMPOSITION_EXTERN template class LLT<MatrixXd>;
ALTFEM_DENSE_DECOMPOSITION_EXTERN template LLT<MatrixXd>::LLT(const EigenBase<MatrixXd>&);
ALTFEM_DENSE_DECOMPOSITION_EXTERN template LLT<MatrixXd>& LLT<MatrixXd>::compute(const EigenBase<MatrixXd>&);

ALTFEM_DENSE_DECOMPOSITION_EXTERN template class HouseholderQR<MatrixXd>;
ALTFEM_DENSE_DECOMPOSITION_EXTERN template HouseholderQR<MatrixXd>::HouseholderQR(const EigenBase<MatrixXd>&);
ALTFEM_DENSE_DECOMPOSITION_EXTERN template HouseholderQR<MatrixXd>& HouseholderQR<MatrixXd>::compute(
    const EigenBase<MatrixXd>&);

ALTFEM_DENSE_DECOMPOSITION_EXTERN template class ColPivHouseholderQR<MatrixXd>;
ALTFEM_DENSE_DECOMPOSITION_EXTERN template ColPivHouseholderQR<MatrixXd>::ColPivHouseholderQR(
    const EigenBase<MatrixXd>&);
ALTFEM_DENSE_DECOMPOSITION_EXTERN template ColPivHouseholderQR<MatrixXd>& ColPivHouseholderQR<MatrixXd>::compute(
    const EigenBase<MatrixXd>&);

}  // namespace Eigen

#undef ALTFEM_DENSE_DECOMPOSITION_EXTERN
