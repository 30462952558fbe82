#pragma once
// The face matrices of DG for isotropic linear elasticity, integrated exactly
// (Kaufmann et al. 2009 §4.1-4.2, eqs. (19)-(21), (24)-(26)): products of the two
// neighbours' monomials are polynomials, integrated over the planar polygonal face by
// the divergence theorem (shared/geometry/planar_polygon_moments). With n the unit
// normal from the minus to the plus element, [[u]] = u⁻ − u⁺ and {σ} = ½(σ⁻ + σ⁺):
//   interior penalty (21):  −∫ [[v]]·{σ(u)}n − ∫ [[u]]·{σ(v)}n + η_f ∫ [[u]]·[[v]]
//   Babuška–Zlámal (19):                                          η_f ∫ [[u]]·[[v]]
// On a boundary face (no plus element) the same with u⁺ = 0 and {σ} = σ⁻: Nitsche's
// weak Dirichlet condition for IP, the penalty alone for BZ (§4.2).
#include <Eigen/Core>
#include <array>

#include "dg/monomial_basis.hpp"
#include "shared/material/lame_parameters.hpp"

namespace altfem::dg {

enum class Flux { interior_penalty, babuska_zlamal };

/// The face's matrix over [minus basis, plus basis] (3(n⁻ + n⁺) square, local DOF 3a+i,
/// the minus element's functions first; n⁺ = 0 without `plus`). polygon: #vertices × 3,
/// planar; normal: unit, minus → plus; penalty: η_f of eq. (20). components: on a
/// boundary face, the components the condition prescribes — with P = diag(components)
/// the terms become −∫ Pv·σ(u)n − ∫ Pu·σ(v)n + η_f ∫ Pu·Pv (all three on interior faces).
/// minus_lame, plus_lame: each side's Lamé parameters; the stress of a side's functions
/// in {σ} takes that side's (a material interface: ½(σ⁻(u⁻) + σ⁺(u⁺)) with σ^± = C^± ε).
Eigen::MatrixXd exact_face_matrix(const Eigen::MatrixXd& polygon, const Eigen::Vector3d& normal,
                                  const MonomialBasis& minus, const MonomialBasis* plus, const LameParameters& minus_lame,
                                  const LameParameters& plus_lame, double penalty, Flux flux,
                                  const std::array<bool, 3>& components = {true, true, true});

/// One material on both sides.
inline Eigen::MatrixXd exact_face_matrix(const Eigen::MatrixXd& polygon, const Eigen::Vector3d& normal,
                                         const MonomialBasis& minus, const MonomialBasis* plus, double lambda, double mu,
                                         double penalty, Flux flux,
                                         const std::array<bool, 3>& components = {true, true, true}) {
  return exact_face_matrix(polygon, normal, minus, plus, {lambda, mu}, {lambda, mu}, penalty, flux, components);
}

/// exact_face_matrix split for stiffness warping (Kaufmann et al. 2009 §6.1): the
/// penalty term K_f3 (26), and per side s (0 minus, 1 plus) K_f1^s = −½∫[[v]]·σ^s(u)n
/// (−∫ v·σ(u)n on a boundary face), rows the jump of the test functions of both sides,
/// columns the strain of side s only; K_f2^s = K_f1^sᵀ. Over the face's whole local DOF
/// set; zero for BZ and for a missing plus side.
/// exact_face_matrix = penalty + Σ_s (consistency[s] + consistency[s]ᵀ).
struct FaceMatrixParts {
  Eigen::MatrixXd penalty;
  std::array<Eigen::MatrixXd, 2> consistency;
};
FaceMatrixParts exact_face_matrix_parts(const Eigen::MatrixXd& polygon, const Eigen::Vector3d& normal,
                                        const MonomialBasis& minus, const MonomialBasis* plus,
                                        const LameParameters& minus_lame, const LameParameters& plus_lame,
                                        double penalty, Flux flux,
                                        const std::array<bool, 3>& components = {true, true, true});

}  // namespace altfem::dg
