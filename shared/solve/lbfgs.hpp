#pragma once
// L-BFGS (Nocedal & Wright, Alg. 7.4/7.5): the alternative to Newton for minimising
// the incremental potential.
//
// Written here instead of NLopt's LD_LBFGS (issue #22): Luksan's line search judges
// steps by function values, and the potential of a finite element problem is a sum of
// terms much larger than the changes near its minimum, so below ‖∇f‖ ≈ √(ε·|f|·λ_max)
// the values no longer show decrease and NLopt stopped with FAILURE above the stopping
// rule of Longva et al. (the shipped twisting beam, step 6). This line search uses the
// approximate Wolfe conditions of Hager & Zhang (2005, eq. (23)), which judge a step by
// the directional derivative ∇f(x + αd)·d once the values are within round-off, and the
// iteration is Jacobi-preconditioned through an optional diagonal scaling.
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
  /// Number of stored correction pairs.
  int memory = 10;
  /// Optional diagonal preconditioner, as a change of variables x = scale ⊙ y
  /// (#unknowns, positive; empty: none). With scale = diag(H)^-1/2 of the Hessian at
  /// the start, unknowns whose stiffness differs by orders of magnitude (a clamped end
  /// against a free one, mass against stiffness) look alike to L-BFGS.
  Eigen::VectorXd scale;
};

enum class LbfgsStatus {
  converged,        ///< the gradient tolerance was met
  max_evaluations,  ///< out of objective evaluations
  stalled,          ///< the line search found no acceptable step
};

struct LbfgsResult {
  LbfgsStatus status = LbfgsStatus::stalled;
  int iterations = 0;        ///< accepted steps
  int evaluations = 0;       ///< objective evaluations (line searches may take several per step)
  double objective = 0;      ///< f at the returned x
  double gradient_norm = 0;  ///< ‖∇f‖₂ at the returned x
  std::string detail;        ///< why it stopped, for messages
};

/// Minimises `objective` from the initial guess `x` (#unknowns); on return `x` is the
/// point that met the gradient tolerance, else the last accepted point. A +inf value
/// makes the line search shrink the step. An exception thrown by `objective` stops the
/// run and is rethrown unchanged.
LbfgsResult minimize_lbfgs(const LbfgsObjective& objective, Eigen::VectorXd& x, const LbfgsOptions& options = {});

}  // namespace altfem
