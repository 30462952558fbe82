// Longva et al. 2020 §6.6, Fig. 10, the convergence of the FCM: the L2 error falls at
// the optimal rates, h² for Hex8 and h³ for Hex20, while a voxel (staircase) fem mesh of
// the same grids does not converge at its rate. Two problems, each against Tet10 fem on
// the very tetrahedra the FCM embeds (one polyhedral domain for both, so the rates
// measure the discretizations, not the geometry):
//   - the paper's: static linear elasticity on a half-ball whose flat face lies on a grid
//     plane and is clamped, under a uniform body load (scenes/half_ball.json). The
//     embedded tetrahedra keep the sharp rim (Mesh_3 with the rim protected as a
//     feature): with a rounded rim the FCM, which clamps background nodes on the plane,
//     would also clamp the rounded lip above it and solve another problem there.
//     Where the clamped face meets the free sphere at 90° the solution is singular
//     (an edge between Dirichlet and Neumann parts): measured rates Hex8 1.45, 1.72 and
//     Hex20 1.36, 1.66, limited by it for Hex20 (the paper's "hemisphere-like" geometry
//     is described only in its supplement). The same half-ball with a smooth
//     manufactured solution (scenes/manufactured_half_ball.json, tested in
//     tests/verify/manufactured) has no singularity and shows the optimal rates 2 and 3;
//   - one backward-Euler step of a free ball set in motion by a smooth non-affine
//     velocity, (M/Δt² + K) u = M v₀/Δt (scenes/ball.json): no boundary condition at all.
// Prints the tables.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "fcm/embedded_mesh.hpp"
#include "fcm/fcm_scene_block.hpp"
#include "shared/cut_cells/intersection_cell_quadrature.hpp"
#include "shared/fem/lagrange_basis_evaluator.hpp"
#include "shared/fem/lagrange_discretization.hpp"
#include "shared/material/material.hpp"
#include "shared/mesh/elevate_order.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/simulation/basis_embedding.hpp"
#include "shared/solve/linear_solver.hpp"
#include "shared/solve/time_integrator.hpp"

