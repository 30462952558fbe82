#pragma once
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "shared/solve/dirichlet_elimination.hpp"
#include "shared/solve/linear_solver.hpp"

namespace altfem {

/// A smooth function of the displacement that Newton minimises: the static potential
/// Ψ(u) − f·u, or backward Euler's incremental potential.
class Objective {
public:
  virtual ~Objective() = default;
  virtual double value(const Eigen::VectorXd& u) const = 0;
  virtual void gradient(const Eigen::VectorXd& u, Eigen::VectorXd& gradient) const = 0;
  /// Into a matrix with the pattern given to NewtonSolver.
  virtual void hessian(const Eigen::VectorXd& u, Eigen::SparseMatrix<double>& hessian, bool project_spd) const = 0;
  virtual bool hessian_is_constant() const = 0;
  /// False when gradient() is not the derivative of value() (a force model): the line
  /// search then takes value() as a merit function only, and also accepts any step that
  /// lowers the residual.
  virtual bool gradient_has_potential() const { return true; }
};

struct NewtonOptions {
  double tolerance = 1e-8;  ///< on the free part of the gradient (absolute)
  int max_iterations = 50;
  bool line_search = true;   ///< Armijo backtracking on the objective
  bool project_spd = false;  ///< project element Hessians to SPD from the start
  int max_backtracks = 40;
};

struct NewtonReport {
  int iterations = 0;   ///< linear solves
  double residual = 0;  ///< final free gradient norm
  /// When the residual stayed above the tolerance but reached the round-off floor of the
  /// assembled forces (NewtonSolver::round_off_floor): that floor; else 0.
  double round_off_floor = 0;
};

/// Damped Newton with Armijo backtracking (Nocedal & Wright, Alg. 3.1) and strong
/// Dirichlet conditions by elimination. The sparsity pattern is analysed once (by the
/// linear solver, per distinct pattern) and reused for every iteration and time step; with a constant Hessian (linear
/// material) the factorisation is reused too. A failed Cholesky factorisation (an
/// indefinite tangent) is retried once with SPD-projected element Hessians (Smith et
/// al. 2018 §4.4; Longva et al. 2020 §6 needed it for fine Tet4 meshes).
///
/// With a constant Hessian H (a linear material), Newton also stops when the residual
/// lies below the round-off floor of the gradient it evaluates, 16 ε ‖(|H| |u|)_free‖
/// (the componentwise bound of a backward-stable solve and of assembling the sums H u,
/// Higham 2002, Accuracy and Stability of Numerical Algorithms, §7.2 and Thm. 10.4): a
/// 1 mm plate's bending stiffness cancels its element forces down to ~0.1–0.7 ε ‖|H||u|‖
/// (thin_plate.json), 100 times the load tolerance, and no further iteration lowers it.
/// Ordinary scenes reach the tolerance first (the cantilever's floor lies 5 orders below
/// it). A nonlinear material's forces are not H u, and |H| bounds them badly: near a
/// collapsing corotated element the floor reached 7.2 against a tolerance of 1.5e-4
/// (soft_large_step.json, dt 0.05) and accepted steps far from equilibrium, so there
/// Newton stops only at the tolerance.
class NewtonSolver {
public:
  /// With `matrix_shares`, the objective's Hessians are each rank's share of a sum
  /// (Discretization::matrix_share_owners) that `linear_solver` sums: what Newton itself
  /// takes from them, the lifting of the prescribed increments and the round-off floor, is
  /// summed over the ranks.
  NewtonSolver(LinearSolver& linear_solver, const Eigen::SparseMatrix<double>& pattern,
               const DirichletElimination& elimination, bool matrix_shares = false);

  /// Minimises `objective` from `u` with the constrained DOFs driven to `prescribed`
  /// (constrained_dofs() order). Throws NumericalError naming `step` and the iteration.
  NewtonReport minimize(const Objective& objective, Eigen::VectorXd& u, const Eigen::VectorXd& prescribed,
                        const NewtonOptions& options, int step);
  /// Linear solves of the last minimize/single_step call so far: after a NumericalError,
  /// the iterations the failed step had spent (summary.json counts them too).
  int iterations_of_last_call() const { return iterations_of_last_call_; }
  /// One Newton step without line search or convergence test (semi-implicit Euler).
  NewtonReport single_step(const Objective& objective, Eigen::VectorXd& u, const Eigen::VectorXd& prescribed,
                           const NewtonOptions& options, int step);

private:
  // 16 ε ‖(|H| |u|)_free‖ with H the last eliminated Hessian (solve_step's).
  double round_off_floor(const Eigen::VectorXd& u);

  // rhs_ lifted by the prescribed increments (DirichletElimination::lift), from `matrix`.
  void lift(const Eigen::SparseMatrix<double>& matrix, const Eigen::VectorXd& increment);

  // Assembles, eliminates, factorises (unless reusable) and solves for the step.
  void solve_step(const Objective& objective, const Eigen::VectorXd& u, const Eigen::VectorXd& gradient,
                  const Eigen::VectorXd& increment, bool project_spd, int step, int iteration);

  // The objective's gradient into gradient_ / Hessian into matrix_, with a failure
  // (an inverted element) rethrown naming the step and iteration.
  void evaluate_gradient(const Objective& objective, const Eigen::VectorXd& u, int step, int iteration);
  void assemble_hessian(const Objective& objective, const Eigen::VectorXd& u, bool project_spd, int step,
                        int iteration);

  LinearSolver& linear_solver_;
  const DirichletElimination& elimination_;
  Eigen::SparseMatrix<double> matrix_;
  Eigen::SparseMatrix<double> constant_hessian_;  // before elimination, for the lifting
  Eigen::VectorXd rhs_, direction_, gradient_, trial_, trial_gradient_, magnitudes_, lifted_;
  bool matrix_shares_ = false;
  int iterations_of_last_call_ = 0;
  bool constant_factorised_ = false;
};

}  // namespace altfem
