#pragma once
// The DG system of isotropic linear elasticity on polyhedral cells, integrated exactly
// (Kaufmann et al. 2009 §4): K = Σ_K K_K + Σ_f K_f (eqs. (23)-(26)) with the penalty
// η_f of eq. (20) or its cell-surface variant (PenaltyScaling), the loads of a body force and
// of Dirichlet data imposed weakly on boundary faces (Nitsche for interior penalty, the
// penalty alone for Babuška–Zlámal).
#include <Eigen/SparseCore>
#include <algorithm>
#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "dg/face_matrices.hpp"
#include "dg/monomial_basis.hpp"
#include "shared/geometry/polyhedron.hpp"
#include "shared/quadrature/polyhedron_rule.hpp"
#include "shared/solve/dirichlet_dofs.hpp"

namespace altfem::dg {

class CellBlockPattern;   // dg/cell_block_pattern.hpp
struct StrongCell;        // dg/strong_conditions.hpp
struct DgIntegralMemory;  // dg/dg_integral_memory.hpp

struct DgFace {
  Eigen::MatrixXd polygon;  ///< #vertices × 3, planar
  Eigen::Vector3d normal;   ///< unit, from `minus` to `plus` (outward on a boundary face)
  int minus = 0;
  int plus = -1;  ///< -1: a boundary face
  /// Boundary faces only: the index of the Dirichlet condition imposed weakly here (the
  /// `condition` argument of dirichlet_load's data), -1 for a free face.
  int condition = -1;
  /// The components that condition prescribes (the others are free on this face).
  std::array<bool, 3> components{true, true, true};
  /// The condition imposed strongly (dg/strong_conditions.hpp): no face term; the cell's
  /// constrained coefficients are DOFs with prescribed values.
  bool strong = false;
};

/// How the penalty of a face depends on the sizes of its two cells. Either way η_f
/// multiplies ∫_f [[u]]·[[v]] and equals η · 2/h on an interior face of a grid of cubes of edge h.
///   face_area     Kaufmann et al. 2009, eq. (20): η · area(f) · (1/vol(K⁻) + 1/vol(K⁺)).
///                 A face much smaller than its cells' other faces (a cut cell's facets of
///                 a curved surface, a face between two cut pieces) gets a penalty per unit
///                 area that is as much smaller, so η must grow with the faces per cell.
///   cell_surface  η · (1/ℓ(K⁻) + 1/ℓ(K⁺)) with ℓ(K) = 6 vol(K)/area(∂K) (the edge of a cube,
///                 the diameter of a ball): every face of a cell the same penalty per unit
///                 area, the one the cell's trace inequality asks for — for k = 1, whose
///                 stress is constant in a cell, Σ_f area(f)/η_f = 6 vol(K)/η on every cell
///                 whatever its number and sizes of faces, as on a cube under eq. (20)
///                 (cf. the polytopic interior penalty of Cangiani, Georgoulis & Houston 2014,
///                 whose penalty per unit area grows like 1/h_⊥ of the cell, not like area(f)).
enum class PenaltyScaling { face_area, cell_surface };
inline constexpr std::array<std::string_view, 2> penalty_scaling_names{"face_area", "cell_surface"};

/// The material of a cell: Lamé parameters, density and η of eq. (20) (units of λ, μ),
/// of which the fraction `tangential_fraction` penalises tangential jumps (JumpPenalty;
/// 1: isotropic, 2μ/(λ + 2μ): Hansbo & Larson's split of a (λ + 2μ)-scaled η).
struct DgMaterial {
  double lambda = 1, mu = 1;
  double density = 1;
  double penalty = 20;
  double tangential_fraction = 1;
};

struct DgSettings {
  int degree = 2;
  Flux flux = Flux::interior_penalty;
  double penalty = 20;  ///< η of eq. (20), in the units of the stiffness (λ, μ)
  double lambda = 1, mu = 1;
  double density = 1;  ///< ρ of the mass matrix
  /// η_f of a boundary face is this factor × eq. (20) (1 in Kaufmann et al.; MFEM and
  /// deal.II halve the sum of the two sides' terms on interior faces only, which is 2 here).
  double boundary_penalty_factor = 1;
  PenaltyScaling scaling = PenaltyScaling::cell_surface;
  double tangential_fraction = 1;  ///< DgMaterial::tangential_fraction
  /// Compute the element matrices once per class of cells that are translates of each
  /// other (same material), the face matrices once per class of faces between such cells
  /// (dg/cell_similarity.hpp). The matrices equal the recomputed ones up to round-off
  /// (≤ 1e-12 relative); false recomputes every cell and face, for comparison.
  bool reuse_similar_cells = true;
  /// The volume rules of the tabulated paths (nonlinear materials, field quadrature)
  /// simplified to at most C(s + 3, 3) points of strength s (simplified_polyhedron_rule),
  /// or the cone rules as they are (nullopt). The exact linear path has no rule.
  std::optional<SimplificationMethod> rule_simplification = std::nullopt;
  /// Over several ranks, leave K each rank's share (its cells' and owned faces' matrices)
  /// on a pattern of its cells' and faces' blocks (the other cells' diagonals alone), for a solver that sums
  /// the shares (PETSc; docs/scaling.md), instead of summing it into every rank's copy.
  bool share_stiffness = false;
};

/// How many cells and faces a DgLinearSystem integrated, and how many distinct classes
/// of translates among them it computed matrices for (the rest reused them).
struct SimilarityStatistics {
  int cells = 0, cell_classes = 0;
  int faces = 0, face_classes = 0;  ///< faces with a term (free or strong boundary faces have none)
  /// Of the classes, those whose matrices were taken from the build before (DgIntegralMemory).
  int remembered_cell_classes = 0, remembered_face_classes = 0;
};

/// What a system takes from the build an event replaces and what it keeps for the next
/// (dg/dg_integral_memory.hpp). Both off: every class integrated, nothing kept.
struct IntegralReuse {
  /// null: none; ignored unless it integrates_as this one. The matrices taken are moved out
  /// of it (the build it came from is being replaced), so that they are not held twice.
  std::shared_ptr<DgIntegralMemory> previous;
  bool remember = false;  ///< keep this build's matrices (integral_memory())
};

/// Several materials (a piecewise-constant elasticity tensor): cell c takes
/// materials[ids[c]]; a face's consistency terms take each side's own λ, μ and its
/// penalty each side's η: η_f = c_f · area(f) · (η⁻/vol(K⁻) + η⁺/vol(K⁺)), eq. (20) with η
/// inside the sum (MFEM's DGElasticityIntegrator sums its κ(λ+2μ) over the sides the same
/// way). Empty: every cell has the settings' penalty, lambda, mu and density.
struct DgCellMaterials {
  std::vector<DgMaterial> materials;
  std::vector<int> ids;  ///< #cells, each < materials.size()
};

using VectorField = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;
/// Dirichlet data g(condition, x): the displacement condition `condition` prescribes at x.
using ConditionData = std::function<Eigen::Vector3d(int condition, const Eigen::Vector3d&)>;
/// Moving Dirichlet data g(condition, x, t): the displacement condition `condition` prescribes
/// at x at time t.
using ConditionTrajectory = std::function<Eigen::Vector3d(int condition, const Eigen::Vector3d&, double time)>;

class DgLinearSystem {
public:
  DgLinearSystem(std::vector<Polyhedron> cells, std::vector<DgFace> faces, const DgSettings& settings,
                 DgCellMaterials cell_materials = {}, IntegralReuse reuse = {});
  ~DgLinearSystem();

