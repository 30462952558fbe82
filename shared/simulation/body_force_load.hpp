#pragma once
// The load of a body force given per unit volume as an expression f(X, t) (N/m³, at the
// rest position X: docs/scene-schema.md, "Loads"), integrated against the method's basis
// with its own volume rule: F_(3a+i) = Σ_q w_q f_i(x_q, t) φ_a(x_q) ≈ ∫ f_i φ_a dV.
#include <Eigen/Core>

#include <functional>
#include <string>

#include "shared/scene/scene.hpp"
#include "shared/simulation/field_quadrature.hpp"
#include "shared/simulation/method_instance.hpp"

namespace altfem {

/// Σ_q w_q f(x_q) φ_a(x_q) for forces (#points × 3, one row per point of `quadrature`): #dofs.
Eigen::VectorXd integrate_against_basis(const FieldQuadrature& quadrature, const Eigen::MatrixXd& forces,
                                        int dof_count);

/// The body-force load at any time; integrated once when f does not depend on t.
class BodyForceLoad {
public:
  BodyForceLoad(FieldQuadrature quadrature, VectorExpression force, int dof_count);
  Eigen::VectorXd operator()(double time) const;

private:
  FieldQuadrature quadrature_;
  VectorExpression force_;
  int dof_count_;
  Eigen::VectorXd constant_;  // the load when f does not depend on t
};

/// The scene's `loads.body_force` on the method's basis as a load at a time (for
/// TimedDiscretization's scene loads); empty when the scene has none. Throws InputError
/// naming the key when the method gives no field quadrature.
std::function<Eigen::VectorXd(double)> body_force_load(const Scene& scene, const MethodInstance& method,
                                                       const std::string& method_name);

}  // namespace altfem