namespace altfem::fcm {
namespace {

// v₀(x) = 0.01 (y z, x², x y): smooth, not affine, with no rigid part.
Eigen::Vector3d initial_velocity(const Eigen::Vector3d& x) {
  return 0.01 * Eigen::Vector3d(x.y() * x.z(), x.x() * x.x(), x.x() * x.y());
}

// A static scene: the equilibrium under its gravity. Otherwise one backward-Euler step of
// Δt = 1 s from rest position with nodal velocities v₀: Δt² K / M ~ E Δt² / (ρ R²) = 100,
// so elasticity shapes the solution.
Eigen::VectorXd solve(const Scene& scene, const Discretization& discretization, const Eigen::MatrixXd& nodes) {
  IntegratorOptions options;
  options.kind = scene.time.is_static ? IntegrationScheme::static_equilibrium : IntegrationScheme::backward_euler;
  options.gravity = scene.gravity;
  options.time_step = 1.0;
  options.tolerance = 1e-10;
  const auto solver = make_linear_solver(LinearSolverOptions{});
  TimeIntegrator integrator(discretization, *solver, options);
  State state;
  state.displacement = Eigen::VectorXd::Zero(discretization.dof_count());
  state.velocity = Eigen::VectorXd::Zero(discretization.dof_count());
  if (!scene.time.is_static)
    for (Eigen::Index node = 0; node < nodes.rows(); ++node)
      state.velocity.segment<3>(3 * node) = initial_velocity(nodes.row(node).transpose());
  integrator.apply_constraints(state);
  integrator.step(state);  // throws NumericalError if Newton fails
  return state.displacement;
}

// The reference's quadrature points, weights and displacement there.
struct ReferenceField {
  Eigen::MatrixXd points;  ///< #points × 3
  Eigen::VectorXd weights;
  Eigen::MatrixXd displacement;  ///< #points × 3
  double norm = 0;               ///< ‖u‖_L2
};

ReferenceField reference_field(const VolumeMesh& mesh, const TabulatedElements& elements, const Eigen::VectorXd& u) {
  ReferenceField field;
  const auto count = static_cast<Eigen::Index>(elements.point_count());
  field.points.resize(count, 3);
  field.weights.resize(count);
  field.displacement.resize(count, 3);
  Eigen::Index row = 0;
  for (int e = 0; e < elements.size(); ++e) {
    const ElementView element = elements[e];
    for (int q = 0; q < element.point_count(); ++q, ++row) {
      Eigen::Vector3d x = Eigen::Vector3d::Zero(), value = Eigen::Vector3d::Zero();
      for (int a = 0; a < element.basis_count(); ++a) {
        x += element.values(q, a) * mesh.nodes.row(element.basis[a]).transpose();
        value += element.values(q, a) * u.segment<3>(3 * element.basis[a]);
      }
      field.points.row(row) = x.transpose();
      field.weights[row] = element.weights[q];
      field.displacement.row(row) = value.transpose();
    }
  }
  field.norm = std::sqrt((field.weights.asDiagonal() * field.displacement.rowwise().squaredNorm()).sum());
  return field;
}

// ‖u_h − u_ref‖_L2 / ‖u_ref‖_L2 at the reference's quadrature points.
double relative_error(const ReferenceField& reference, const VolumeMesh& mesh, const Eigen::VectorXd& u) {
  const LagrangeBasisEvaluator evaluator(mesh);
  const BasisEmbedding embedding(evaluator, reference.points);
  const Eigen::MatrixXd difference = embedding.displacement(u) - reference.displacement;
  return std::sqrt((reference.weights.asDiagonal() * difference.rowwise().squaredNorm()).sum()) / reference.norm;
}

struct Row {
  double h;
  int dofs;
  double error;
};

void print(const char* title, const std::vector<Row>& rows) {
  std::printf("%s\n  %8s %8s %12s %6s\n", title, "h", "DOFs", "L2 error", "rate");
  for (size_t i = 0; i < rows.size(); ++i) {
    if (i == 0) std::printf("  %8.4f %8d %12.4e %6s\n", rows[i].h, rows[i].dofs, rows[i].error, "");
    else
      std::printf("  %8.4f %8d %12.4e %6.2f\n", rows[i].h, rows[i].dofs, rows[i].error,
                  std::log(rows[i - 1].error / rows[i].error) / std::log(rows[i - 1].h / rows[i].h));
  }
}

double mean_rate(const std::vector<Row>& rows) {
  return std::log(rows.front().error / rows.back().error) / std::log(rows.front().h / rows.back().h);
}

double last_rate(const std::vector<Row>& rows) {
  const Row& a = rows[rows.size() - 2];
  const Row& b = rows.back();
  return std::log(a.error / b.error) / std::log(a.h / b.h);
}

// Grid cells of size h = (longest side of the bounds) / n, as many as fit each side.
Eigen::Vector3i resolution(const Eigen::AlignedBox3d& bounds, int n) {
  const double h = bounds.sizes().maxCoeff() / n;
  return (bounds.sizes() / h).array().round().cast<int>().max(1);
}

// The study of one scene file (tests/verify/fcm/scenes/<name>.json).
template <const char* name>
class Convergence : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    scene_ = new Scene(load_scene(std::string(ALTFEM_SOURCE_DIR "/tests/verify/fcm/scenes/") + name + ".json"));
    geometry_ = new SceneGeometry(load_scene_geometry(*scene_));
    const MaterialSpec& spec = scene_->material;
    material_ =
        make_material(*material_model_from_name(spec.model), spec.youngs_modulus, spec.poisson_ratio, spec.density)
            .release();
    const double size = scene_->resolved["discretization"]["fcm"]["embedded_cell_size"].get<double>();
    embedded_ = new VolumeMesh(embedded_tetrahedra(*geometry_, size, name));
    reference_mesh_ = new VolumeMesh(elevate_order(*embedded_, ElementType::tet10));
    const auto reference = make_lagrange_discretization(*reference_mesh_, *material_, scene_->dirichlet, 6);
    reference_ = new ReferenceField(
        reference_field(*reference_mesh_, reference->elements(), solve(*scene_, *reference, reference_mesh_->nodes)));
    std::printf("reference: Tet10 fem, %lld DOFs, %lld quadrature points\n",
                static_cast<long long>(3 * reference_mesh_->nodes.rows()),
                static_cast<long long>(reference_->weights.size()));
  }
  static void TearDownTestSuite() {
    delete reference_;
    delete reference_mesh_;
    delete embedded_;
    delete material_;
    delete geometry_;
    delete scene_;
  }

