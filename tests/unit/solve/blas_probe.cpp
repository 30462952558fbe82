// Prints the BLAS this process runs on ("implementation\nlibrary\n") after a
// tiny CHOLMOD factorisation, so that the BLAS CHOLMOD calls is surely loaded.
#include "shared/solve/blas_info.hpp"
#include "shared/solve/linear_solver.hpp"

#include <iostream>

int main() {
  Eigen::SparseMatrix<double> matrix(2, 2);
  matrix.insert(0, 0) = 2.0;
  matrix.insert(1, 1) = 3.0;
  auto solver = altfem::make_linear_solver({});
  solver->factorize(matrix);
  const altfem::BlasInfo blas = altfem::loaded_blas();
  std::cout << blas.implementation << '\n' << blas.library << '\n';
}
