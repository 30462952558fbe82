// The three embeddings of the dg method (Kaufmann et al. 2009 §7) on a 3 × 3 × 3 grid of
// hexahedra and of tetrahedra, degree 2: each reproduces an affine displacement at
// arbitrary points (MLS by its linear completeness, eq. (31); stitching because nodal
// averages of a continuous field are its nodal values, eq. (30)). For a discontinuous
// field (random coefficients per element) the per-element evaluation jumps across every
// interior face, while MLS and stitching are continuous: at points ±ε on either side of
// the faces their difference is O(ε). Prints the jumps.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "dg/monomial_basis_evaluator.hpp"
#include "dg/polyhedral_mesh_faces.hpp"
#include "shared/fem/lagrange_basis_evaluator.hpp"
#include "shared/mesh/cut_polyhedral_mesh.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/simulation/mls_embedding.hpp"
#include "shared/simulation/stitched_embedding.hpp"

namespace altfem::dg {
namespace {

struct Embeddings {
  VolumeMesh volume;
  PolyhedralMesh mesh;
  std::unique_ptr<DgLinearSystem> system;
  std::unique_ptr<MonomialBasisEvaluator> evaluator;
  std::unique_ptr<LagrangeBasisEvaluator> lagrange;
  std::unique_ptr<BasisEmbedding> element;
  std::unique_ptr<StitchedEmbedding> stitched;
  std::unique_ptr<MlsEmbedding> mls;

  Embeddings(ElementType type, const Eigen::MatrixXd& points) {
    volume = structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()), {3, 3, 3}, type);
    mesh = polyhedral_mesh_from_volume_mesh(volume);
    system = std::make_unique<DgLinearSystem>(mesh_cells(mesh), mesh_faces(mesh), DgSettings{});
    evaluator = std::make_unique<MonomialBasisEvaluator>(mesh, *system);
    lagrange = std::make_unique<LagrangeBasisEvaluator>(volume);
    element = std::make_unique<BasisEmbedding>(*evaluator, points);
    stitched = std::make_unique<StitchedEmbedding>(*evaluator, volume.nodes, *lagrange, points);
    mls = std::make_unique<MlsEmbedding>(*evaluator, mesh.nodes, longest_edge_at_nodes(mesh), points);
  }
};

Eigen::MatrixXd random_points(int count) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Eigen::MatrixXd points(count, 3);
  for (int p = 0; p < count; ++p) points.row(p) << unit(random), unit(random), unit(random);
  points.row(0) << 0, 0, 0;  // a corner, an edge and a face point of the box too
  points.row(1) << 1, 0.5, 0;
  points.row(2) << 0.3, 1, 0.7;
  return points;
}

TEST(DgEmbedding, EveryEmbeddingReproducesAnAffineDisplacement) {
  const Eigen::MatrixXd points = random_points(200);
  Eigen::Matrix3d gradient;
  gradient << 0.3, -0.2, 0.5, 0.1, 0.4, -0.3, -0.6, 0.2, 0.1;
  const Eigen::RowVector3d shift(1.0, -2.0, 0.5);
  const Eigen::MatrixXd exact = (points * gradient.transpose()).rowwise() + shift;
  for (ElementType type : {ElementType::hex8, ElementType::tet4}) {
    const Embeddings embeddings(type, points);
    const Eigen::VectorXd u = embeddings.system->interpolate(
        [&](const Eigen::Vector3d& x) { return (gradient * x + shift.transpose()).eval(); });
    const double scale = exact.cwiseAbs().maxCoeff();
    EXPECT_LE((embeddings.element->displacement(u) - exact).cwiseAbs().maxCoeff(), 1e-12 * scale);
    EXPECT_LE((embeddings.stitched->displacement(u) - exact).cwiseAbs().maxCoeff(), 1e-12 * scale);
    EXPECT_LE((embeddings.mls->displacement(u) - exact).cwiseAbs().maxCoeff(), 1e-12 * scale);
  }
}

TEST(DgEmbedding, MlsAndStitchingAreContinuousAcrossElementFacesPerElementEvaluationIsNot) {
  constexpr double epsilon = 1e-7;
  std::printf("  %-6s %14s %14s %14s   (max |u(x+εn) − u(x−εn)| at interior face centroids, ε = %g)\n", "mesh",
              "element", "stitched", "mls", epsilon);
  for (ElementType type : {ElementType::hex8, ElementType::tet4}) {
    // Points on both sides of every interior face's centroid.
    const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(
        structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()), {3, 3, 3}, type));
    std::vector<Eigen::RowVector3d> pairs;
    for (int f = 0; f < mesh.face_count(); ++f)
      if (!mesh.is_boundary_face(f)) {
        pairs.push_back(mesh.face_centroids.row(f) + epsilon * mesh.face_normals.row(f));
        pairs.push_back(mesh.face_centroids.row(f) - epsilon * mesh.face_normals.row(f));
      }
    Eigen::MatrixXd points(static_cast<Eigen::Index>(pairs.size()), 3);
    for (size_t p = 0; p < pairs.size(); ++p) points.row(static_cast<Eigen::Index>(p)) = pairs[p];
    const Embeddings embeddings(type, points);
    std::mt19937 random(11);
    std::uniform_real_distribution<double> coefficient(-1.0, 1.0);
    Eigen::VectorXd u(embeddings.system->dof_count());
    for (Eigen::Index i = 0; i < u.size(); ++i) u[i] = coefficient(random);
    double jumps[3] = {0, 0, 0};
    const Eigen::MatrixXd displacements[3] = {embeddings.element->displacement(u), embeddings.stitched->displacement(u),
                                              embeddings.mls->displacement(u)};
    for (int kind = 0; kind < 3; ++kind)
      for (Eigen::Index p = 0; p < points.rows(); p += 2)
        jumps[kind] = std::max(jumps[kind], (displacements[kind].row(p) - displacements[kind].row(p + 1)).norm());
    std::printf("  %-6s %14.3e %14.3e %14.3e\n", type == ElementType::hex8 ? "hex8" : "tet4", jumps[0], jumps[1],
                jumps[2]);
    EXPECT_GT(jumps[0], 0.1);
    EXPECT_LT(jumps[1], 1e4 * epsilon);
    EXPECT_LT(jumps[2], 1e4 * epsilon);
  }
}

