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
//   - a rebuild on the same mesh locates none;
//   - fcm, a second cut in the background cell of the first: the vertices of the piece it
//     left alone stay, though a piece before theirs among their candidates changed.
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
  if (GetParam() != "harmonic") {
    EXPECT_LT(relocated(simulation->method()), vertices * 3 / 4);
  }
}

// A second cut in the background cell of the first (x = 0.52, then 0.55, both in fcm's
// cell [0.5, 0.6]) changes one of the cell's pieces: the vertices of the other, the far
// side of the first cut included, stay (ElementBasisEvaluator::rejects), as after each
// cut of a pencil's tip, whose cell holds the chips cut off before.
TEST(IncrementalEmbeddingFcm, ASecondCutInTheCellOfTheFirstKeepsTheVerticesOfItsOtherPiece) {
  const Scene scene = load_scene(
      cantilever_cut, {parse_scene_override("events=[{\"time\": 0.02, \"cut\": {\"plane\": {\"point\": [0.55, 0, 0], "
                                            "\"normal\": [1, 0, 0]}}}, {\"time\": 0.03, \"cut\": {\"plane\": "
                                            "{\"point\": [0.52, 0, 0], \"normal\": [1, 0, 0]}}}]")});
  const SceneGeometry geometry = load_scene_geometry(scene);
  const auto simulation = simulate(scene, geometry, "fcm");
  simulation->method().embedded_displacement(simulation->state().displacement);
  simulation->apply(scene.events.at(0));
  const SurfaceMesh first = simulation->method().embedded_surface();
  simulation->method().embedded_displacement(simulation->state().displacement);
  simulation->apply(scene.events.at(1));
  const MethodInstance& method = simulation->method();
  expect_embedding_as_from_scratch(method);
  // Located again: the vertices the second cut added and those of the piece it cut,
  // x in [0.5, 0.55] (at 0.55 the first cut's cap on the near side, read a hair inside
  // it: embedding_offsets); not those of the other piece, the far side of that cap and on.
  const Eigen::Index added = method.embedded_surface().vertices.rows() - first.vertices.rows();
  int in_cut_piece = 0, on_the_far_piece = 0;
  for (Eigen::Index v = 0; v < first.vertices.rows(); ++v) {
    const double x = first.vertices(v, 0), inward = first.embedding_offsets(v, 0);
    const bool near = x < 0.55 - 1e-9 || (x < 0.55 + 1e-9 && inward < 0);
    in_cut_piece += x >= 0.5 - 1e-9 && near;
    on_the_far_piece += x <= 0.6 + 1e-9 && !near;
  }
  ASSERT_GT(on_the_far_piece, 0);
  EXPECT_LE(relocated(method), added + in_cut_piece) << on_the_far_piece << " on the far piece";
}

INSTANTIATE_TEST_SUITE_P(BasisEmbeddings, IncrementalEmbedding, ::testing::Values("fem", "fcm", "harmonic"),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace altfem
