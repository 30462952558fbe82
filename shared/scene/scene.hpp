#pragma once
// The scene model: the physical problem of one JSON scene file, validated against
// docs/scene-schema.md (the table of every key lives in scene_schema.cpp) and with
// every default resolved.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "shared/mesh/cutting_plane.hpp"

#include "shared/element/element_type.hpp"
#include "shared/geometry/analytic_shape.hpp"
#include "shared/scene/vector_expression.hpp"
#include "shared/solve/linear_solver.hpp"

namespace altfem {

// Each enum's values are in the order of its names array; the arrays are the
// allowed strings of the schema.
enum class GeometryKind { surface, mesh, shape };
enum class RegionKind { box, half_space, sphere };
enum class MotionKind { fixed, translate, rotate, field };
enum class IntegratorKind { backward_euler, symplectic_euler, semi_implicit };
enum class NonlinearSolverKind { newton, lbfgs };

inline constexpr std::array<std::string_view, 5> material_model_names{
    "linear", "corotated_linear", "st_venant_kirchhoff", "neo_hookean", "stable_neo_hookean"};
inline constexpr std::array<std::string_view, 4> motion_kind_names{"fixed", "translate", "rotate", "field"};
inline constexpr std::array<std::string_view, 3> integrator_names{"backward_euler", "symplectic_euler",
                                                                  "semi_implicit"};
inline constexpr std::array<std::string_view, 2> nonlinear_solver_names{"newton", "lbfgs"};

struct GeometrySpec {
  GeometryKind kind = GeometryKind::shape;
  std::filesystem::path file;  ///< absolute; surface or mesh kinds
  ShapePointer shape;          ///< shape kind, before scale/translate
  double scale = 1.0;          ///< applied on load: x ↦ scale·x + translate
  Eigen::Vector3d translate = Eigen::Vector3d::Zero();
};

/// Which material points a boundary condition acts on (world coordinates).
struct RegionSelector {
  RegionKind kind = RegionKind::box;
  Eigen::AlignedBox3d box;                            ///< box kind
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    ///< half_space: a point on the plane
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< half_space: unit; selects (x − point)·normal ≤ 0
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();   ///< sphere kind
  double radius = 0.0;                                ///< sphere kind
  std::string pointer;                                ///< JSON pointer, for error messages

  bool contains(const Eigen::Vector3d& x, double tolerance) const;
  /// The region's bounding box; unbounded (±infinity) for a half-space.
  Eigen::AlignedBox3d bounds() const;
};

/// The resolved `region` object at `pointer` (its keys checked by the schema).
RegionSelector region_from_json(const nlohmann::json& region, const std::string& pointer);

/// The regions' tolerance of docs/scene-schema.md: 1e-6 × the geometry's bounding-box diagonal.
double region_tolerance(const Eigen::AlignedBox3d& geometry_bounds);

struct MaterialSpec {
  std::string model;  ///< one of material_model_names
  double youngs_modulus = 0.0;
  double poisson_ratio = 0.0;
  double density = 0.0;
  /// `materials` entries: the elements whose centroid it holds (first match wins).
  std::optional<RegionSelector> region;
  std::string pointer;  ///< "/material" or "/materials/i", for messages
};

/// A prescribed displacement u(X, t) of the material point X at time t.
struct Motion {
  MotionKind kind = MotionKind::fixed;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();            ///< translate: u = v t
  Eigen::Vector3d total_displacement = Eigen::Vector3d::Zero();  ///< translate: u = d min(t/T, 1)
  double duration = 0.0;                                         ///< T; 0 means the velocity form
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();               ///< rotate: unit
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();              ///< rotate: a point on the axis
  double angular_velocity = 0.0;                                 ///< rotate: rad/s
  VectorExpression field;                                        ///< field: u = field(X, t)

  Eigen::Vector3d displacement(const Eigen::Vector3d& rest_position, double time) const;
};

struct DirichletCondition {
  RegionSelector region;
  Motion motion;
  std::array<bool, 3> components{true, true, true};  ///< which of x, y, z are prescribed
  std::string pointer;                               ///< e.g. "/boundary_conditions/0"
  std::string name;                                  ///< what events call it; empty: unnamed
};

/// A surface load of `loads.traction` (docs/scene-schema.md): a dead load — its direction
/// is fixed in the reference configuration — on the embedded surface's triangles whose
/// centroid the region holds.
struct SurfaceTraction {
  RegionSelector region;
  /// Force per reference area [Pa]: the traction vector, or the traction field (an
  /// expression of x, y, z, t and the outward unit normal nx, ny, nz), or −pressure ×
  /// the outward unit normal of each triangle (a positive pressure pushes into the body).
  std::optional<Eigen::Vector3d> traction;
  VectorExpression traction_field;
  double pressure = 0.0;  ///< used when neither `traction` nor `traction_field` is given
  double ramp = 0.0;      ///< T [s]: the load is scaled by min(t/T, 1); 0 means no ramp
  std::string pointer;    ///< "/loads/traction/i", for messages

  /// The load factor at a time: min(t/T, 1), or 1 without a ramp.
  double factor(double time) const { return ramp > 0 ? std::min(time / ramp, 1.0) : 1.0; }
};

struct InitialConditions {
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
  std::optional<Eigen::Vector3d> centre;  ///< nullopt: the centre of mass

