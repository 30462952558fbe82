// Topology-aware cells end to end (issue 17): two parallel bars 0.2 apart share a row of
// background cells but no material. Their ends are moved apart (the lower bar by −δ, the
// upper by +δ along y), so the exact solution translates each bar rigidly and opens the
// gap by 2δ. With one DOF copy per piece the discrete solution is that translation;
// with shared DOFs the cells the bars share glue them together and bend both. The
// end regions hold the nodes of the cells both bars cross, so the test also needs each
// region to select only the copies of its own bar (piece_dirichlet), and each surface
// vertex to be embedded in its own bar's piece (piece_basis_evaluator): without either,
// the topology-aware error is 0.73 δ or 2 δ.
#include <gtest/gtest.h>

#include <filesystem>

#include "fcm/fcm_method.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/solve/linear_solver.hpp"
#include "shared/solve/time_integrator.hpp"

namespace altfem::fcm {
namespace {

const std::filesystem::path scene_file =
    std::filesystem::path(ALTFEM_SOURCE_DIR) / "tests/unit/fcm/scenes/two_bars.json";
constexpr double delta = 0.01;  // the scene's end displacement
constexpr double gap_middle = 1.1;

struct BarsRun {
  nlohmann::json facts;
  Eigen::VectorXd pieces;  ///< the volume output's `piece` per kept cell
  double worst_error = 0;  ///< max over surface vertices of |u − (0, ∓δ, 0)| / δ
};

BarsRun run_two_bars(bool topology_aware) {
  Scene scene = load_scene(scene_file);
  scene.resolved["discretization"]["fcm"]["topology_aware"] = topology_aware;
  const SceneGeometry geometry = load_scene_geometry(scene);
  const auto method = make_fcm_method(scene, geometry);
  const Discretization& discretization = method->discretization();
  const auto solver = make_linear_solver(LinearSolverOptions{});
  IntegratorOptions options;
  options.tolerance = 1e-12;
  TimeIntegrator integrator(discretization, *solver, options);
  State state;
  state.time = 1.0;  // the end of the conditions' duration: the full displacement
  state.displacement = Eigen::VectorXd::Zero(discretization.dof_count());
  state.velocity = state.displacement;
  integrator.step(state);

  BarsRun run{method->facts(), {}, 0.0};
  for (const auto& [name, values] : method->volume_grid(state.displacement).cell_data)
    if (name == "piece") run.pieces = values.col(0);
  const Eigen::MatrixXd displacement = method->embedded_displacement(state.displacement);
  const Eigen::MatrixXd& vertices = method->embedded_surface().vertices;
  for (Eigen::Index v = 0; v < vertices.rows(); ++v) {
    const Eigen::Vector3d exact(0, vertices(v, 1) < gap_middle ? -delta : delta, 0);
    run.worst_error = std::max(run.worst_error, (displacement.row(v).transpose() - exact).norm() / delta);
  }
  return run;
}

TEST(TopologyAwareCells, TwoBarsSharingCellsSeparateAsTheExactSolution) {
  const BarsRun separate = run_two_bars(true);
  EXPECT_EQ(separate.facts["cells"]["split"].get<int>(), 4);  // the middle row of the 4 × 3 × 1 grid
  EXPECT_LT(separate.worst_error, 1e-8);
  // 4 × 3 grid cells, the 4 middle ones in two pieces: 16 kept cells, 4 of them piece 1.
  ASSERT_EQ(separate.pieces.size(), 16);
  EXPECT_EQ(separate.pieces.sum(), 4);
  const BarsRun glued = run_two_bars(false);
  EXPECT_EQ(glued.facts["cells"]["split"].get<int>(), 0);
  EXPECT_GT(glued.worst_error, 0.1);
  EXPECT_EQ(glued.pieces.size(), 12);
  EXPECT_EQ(glued.pieces.sum(), 0);
  std::printf("two bars, worst |u - exact| / delta: topology-aware %.3e, shared DOFs %.3e\n", separate.worst_error,
              glued.worst_error);
}

}  // namespace
}  // namespace altfem::fcm
