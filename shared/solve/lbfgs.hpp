#pragma once
// L-BFGS through NLopt (Luksan's limited-memory BFGS, NLOPT_LD_LBFGS): the
// alternative to Newton for minimising the incremental potential.
#include <Eigen/Core>

#include <functional>
#include <string>

namespace altfem {

/// Returns f(x) and writes ∇f(x) into `gradient` (#unknowns; sized by the
/// objective). May return +inf for an inadmissible x (an inverted element).
using LbfgsObjective = std::function<double(const Eigen::VectorXd& x, Eigen::VectorXd& gradient)>;

struct LbfgsOptions {
  /// Converged when ‖∇f(x)‖₂ ≤ gradient_tolerance at an evaluated point.
  double gradient_tolerance = 1e-8;
  int max_evaluations = 10000;
  /// Number of stored correction pairs (NLopt's vector storage). NLopt's own
  /// default grows like 1/#unknowns and allocates and clears tens of megabytes
  /// for small problems (~0.1 s per call).
  int memory = 10;
  /// Optional diagonal change of variables x = scale ⊙ y (#unknowns, positive; empty:
  /// none). With scale = diag(H)^-1/2 of the Hessian at the start, L-BFGS sees a
  /// Jacobi-preconditioned problem: finite element unknowns whose stiffness differs by
  /// orders of magnitude (a clamped end against a free one, mass against stiffness)
  /// otherwise stall Luksan's line search. The gradient tolerance still applies to ∇f(x).
  Eigen::VectorXd scale;
};

enum class LbfgsStatus {
  converged,        ///< the gradient tolerance was met
  max_evaluations,  ///< out of objective evaluations
  stalled,          ///< NLopt stopped first (its line search made no more progress)
};

struct LbfgsResult {
  LbfgsStatus status = LbfgsStatus::stalled;
  /// Objective evaluations. NLopt does not expose L-BFGS iterations; each takes
  /// one evaluation unless its line search backtracks.
  int evaluations = 0;
  double objective = 0;      ///< f at the returned x
  double gradient_norm = 0;  ///< ‖∇f‖₂ at the returned x
  std::string detail;        ///< NLopt's result code, e.g. "FORCED_STOP", for logs
};

/// Minimises `objective` from the initial guess `x` (#unknowns); on return `x`
/// is the point that met the gradient tolerance, else the best point evaluated.
///
/// NLopt has no gradient-norm stopping rule, so the objective wrapper checks
/// ‖∇f‖ after every evaluation and calls nlopt::opt::force_stop(); NLopt's own
/// ftol/xtol tests are off and its fixed ‖∇f‖∞ ≤ 1e-8 test is outscaled (lbfgs.cpp).
/// Below ‖∇f‖ ≈ √(ε·|f|·λmax) the line search cannot see decrease any more
/// and the run ends as `stalled`. A +inf value is returned to NLopt as is: its line
/// search treats it as a failed step and shrinks (see tests/unit/solve/test_lbfgs.cpp).
/// An exception thrown by `objective` stops the run and is rethrown unchanged.
LbfgsResult minimize_lbfgs(const LbfgsObjective& objective, Eigen::VectorXd& x, const LbfgsOptions& options = {});

}  // namespace altfem
