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

/// The penalty of a face's jumps, split into its normal and tangential parts:
/// η_f ∫ [[u]]ᵀ T [[v]] with T = tangential I + (normal − tangential) n nᵀ. Isotropic
/// (normal = tangential = η_f) in Kaufmann et al. 2009 (eq. (26)); with a (λ + 2μ)-scaled
/// penalty split as Hansbo & Larson 2002 (CMAME 191) do — 2μ on the whole jump, λ on
/// its normal part only — the discrete space keeps divergence-free functions with
/// continuous normal components, and nearly incompressible materials do not lock.
struct JumpPenalty {
  double normal = 0;
  double tangential = 0;
  JumpPenalty() = default;
  JumpPenalty(double isotropic) : normal(isotropic), tangential(isotropic) {}  // NOLINT: a scalar η_f is isotropic
  JumpPenalty(double normal_part, double tangential_part) : normal(normal_part), tangential(tangential_part) {}
  /// T for the unit normal n (3 × 3, symmetric).
  Eigen::Matrix3d tensor(const Eigen::Vector3d& n) const {
    return tangential * Eigen::Matrix3d::Identity() + (normal - tangential) * n * n.transpose();
  }
};

/// The face's matrix over [minus basis, plus basis] (3(n⁻ + n⁺) square, local DOF 3a+i,
/// the minus element's functions first; n⁺ = 0 without `plus`). polygon: #vertices × 3,
/// planar; normal: unit, minus → plus; penalty: η_f of eq. (20), split or not. components: on a
/// boundary face, the components the condition prescribes — with P = diag(components)
/// the terms become −∫ Pv·σ(u)n − ∫ Pu·σ(v)n + η_f ∫ (Pu)ᵀ T Pv (all three on interior faces).
/// minus_lame, plus_lame: each side's Lamé parameters; the stress of a side's functions
/// in {σ} takes that side's (a material interface: ½(σ⁻(u⁻) + σ⁺(u⁺)) with σ^± = C^± ε).
Eigen::MatrixXd exact_face_matrix(const Eigen::MatrixXd& polygon, const Eigen::Vector3d& normal,
                                  const MonomialBasis& minus, const MonomialBasis* plus,
                                  const LameParameters& minus_lame, const LameParameters& plus_lame,
                                  const JumpPenalty& penalty, Flux flux,
                                  const std::array<bool, 3>& components = {true, true, true});

/// One material on both sides.
inline Eigen::MatrixXd exact_face_matrix(const Eigen::MatrixXd& polygon, const Eigen::Vector3d& normal,
                                         const MonomialBasis& minus, const MonomialBasis* plus, double lambda,
                                         double mu, const JumpPenalty& penalty, Flux flux,
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
                                        const JumpPenalty& penalty, Flux flux,
                                        const std::array<bool, 3>& components = {true, true, true});

}  // namespace altfem::dg