  /// v + ω × (x − c), with c = centre or else `centre_of_mass`.
  Eigen::Vector3d velocity_at(const Eigen::Vector3d& x, const Eigen::Vector3d& centre_of_mass) const;
};

struct TimeSpec {
  bool is_static = true;
  double dt = 0.0;
  int steps = 0;
  IntegratorKind integrator = IntegratorKind::backward_euler;
  double rayleigh_mass = 0.0;       ///< α of C = α M + β K
  double rayleigh_stiffness = 0.0;  ///< β
  /// Static scenes: equilibria at the load factors k / load_steps, k = 1 … load_steps
  /// (docs/scene-schema.md, "time"); 1 for dynamic scenes.
  int load_steps = 1;
};

enum class EventKind { release, cut, refine };
inline constexpr std::array<std::string_view, 3> event_kind_names{"release", "cut", "refine"};

/// How a refine event splits a marked cell (Kaufmann et al. 2009 §9.3): into 8 by the three
/// coordinate planes through its centroid, or into 2 by the plane through it normal to the
/// principal direction of the largest absolute principal stress.
enum class RefineSplit { eighths, halves };
inline constexpr std::array<std::string_view, 2> refine_split_names{"1to8", "1to2"};

/// What a refine event marks cells by: the largest absolute principal stress (Kaufmann et
/// al. 2009 §9.3, "where the stress is high"), or the jump of the traction across the
/// cell's faces (a Kelly-type indicator, "where the error is").
enum class RefineCriterion { principal_stress, error_indicator };
inline constexpr std::array<std::string_view, 2> refine_criterion_names{"principal_stress", "error_indicator"};

/// A refine event's marking and splitting (docs/scene-schema.md, "Events").
struct RefineSpec {
  RefineCriterion criterion = RefineCriterion::principal_stress;
  /// Marks a cell whose criterion exceeds this [Pa]: the largest absolute principal value of
  /// its mean small-strain stress σ = λ tr(ε) I + 2μ ε, or its traction jump indicator.
  double threshold = 0.0;
  /// Instead of `threshold` (when set, in (0, 1]): bulk marking (Dörfler 1996) — the fewest
  /// cells, largest estimates first, whose squared estimates carry this fraction of their sum
  /// (mark_cells_to_refine).
  std::optional<double> fraction;
  RefineSplit split = RefineSplit::eighths;
  int max_level = 3;                     ///< a cell split this many times is not split again
  std::optional<RegionSelector> region;  ///< only cells whose centroid it holds
};

/// One entry of `events` (docs/scene-schema.md, "events"): something that changes the
/// scene while it runs. It acts at the first step boundary at or after `time` (dynamic
/// scenes: seconds; static scenes: after load step `time`, 0 before the first).
struct SceneEvent {
  double time = 0.0;
  EventKind kind = EventKind::release;
  int condition = -1;            ///< release: the index into Scene::dirichlet
  CuttingPlane blade;            ///< cut: the plane the rest configuration is cut by
  double merge_fraction = 1e-3;  ///< cut: dg and harmonic merge pieces below this fraction of their cell
  RefineSpec refine;             ///< refine: which cells, split how
  std::string pointer;           ///< "/events/i", for messages
};

struct SolverSpec {
  NonlinearSolverKind nonlinear = NonlinearSolverKind::newton;
  double tolerance = 1e-5;  ///< Longva et al. 2020 §6 stopping rule
  int max_iterations = 50;
  bool line_search = true;
  bool project_spd = false;
  LinearSolverKind linear = LinearSolverKind::cholmod;
  std::string preconditioner = "jacobi";  ///< one of preconditioner_names (shared/solve)
  double linear_tolerance = 1e-10;
  int linear_max_iterations = 10000;
  /// `petsc` only: PETSc options, whether the rigid-body modes are its preconditioner's
  /// near-null space, and whether the method's own preconditioner smooths multigrid's
  /// finest level (on one process), and whether GAMG works on the method's first-order
  /// space as a two-level p-multigrid's coarse level (higher-order fem and fcm).
  std::string petsc_options;
  bool rigid_body_modes = true;
  bool method_smoother = true;
  bool p_multigrid = true;
  /// Halvings of a failed implicit step or load step (docs/scene-schema.md, "Solver").
  int cutbacks = 10;
};

struct OutputSpec {
  int every = 1;
  bool surface = true;
  bool volume = true;
};

struct Scene {
  std::filesystem::path file;
  std::string name;
  GeometrySpec geometry;
  /// The scene's materials, at least one: `material`, or the `materials` list, whose
  /// unselected rest takes the first (docs/scene-schema.md, "Material").
  std::vector<MaterialSpec> materials;
  MaterialSpec material;  ///< materials[0]: the material of a scene with one
  std::vector<DirichletCondition> dirichlet;
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
  std::vector<SurfaceTraction> tractions;  ///< `loads.traction`
  /// loads.body_force: force per unit volume f(X, t) (N/m³) at the rest position X; absent: none.
  VectorExpression body_force;
  /// exact_displacement: u(X, t) for the field errors of summary.json; absent: none.
  VectorExpression exact_displacement;
  InitialConditions initial;
  TimeSpec time;
  SolverSpec solver;
  OutputSpec output;
  /// Sorted by time (scene order among equal times).
  std::vector<SceneEvent> events;
  /// The whole scene with defaults filled and paths absolute. Each method's block under
  /// /discretization is resolved by that method (method_scene_block.hpp): load_scene
  /// only checks that every block is an object.
  nlohmann::json resolved;
};

/// Whether an event of `scene` rebuilds the method (a cut or a refinement, not a release):
/// then each build keeps what the next can take from it.
bool events_rebuild(const Scene& scene);

/// Reads, validates and resolves a scene file, and checks that the files it names
/// exist. Throws InputError with a one-line message naming the file and the JSON
/// pointer or line/column.
Scene load_scene(const std::filesystem::path& path);
/// Validates and resolves scene text; `file` names it in messages and anchors
/// relative paths. Reads no other file.
Scene parse_scene(std::string_view text, const std::filesystem::path& file);

}  // namespace altfem
