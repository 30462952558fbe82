#pragma once
// The `dg` block of a scene (docs/scene-schema.md, "dg"): its rules, the defaults that
// depend on the geometry, and the options the dg method reads.
//
// Penalty conventions. Every convention ends as Kaufmann et al.'s face penalty
// (2009, eq. (20)) η_f = c_f · η · area(f) · (1/vol(K⁻) + 1/vol(K⁺)), where c_f = 1 on
// interior faces and c_f = `boundary_factor` on Dirichlet faces (the plus term is absent),
// or, with `scaling` cell_surface (the default), η_f = c_f · η · (1/ℓ(K⁻) + 1/ℓ(K⁺)) with
// ℓ(K) = 6 vol(K)/area(∂K) (PenaltyScaling; the same on cubes; 1/h below means either):
//   kaufmann  value η̂ (default 20):  η = η̂ · E (η̂ relative to Young's modulus, so that
//             the paper's 10¹–10² is unit-free), c_f = 1 on every face;
//   mfem      value κ (default (k+1)², MFEM example 17): MFEM's κ·(λ+2μ)/h with
//             1/h = area(f)/vol(K) averaged (½ each side) on interior faces and taken
//             whole on boundary faces, i.e. η = κ(λ+2μ)/2, c_f = 2;
//   dealii    value γ (default 1, deal.II step-74): γ·k(k+1)·(λ+2μ)·½(1/h⁻ + 1/h⁺) with the
//             cell extent h = vol(K)/area(f) (1/h on a boundary face), i.e.
//             η = γ·k(k+1)(λ+2μ)/2, c_f = 2.
// With `lame_split` (mfem and dealii) the λ part of that (λ + 2μ)-scaled η penalises the
// normal jump only and 2μ the whole jump (Hansbo & Larson 2002): locking-free as ν → ½.
// With `double_until_definite` (default for kaufmann only) η is doubled until K is
// positive definite, as Kaufmann et al. do (§8, "we simply start with a low value and
// double it"); the η used is reported in summary.json (facts).
#include <string>

#include "dg/dg_linear_system.hpp"
#include "shared/fem/fem_scene_block.hpp"
#include "shared/fem/polyhedral_scene_mesh.hpp"
#include "shared/scene/method_scene_block.hpp"

namespace altfem::dg {

enum class PenaltyConvention { kaufmann, mfem, dealii };
inline constexpr std::array<std::string_view, 3> penalty_convention_names{"kaufmann", "mfem", "dealii"};
inline constexpr std::array<std::string_view, 2> flux_names{"interior_penalty", "babuska_zlamal"};
/// Dirichlet conditions through the boundary faces' flux terms (§4.2), or as constraints on
/// the coefficients of the cells they touch (dg/strong_conditions.hpp).
inline constexpr std::array<std::string_view, 2> condition_imposition_names{"weak", "strong"};
/// How the scene surface follows the discontinuous field (Kaufmann et al. 2009 §7): each
/// vertex by its own element's polynomial (the mean on shared faces), nodal averages
/// (eq. (30)) interpolated by the converted mesh's C⁰ basis, or MLS (eqs. (31)-(32)).
enum class Embedding { element, stitched, mls };
inline constexpr std::array<std::string_view, 3> embedding_names{"element", "stitched", "mls"};

/// The preconditioner of iterative linear solvers (solver/linear pcg, minres,
/// conjugate_residual): block Jacobi (one block per element), the two-level V-cycle of that
/// smoother with the vertex coarse space (dg/vertex_coarse_space.hpp), or the multilevel one
/// whose coarse solve is a V-cycle over background grids (dg/grid_coarse_levels.hpp); the
/// last two keep the iterations bounded under refinement.
enum class DgPreconditioner { block_jacobi, two_level, multilevel };
inline constexpr std::array<std::string_view, 3> dg_preconditioner_names{"block_jacobi", "two_level", "multilevel"};

struct DgSpec {
  int degree = 2;
  Flux flux = Flux::interior_penalty;
  PenaltyConvention convention = PenaltyConvention::kaufmann;
  double penalty_value = 20;
  bool double_until_definite = true;
  PenaltyScaling scaling = PenaltyScaling::cell_surface;
  /// The λ part of a (λ + 2μ)-scaled penalty on normal jumps only (Hansbo & Larson 2002).
  bool lame_split = false;
  /// Corotated stiffness warping (Kaufmann et al. 2009 §6), linear material only.
  bool warping = false;
  /// Dirichlet conditions imposed strongly (linear material without warping only).
  bool strong_conditions = false;
  Embedding embedding = Embedding::mls;
  DgPreconditioner preconditioner = DgPreconditioner::block_jacobi;
  /// The nonlinear path's volume rules simplified (DgSettings::rule_simplification).
  std::optional<SimplificationMethod> rule_simplification = SimplificationMethod::caratheodory;
  /// The geometry sliced (mesh "slice"), or the volume mesh converted into polyhedra:
  /// element, mesh kind, resolution and max_cell_size as the `fem` block means them
  /// (quadrature_order and curved unused).
  PolyhedralMeshSource mesh;
};

const MethodSceneBlock& dg_scene_block();

/// The resolved /discretization/dg of `scene` as options. Throws InputError for a bad block.
DgSpec dg_spec(const Scene& scene);

struct FacePenalty {
  double eta;                  ///< η of eq. (20) in the units of the stiffness (Pa)
  double boundary_factor;      ///< c_f on Dirichlet faces
  double tangential_fraction;  ///< of η on tangential jumps: 2μ/(λ + 2μ) with lame_split, else 1
};

/// The penalty of `spec`'s convention for a material (E, λ, μ), before any doubling.
FacePenalty face_penalty(const DgSpec& spec, double youngs_modulus, double lambda, double mu);

}  // namespace altfem::dg