  // FCM with `cell` on the grid of resolution(bounds, n), with the scene block's (the
  // authors') quadrature options; ghost_penalty > 0 replaces the quadrature
  // stabilisation by the face ghost penalty with that γ.
  static Row fcm_row(const std::string& cell, int n, double ghost_penalty = 0) {
    Scene scene = *scene_;
    scene.resolved["discretization"]["fcm"]["cell"] = cell;
    if (ghost_penalty > 0) {
      scene.resolved["discretization"]["fcm"]["ghost_penalty"] = ghost_penalty;
      scene.resolved["discretization"]["fcm"]["stabilization"] = 0.0;
    }
    const FcmSpec spec = fcm_spec(scene);
    const VolumeMesh background = structured_grid(geometry_->bounds, resolution(geometry_->bounds, n), spec.cell);
    const CellQuadratureSource rules =
        intersection_cell_quadrature(background, *embedded_, spec.simplifier, spec.simplification_tolerance);
    const FcmDiscretization fcm =
        build_fcm_discretization(background, rules, *material_, scene.dirichlet, spec.options);
    const Eigen::VectorXd u = solve(*scene_, *fcm.discretization, fcm.mesh.nodes);
    return {h(n), fcm.discretization->dof_count(), relative_error(*reference_, fcm.mesh, u)};
  }

  // fem on the voxels of the same grid: the Hex8 cells whose centre is inside.
  static Row voxel_row(int n) {
    const Eigen::AlignedBox3d box = geometry_->bounds;
    const VolumeMesh grid = structured_grid(box, resolution(box, n), ElementType::hex8);
    std::vector<int> inside;
    for (Eigen::Index c = 0; c < grid.cells.rows(); ++c) {
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      for (int a = 0; a < 8; ++a) centre += grid.nodes.row(grid.cells(c, a)).transpose() / 8;
      if (geometry_->shape->level_set(centre) < 0) inside.push_back(static_cast<int>(c));
    }
    VolumeMesh voxels{ElementType::hex8, grid.nodes, Eigen::MatrixXi(inside.size(), 8)};
    for (size_t i = 0; i < inside.size(); ++i)
      voxels.cells.row(static_cast<Eigen::Index>(i)) = grid.cells.row(inside[i]);
    // Unused grid nodes carry no element: give them to no DOF by compacting.
    std::vector<int> index(grid.nodes.rows(), -1);
    int used = 0;
    for (Eigen::Index c = 0; c < voxels.cells.rows(); ++c)
      for (int a = 0; a < 8; ++a)
        if (index[voxels.cells(c, a)] < 0) index[voxels.cells(c, a)] = used++;
    Eigen::MatrixXd nodes(used, 3);
    for (Eigen::Index node = 0; node < grid.nodes.rows(); ++node)
      if (index[node] >= 0) nodes.row(index[node]) = grid.nodes.row(node);
    for (Eigen::Index c = 0; c < voxels.cells.rows(); ++c)
      for (int a = 0; a < 8; ++a) voxels.cells(c, a) = index[voxels.cells(c, a)];
    voxels.nodes = nodes;
    const auto discretization = make_lagrange_discretization(voxels, *material_, scene_->dirichlet, 2);
    const Eigen::VectorXd u = solve(*scene_, *discretization, voxels.nodes);
    return {h(n), discretization->dof_count(), relative_error(*reference_, voxels, u)};
  }

  static double h(int n) { return geometry_->bounds.sizes().maxCoeff() / n; }

  // The FCM rows of `cell` on the grids n, printed under `title`.
  static std::vector<Row> fcm_study(const std::string& cell, const std::vector<int>& sizes, const std::string& title) {
    std::vector<Row> rows;
    for (int n : sizes) rows.push_back(fcm_row(cell, n));
    print(title.c_str(), rows);
    return rows;
  }

  // The voxel fem rows on the grids n = 4 … 32, printed under `title` with their mean rate.
  static std::vector<Row> voxel_study(const std::string& title) {
    std::vector<Row> rows;
    for (int n : {4, 8, 16, 32}) rows.push_back(voxel_row(n));
    print(title.c_str(), rows);
    std::printf("mean rate %.2f\n", mean_rate(rows));
    return rows;
  }