  /// 3 × Σ #functions square; cell c's functions start at offset(c), DOF 3a + i.
  const Eigen::SparseMatrix<double>& stiffness() const { return stiffness_; }
  /// Hands K over (stiffness() is empty afterwards): for the owner whose discretization
  /// keeps K, so that it is not stored twice.
  /// (Eigen 3.4's SparseMatrix has no move constructor: std::move would copy; swap does not.)
  Eigen::SparseMatrix<double> take_stiffness() {
    Eigen::SparseMatrix<double> taken;
    taken.swap(stiffness_);
    return taken;
  }
  /// The consistent mass ρ ∫ φ_a φ_b δ_ik (3 × Σ #functions square), block-diagonal by cell.
  Eigen::SparseMatrix<double> mass() const;
  /// ∫ φ_a dV of every function (Σ #functions): the load of a unit body force density.
  const Eigen::VectorXd& function_integrals() const { return integrals_; }
  int cell_count() const { return static_cast<int>(cells_.size()); }
  const Polyhedron& cell(int index) const { return cells_[index]; }
  /// The volume rule of a cell at a strength for the tabulated paths: the cone rule
  /// (polyhedron_rule), simplified as the settings' rule_simplification says.
  PolyhedronRule cell_rule(int cell, int strength) const;
  const std::vector<DgFace>& faces() const { return faces_; }
  Flux flux() const { return settings_.flux; }
  /// η_f of one of faces() by the settings' scaling (× boundary_penalty_factor on a boundary
  /// face), its normal and tangential parts (each side's η times its tangential_fraction).
  JumpPenalty face_penalty(const DgFace& face) const;
  /// The share of face_penalty(face) that `cell`, one of the face's sides, contributes: its
  /// own η over its length (face_penalty sums the two sides' shares).
  JumpPenalty side_penalty(const DgFace& face, int cell) const;
  /// With settings.share_stiffness over several ranks, the rank owning each function's rows
  /// (Σ #functions: its cell's part); empty when K is the whole on every rank.
  std::vector<int> share_row_owners() const;
  /// Over several ranks (docs/scaling.md), whether this rank integrates a cell's matrices
  /// and a face's (the lower part of its cells'); always on one rank. K, the mass and the
  /// cells' sizes and integrals are the sums of every rank's parts.
  bool owns_cell(int cell) const { return cell_parts_.empty() || cell_parts_[cell] == rank_; }
  bool owns_face(const DgFace& face) const {
    if (cell_parts_.empty()) return true;
    const int part =
        face.plus < 0 ? cell_parts_[face.minus] : std::min(cell_parts_[face.minus], cell_parts_[face.plus]);
    return part == rank_;
  }
  /// A cell's class of translates, and that class's volume stiffness (3 #functions square;
  /// over several ranks, only the classes of this rank's cells).
  int cell_class(int cell) const { return cell_classes_[cell]; }
  const Eigen::MatrixXd& class_stiffness(int cell_class) const { return stiffnesses_[cell_class]; }
  /// A face's class (faces of a class are translates between cells of the same classes);
  /// −1 for a face without a term (free, or held strongly).
  int face_class(int face) const { return face_classes_[face]; }
  int offset(int cell) const { return offsets_[cell]; }
  double volume(int cell) const { return volumes_[cell]; }
  /// The index into cell_materials.materials of a cell's material (0 with a single material).
  int material_id(int cell) const { return cell_materials_.ids.empty() ? 0 : cell_materials_.ids[cell]; }
  /// A cell's material: cell_materials.materials[material_id(cell)], or the settings' one.
  DgMaterial material(int cell) const;
  const MonomialBasis& basis(int cell) const { return bases_[cell]; }
  int dof_count() const { return 3 * offsets_.back(); }
  const SimilarityStatistics& similarity() const { return similarity_; }
  /// This build's matrices by class, for the system an event rebuilds, which moves what it
  /// takes out of them (null unless IntegralReuse::remember).
  std::shared_ptr<DgIntegralMemory> integral_memory() const { return memory_; }
  /// Per class of cells, or of faces, the class of the build before whose matrices it took
  /// (−1: integrated here); and that build's certificate ratios (DgIntegralMemory), in its
  /// classes. Empty without such a build.
  int previous_cell_class(int k) const { return previous_cell_classes_.empty() ? -1 : previous_cell_classes_[k]; }
  int previous_face_class(int k) const { return previous_face_classes_.empty() ? -1 : previous_face_classes_[k]; }
  const std::map<std::vector<int>, double>& previous_certificate_ratios() const { return previous_certificates_; }

