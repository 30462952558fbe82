#pragma once
// The stress in each element as one tensor, what refinement marks by (Kaufmann et al. 2009
// §9.3: "the largest absolute principal stress" of an element; Martin et al. 2008 §8).
#include <Eigen/Core>
#include <vector>

#include "shared/assembly/tabulated_elements.hpp"
#include "shared/material/lame_parameters.hpp"
#include "shared/material/material.hpp"

namespace altfem {

/// Per element of `elements`, the small-strain stress σ = λ tr(ε) I + 2μ ε of its mean
/// strain ε = (1/V) ∫ sym(∇u) dV (the rule's weights), with the Lamé parameters of the
/// element's own material (materials[element.material], as the tabulation assigned them)
/// and u the coefficients (#dofs; basis function a carries 3a..3a+2). Exact for any field
/// whose gradient the rule integrates. Over a rank's share (TabulatedElements::keep_only)
/// every rank computes its elements' and receives the others' (a collective call).
std::vector<Eigen::Matrix3d> mean_cell_stresses(const TabulatedElements& elements,
                                                const std::vector<const Material*>& materials,
                                                const Eigen::VectorXd& u);

/// The largest absolute eigenvalue of the symmetric `stress` and its unit eigenvector.
struct PrincipalStress {
  double value = 0;  ///< |σ_i| largest
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();
};
PrincipalStress largest_principal_stress(const Eigen::Matrix3d& stress);

}  // namespace altfem