  // The face ghost penalty in place of the stabilisation (γ = 0.01, the conditioning
  // command's default) is consistent: it vanishes on polynomials of the cell's degree, so
  // the rates stay optimal. Its weak inconsistency for smooth non-polynomial fields costs
  // accuracy on Hex20 (measured at h = 1/4: 1.45× the stabilised run's error at γ = 0.01,
  // 6× at γ = 0.1, none at 0.001; Hex8 unchanged): the bound 2× on the finest grid guards
  // that trade. `stabilised` is the stabilised run on the finest of `sizes`.
  static void expect_ghost_penalty_keeps_the_rate_within_twice_the_error(const std::string& cell,
                                                                         const std::vector<int>& sizes, double rate,
                                                                         const Row& stabilised) {
    std::vector<Row> rows;
    for (int n : sizes) rows.push_back(fcm_row(cell, n, 0.01));
    print((cell + " FCM, ghost penalty 0.01, no stabilisation").c_str(), rows);
    EXPECT_GE(last_rate(rows), rate);
    std::printf("%s FCM at h = %.4f: L2 error %.4e with the ghost penalty 0.01, %.4e with stabilisation 1e-6\n",
                cell.c_str(), rows.back().h, rows.back().error, stabilised.error);
    EXPECT_LT(rows.back().error, 2 * stabilised.error);
  }

  static Scene* scene_;
  static SceneGeometry* geometry_;
  static Material* material_;
  static VolumeMesh* embedded_;
  static VolumeMesh* reference_mesh_;
  static ReferenceField* reference_;
};

template <const char* name>
Scene* Convergence<name>::scene_ = nullptr;
template <const char* name>
SceneGeometry* Convergence<name>::geometry_ = nullptr;
template <const char* name>
Material* Convergence<name>::material_ = nullptr;
template <const char* name>
VolumeMesh* Convergence<name>::embedded_ = nullptr;
template <const char* name>
VolumeMesh* Convergence<name>::reference_mesh_ = nullptr;
template <const char* name>
ReferenceField* Convergence<name>::reference_ = nullptr;

constexpr char half_ball[] = "half_ball";
constexpr char ball[] = "ball";
using ClampedHalfBall = Convergence<half_ball>;
using FreeBall = Convergence<ball>;

TEST_F(ClampedHalfBall, Hex8FcmConvergesTowardsRateTwo) {
  EXPECT_GE(last_rate(fcm_study("hex8", {4, 8, 16}, "Hex8 FCM, clamped half-ball")), 1.6);
}

// The rim singularity caps Hex20's rate; it still beats Hex8 at equal h by far.
TEST_F(ClampedHalfBall, Hex20FcmIsFarMoreAccurateThanHex8) {
  const std::vector<Row> rows = fcm_study("hex20", {2, 4, 8}, "Hex20 FCM, clamped half-ball");
  EXPECT_GE(last_rate(rows), 1.5);
  EXPECT_LT(5 * rows.back().error, fcm_row("hex8", 8).error);  // h = 1/4
}

TEST_F(ClampedHalfBall, VoxelFemStallsNearRateOne) {
  const std::vector<Row> rows = voxel_study("Hex8 voxel fem, clamped half-ball");
  EXPECT_LT(mean_rate(rows), 1.5);
  EXPECT_GT(rows[2].error, 1.5 * fcm_row("hex8", 16).error);  // h = 1/8
}

// Each process computes the reference again (ctest runs every test on its own), so the
// Hex8 claims share one test; the Hex20 runs are split in two, each under 20 s.
TEST_F(FreeBall, Hex8FcmConvergesAtRateTwoStabilisedOrWithTheGhostPenalty) {
  const std::vector<Row> stabilised = fcm_study("hex8", {4, 8, 16}, "Hex8 FCM");
  EXPECT_GE(last_rate(stabilised), 1.8);
  expect_ghost_penalty_keeps_the_rate_within_twice_the_error("hex8", {4, 8, 16}, 1.8, stabilised.back());
}

TEST_F(FreeBall, Hex20FcmConvergesAtRateThree) {
  EXPECT_GE(last_rate(fcm_study("hex20", {2, 4, 8}, "Hex20 FCM")), 2.6);
}

TEST_F(FreeBall, GhostPenaltyKeepsTheHex20RateWithinTwiceTheStabilisedError) {
  expect_ghost_penalty_keeps_the_rate_within_twice_the_error("hex20", {2, 4, 8}, 2.6, fcm_row("hex20", 8));
}

// The staircase boundary moves by O(h) with every refinement: the error falls
// erratically, at about rate 1 on average instead of 2, and stays well above the FCM's.
TEST_F(FreeBall, VoxelFemStallsNearRateOne) {
  const std::vector<Row> rows = voxel_study("Hex8 voxel fem");
  EXPECT_LT(mean_rate(rows), 1.5);
  EXPECT_GT(rows[2].error, 2 * fcm_row("hex8", 16).error);  // h = 1/8
}

}  // namespace
}  // namespace altfem::fcm