  /// ∫ f·v for a force density f, by a rule of strength 2k + 2 on each cell (exact for
  /// polynomial f of degree ≤ k + 2).
  Eigen::VectorXd body_load(const VectorField& force_density) const;
  /// −∫ Pg·σ(v)n + η_f ∫ Pg·v (IP) or η_f ∫ Pg·v (BZ) over the Dirichlet faces, g = data(the
  /// face's condition, x), P = diag(the face's components), by a rule of strength 2k + 2 on each face (exact for
  /// polynomial data of degree ≤ k + 3). `penalty_only`: the η_f ∫ Pg·v part alone (stiffness warping rotates the
  /// consistency part with the boundary element, §6).
  Eigen::VectorXd dirichlet_load(const ConditionData& data, bool penalty_only = false) const;
  /// The DOFs that strongly imposed conditions fix (sorted), and their values for the
  /// data g = data(condition, x) (in the same order): the constrained coefficients of the
  /// prescribed components of each cell with strong faces (dg/strong_conditions.hpp).
  const std::vector<int>& constrained_dofs() const { return constrained_dofs_; }
  /// Per constrained DOF, the conditions of its cell's strong faces.
  const std::vector<ConstraintHolders>& constraint_holders() const { return constraint_holders_; }
  Eigen::VectorXd constrained_values(const ConditionData& data) const;
  /// (∫ |u_h − u|² dV)^½ for coefficients u_h and a field u, by a strength 2k + 4 rule.
  double l2_error(const Eigen::VectorXd& coefficients, const VectorField& field) const;
  /// The coefficients of a polynomial field of degree ≤ the basis degree (exact), by
  /// collocation at points of each cell's frame.
  Eigen::VectorXd interpolate(const VectorField& field) const;

private:
  // K's element blocks (and the per-cell volumes, lengths, integrals and masses) and its
  // face blocks, each computed once per class of translates (dg/cell_similarity.hpp) or
  // taken from `previous` (may be null). add_element_matrices returns per cell class its
  // class in `previous` (-1: none), which the faces' keys there hold.
  std::vector<int> add_element_matrices(const CellBlockPattern& pattern, DgIntegralMemory* previous);
  void add_face_matrices(const CellBlockPattern& pattern, DgIntegralMemory* previous,
                         const std::vector<int>& previous_cell_classes);
  // body(cell, x, w, φ(x)) at every point of a rule of `strength` on every cell.
  template <typename Body>
  void for_each_cell_point(int strength, Body&& body) const;

