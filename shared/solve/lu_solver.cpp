#include "shared/solve/lu_solver.hpp"

#include "shared/common/error.hpp"

#include <Eigen/UmfPackSupport>

#include <string>

namespace altfem {
namespace {

class LuSolver final : public LinearSolver {
public:
  std::string_view name() const override { return "lu"; }

protected:
  void analyze_pattern(const Eigen::SparseMatrix<double>& matrix) override {
    keep(matrix);
    lu_.analyzePattern(matrix_);
    if (lu_.info() != Eigen::Success) throw NumericalError("UMFPACK symbolic analysis failed");
  }

  void factorize_values(const Eigen::SparseMatrix<double>& matrix) override {
    keep(matrix);
    lu_.factorize(matrix_);
    if (lu_.info() != Eigen::Success)
      throw NumericalError("matrix is singular (UMFPACK status " + std::to_string(lu_.umfpackFactorizeReturncode()) +
                           ")");
  }

  long solve_system(const Eigen::VectorXd& rhs, Eigen::VectorXd& solution) override {
    solution = lu_.solve(rhs);
    if (lu_.info() != Eigen::Success) throw NumericalError("UMFPACK solve failed");
    return 0;
  }

private:
  // UmfPackLU keeps a reference to the matrix and its solve passes the matrix
  // to UMFPACK again (iterative refinement), so the solver owns a copy.
  void keep(const Eigen::SparseMatrix<double>& matrix) {
    matrix_ = matrix;
    matrix_.makeCompressed();
  }

  Eigen::SparseMatrix<double> matrix_;
  Eigen::UmfPackLU<Eigen::SparseMatrix<double>> lu_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_lu_solver() { return std::make_unique<LuSolver>(); }

}  // namespace altfem