// A cut along the faces x = 1/3 (cut_polyhedral_mesh) separates the sides: each side's
// nodes on the blade are copies of their own, and with the cells holding each node as
// its sample elements the MLS embedding stitches and interpolates each side from its own
// samples only, so one side at rest and the other moved rigidly are each reproduced
// exactly up to the blade. By the samples' positions (no sample elements), the copies on
// the blade averaged both sides and blurred 391 of these points.
TEST(DgEmbedding, MlsKeepsTheSidesOfACutApart) {
  const VolumeMesh volume = structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()),
                                            {3, 3, 3}, ElementType::hex8);
  const CuttingPlane blade{Eigen::Vector3d(1.0 / 3.0, 0, 0), Eigen::Vector3d::UnitX()};
  const PolyhedralMesh mesh = cut_polyhedral_mesh(polyhedral_mesh_from_volume_mesh(volume), blade).mesh;
  const DgLinearSystem system(mesh_cells(mesh), mesh_faces(mesh), DgSettings{});
  const MonomialBasisEvaluator evaluator(mesh, system);
  const Eigen::MatrixXd points = random_points(400);
  const auto beyond = [](const Eigen::Vector3d& x) { return x.x() > 1.0 / 3.0; };
  const Eigen::VectorXd u = system.interpolate([&](const Eigen::Vector3d& x) -> Eigen::Vector3d {
    return beyond(x) ? Eigen::Vector3d(0.1, -0.2, -1.0) : Eigen::Vector3d::Zero();
  });
  const MlsEmbedding mls(evaluator, mesh.nodes, longest_edge_at_nodes(mesh), points, MlsOptions{},
                         cells_at_nodes(mesh));
  const Eigen::MatrixXd displacement = mls.displacement(u);
  int checked = 0;
  for (Eigen::Index p = 0; p < points.rows(); ++p) {
    if (std::abs(points(p, 0) - 1.0 / 3.0) < 1e-6) continue;
    const Eigen::RowVector3d expected =
        beyond(points.row(p).transpose()) ? Eigen::RowVector3d(0.1, -0.2, -1.0) : Eigen::RowVector3d::Zero();
    EXPECT_LE((displacement.row(p) - expected).cwiseAbs().maxCoeff(), 1e-12) << "point " << points.row(p);
    ++checked;
  }
  EXPECT_GT(checked, 390);
}

// After a second cut (x = 0.8) that leaves the slab x < 1/3 alone, the MLS embedding built
// from the one before keeps the weights of the slab's points, on its samples' new indices,
// and computes only the others': its displacement of a field discontinuous across every
// face is the embedding's built afresh, to rounding.
TEST(DgEmbedding, MlsAfterACutKeepsTheWeightsOfThePiecesItLeftAlone) {
  const VolumeMesh volume = structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()),
                                            {3, 3, 3}, ElementType::hex8);
  const PolyhedralMesh before = cut_polyhedral_mesh(polyhedral_mesh_from_volume_mesh(volume),
                                                    {Eigen::Vector3d(1.0 / 3.0, 0, 0), Eigen::Vector3d::UnitX()})
                                    .mesh;
  const PolyhedralMesh after = cut_polyhedral_mesh(before, {Eigen::Vector3d(0.8, 0, 0), Eigen::Vector3d::UnitX()}).mesh;
  const Eigen::MatrixXd points = random_points(400);
  const DgLinearSystem system_before(mesh_cells(before), mesh_faces(before), DgSettings{});
  const MonomialBasisEvaluator evaluator_before(before, system_before);
  const MlsEmbedding first(evaluator_before, before.nodes, longest_edge_at_nodes(before), points, MlsOptions{},
                           cells_at_nodes(before));
  const DgLinearSystem system(mesh_cells(after), mesh_faces(after), DgSettings{});
  const MonomialBasisEvaluator evaluator(after, system);
  const MlsEmbedding fresh(evaluator, after.nodes, longest_edge_at_nodes(after), points, MlsOptions{},
                           cells_at_nodes(after));
  const MlsEmbedding kept(evaluator, after.nodes, longest_edge_at_nodes(after), points, MlsOptions{},
                          cells_at_nodes(after), &first);
  int beyond = 0;
  for (Eigen::Index p = 0; p < points.rows(); ++p) beyond += points(p, 0) > 1.0 / 3.0;
  EXPECT_EQ(fresh.facts()["surface_vertices_relocated"], points.rows());
  EXPECT_EQ(kept.facts()["surface_vertices_relocated"], beyond);
  EXPECT_LT(beyond, points.rows() - 100);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coefficient(-1.0, 1.0);
  const Eigen::VectorXd u = Eigen::VectorXd::NullaryExpr(system.dof_count(), [&] { return coefficient(random); });
  EXPECT_LE((kept.displacement(u) - fresh.displacement(u)).cwiseAbs().maxCoeff(), 1e-13);
}

}  // namespace
}  // namespace altfem::dg