  std::vector<Polyhedron> cells_;
  std::vector<DgFace> faces_;
  DgSettings settings_;
  DgCellMaterials cell_materials_;
  std::vector<MonomialBasis> bases_;
  std::vector<StrongCell> strong_cells_;  // the cells with strongly constrained faces
  std::vector<int> constrained_dofs_;
  std::vector<ConstraintHolders> constraint_holders_;
  std::vector<double> volumes_;
  std::vector<double> inverse_lengths_;       // per cell, area(∂K) / (6 vol(K)) = 1/ℓ(K)
  std::vector<int> cell_classes_;             // per cell, its class of translates
  std::vector<Eigen::MatrixXd> masses_;       // per class of cells, #functions square
  std::vector<Eigen::MatrixXd> stiffnesses_;  // per class of cells, 3 #functions square
  std::vector<int> face_classes_;             // per face, its class (-1: no term)
  std::vector<int> cell_parts_;               // per cell, the rank integrating it (empty: one rank)
  int rank_ = 0;
  Eigen::SparseMatrix<double> distributed_mass_;  // over several ranks, the summed mass (else empty)
  Eigen::VectorXd integrals_;
  std::vector<int> offsets_;  // #cells + 1
  Eigen::SparseMatrix<double> stiffness_;
  SimilarityStatistics similarity_;
  std::shared_ptr<DgIntegralMemory> memory_;
  std::vector<int> previous_cell_classes_, previous_face_classes_;  // per class (empty: no build before)
  std::map<std::vector<int>, double> previous_certificates_;
};

}  // namespace altfem::dg
