// The surface's embedding after an event keeps the vertices of the elements the event
// left alone and locates only the others (BasisEmbedding's constructor with `previous`,
// docs/architecture.md, "Events"). With fem, fcm and harmonic, after a cut of the 10-cell
// cantilever at x = 0.55 and after a refinement of its clamped half:
//   - the surface deforms exactly as with an embedding built from scratch in the new
//     basis, bit for bit, for any coefficients;
//   - fem and fcm locate again only the vertices the cut added and those of the cells it
//     crossed (under a quarter of the surface's vertices, the summary's
//     facts.surface.vertices_relocated of the event), and after the refinement those of
//     the split half; harmonic keeps fewer: the cut polyhedral mesh lists the faces of some
//     cells it did not cross in another order, which orders their closed-form hexahedra's
//     nodes otherwise (plain_cells.hpp), and the refined mesh every cell's;
//   - a rebuild on the same mesh locates none.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "app/method_registry.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/scene/scene_override.hpp"
#include "shared/simulation/simulation.hpp"
#include "tests/verify/events/refine_checks.hpp"

namespace altfem {
namespace {

const std::filesystem::path cantilever_cut =
    std::filesystem::path(ALTFEM_SOURCE_DIR) / "tests/verify/events/scenes/cantilever_cut.json";

std::unique_ptr<Simulation> simulate(const Scene& scene, const SceneGeometry& geometry, const std::string& name) {
  const MethodDescription& method = cli::find_method(name);
  return std::make_unique<Simulation>(scene, geometry, name, method.factory, method.rebuild);
}

// The method's surface displacement for random coefficients, against an embedding of the
// same vertices built from scratch in its basis.
void expect_embedding_as_from_scratch(const MethodInstance& method) {
  const Eigen::VectorXd u = Eigen::VectorXd::Random(method.discretization().dof_count());
  const Eigen::MatrixXd kept = method.embedded_displacement(u);
  const BasisEmbedding scratch(method.basis_evaluator(), embedding_points(method.embedded_surface()));
  const Eigen::MatrixXd fresh = scratch.displacement(u);
  ASSERT_EQ(kept.rows(), fresh.rows());
  EXPECT_EQ((kept - fresh).cwiseAbs().maxCoeff(), 0.0);
}

int relocated(const MethodInstance& method) { return method.facts()["surface_vertices_relocated"].get<int>(); }

class IncrementalEmbedding : public ::testing::TestWithParam<std::string> {};

TEST_P(IncrementalEmbedding, AfterACutIsTheEmbeddingFromScratchAndLocatesFewVertices) {
  const Scene scene = load_scene(cantilever_cut);
  const SceneGeometry geometry = load_scene_geometry(scene);
  const auto simulation = simulate(scene, geometry, GetParam());
  for (int step = 0; step < 5; ++step) simulation->integrator().step(simulation->state());
  // Embedded before the cut, as a surface frame would have.
  const Eigen::Index before = simulation->method().embedded_displacement(simulation->state().displacement).rows();
  EXPECT_EQ(relocated(simulation->method()), before);

  simulation->apply(scene.events.at(0));
  const MethodInstance& method = simulation->method();
  expect_embedding_as_from_scratch(method);
  const Eigen::Index vertices = method.embedded_surface().vertices.rows();
  ASSERT_GT(vertices, before);
  // The vertices the cut added, and those of the cells it crossed, and hardly more.
  EXPECT_GE(relocated(method), vertices - before);
  EXPECT_LT(relocated(method), GetParam() == "harmonic" ? vertices * 2 / 3 : vertices / 4) << "of " << vertices;

  // A rebuild on the same mesh leaves every element alone.
  simulation->rebuild();
  expect_embedding_as_from_scratch(simulation->method());
  EXPECT_EQ(relocated(simulation->method()), 0);
}

TEST_P(IncrementalEmbedding, AfterARefinementIsTheEmbeddingFromScratch) {
  std::vector<SceneOverride> overrides{clamp_half};
  if (GetParam() == "fcm")
    overrides.push_back(
        parse_scene_override("discretization/fcm={\"cell\": \"hex8\", \"resolution\": [10, 2, 2], \"margin\": 0.05}"));
  const Scene scene = load_scene(cantilever_refine_scene, overrides);
  const SceneGeometry geometry = load_scene_geometry(scene);
  const auto simulation = simulate(scene, geometry, GetParam());
  simulation->state().displacement = simulation->method().interpolate(patch_field);
  const Eigen::Index vertices = simulation->method().embedded_displacement(simulation->state().displacement).rows();

  const EventRecord record = simulation->apply(scene.events.at(0));
  ASSERT_GT(record.dofs_after, record.dofs_before);
  expect_embedding_as_from_scratch(simulation->method());
  EXPECT_GT(relocated(simulation->method()), 0);
  // The unsplit half keeps the vertices of its cells that hold no hanging node.
  if (GetParam() != "harmonic") EXPECT_LT(relocated(simulation->method()), vertices * 3 / 4);
}

INSTANTIATE_TEST_SUITE_P(BasisEmbeddings, IncrementalEmbedding, ::testing::Values("fem", "fcm", "harmonic"),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace altfem
