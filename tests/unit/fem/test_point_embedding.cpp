// BasisEmbedding over a Lagrange mesh reproduces an affine displacement at random interior points of
// distorted meshes (the basis reproduces affine fields; the inverse map must find
// the right cell and reference point).
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>

#include <cmath>
#include <random>

#include "shared/element/geometry_map.hpp"
#include "shared/fem/lagrange_basis_evaluator.hpp"
#include "shared/simulation/basis_embedding.hpp"
#include "shared/simulation/embedded_surface.hpp"
#include "tests/unit/fem/test_meshes.hpp"

namespace altfem {
namespace {

// `count` points x_p = x_cell(ξ_p) at random reference points of random cells (#points × 3).
Eigen::MatrixXd random_interior_points(const VolumeMesh& mesh, int count, unsigned seed) {
  const ReferenceElement& element = reference_element(mesh.element_type);
  const bool tet = element.shape() == ElementShape::tetrahedron;
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> pick_cell(0, static_cast<int>(mesh.cells.rows()) - 1);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  Eigen::MatrixXd points(count, 3);
  Eigen::MatrixXd cell_nodes(element.node_count(), 3);
  for (int p = 0; p < count; ++p) {
    const int cell = pick_cell(random);
    for (int a = 0; a < element.node_count(); ++a) cell_nodes.row(a) = mesh.nodes.row(mesh.cells(cell, a));
    Eigen::Vector3d xi;
    if (tet) {
      // Uniform barycentric coordinates, kept 1% away from the faces.
      Eigen::Vector4d b;
      for (int i = 0; i < 4; ++i) b[i] = 0.01 - std::log(1.0 - uniform(random));
      xi = b.head<3>() / b.sum();
    } else {
      for (int i = 0; i < 3; ++i) xi[i] = 1.98 * uniform(random) - 0.99;
    }
    points.row(p) = map_to_physical(element, cell_nodes, xi).transpose();
  }
  return points;
}

class EmbeddingOfType : public ::testing::TestWithParam<ElementType> {};

TEST_P(EmbeddingOfType, ReproducesAnAffineDisplacement) {
  const VolumeMesh mesh = test::distorted_grid(test::unit_cube(), {3, 3, 3}, GetParam(), 0.15, 5);
  const Eigen::MatrixXd points = random_interior_points(mesh, 300, 9);
  Eigen::Matrix3d A;
  A << 0.1, -0.3, 0.2, 0.05, 0.4, -0.1, -0.2, 0.15, 0.3;
  const Eigen::Vector3d b(0.3, -0.2, 0.1);
  const Eigen::VectorXd u =
      test::nodal_values(mesh, [&](const Eigen::Vector3d& x) -> Eigen::Vector3d { return A * x + b; });

  const BasisEmbedding embedding(LagrangeBasisEvaluator(mesh), points);
  EXPECT_EQ(embedding.outside_count(), 0);
  EXPECT_EQ(embedding.max_outside_distance(), 0.0);
  const Eigen::MatrixXd displacement = embedding.displacement(u);
  ASSERT_EQ(displacement.rows(), points.rows());
  ASSERT_EQ(displacement.cols(), 3);
  const Eigen::MatrixXd expected = (points * A.transpose()).rowwise() + b.transpose();
  EXPECT_LT((displacement - expected).cwiseAbs().maxCoeff(), 1e-12);
}

// The points are located in parallel, a block per thread, and joined in order: any number
// of threads gives the same entries, bit for bit, the points outside extrapolated alike.
TEST_P(EmbeddingOfType, EveryThreadCountGivesTheSameEmbedding) {
  const VolumeMesh mesh = test::distorted_grid(test::unit_cube(), {3, 3, 3}, GetParam(), 0.15, 5);
  Eigen::MatrixXd points(310, 3);
  points.topRows(300) = random_interior_points(mesh, 300, 11);
  for (int p = 300; p < 310; ++p) points.row(p) = Eigen::RowVector3d(1.02 + 0.001 * p, 0.5, 0.4 - 0.01 * p);
  const Eigen::VectorXd u = test::nodal_values(mesh, [](const Eigen::Vector3d& x) -> Eigen::Vector3d {
    return {std::sin(3 * x.x()), x.y() * x.z(), x.x()};
  });
  const LagrangeBasisEvaluator evaluator(mesh);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const BasisEmbedding serial(evaluator, points);
  omp_set_num_threads(3);
  const BasisEmbedding parallel(evaluator, points);
  omp_set_num_threads(threads);
  EXPECT_EQ(serial.outside_count(), 10);
  EXPECT_EQ(parallel.outside_count(), 10);
  EXPECT_EQ(parallel.max_outside_distance(), serial.max_outside_distance());
  for (Eigen::Index p = 0; p < points.rows(); ++p) {
    const std::span<const int> serial_basis = serial.basis_of(p), parallel_basis = parallel.basis_of(p);
    ASSERT_TRUE(std::equal(serial_basis.begin(), serial_basis.end(), parallel_basis.begin(), parallel_basis.end()))
        << "point " << p;
  }
  EXPECT_EQ(parallel.displacement(u), serial.displacement(u));
}

// A method's surface embeds its vertices on first use, once: a run that writes no surface
// frames embeds nothing after a cut or a refinement.
TEST(EmbeddedSurface, EmbedsItsVerticesOnFirstUseAndOnce) {
  const VolumeMesh mesh = test::distorted_grid(test::unit_cube(), {2, 2, 2}, ElementType::hex8, 0.1, 3);
  EmbeddedSurface surface;
  surface.surface.vertices = random_interior_points(mesh, 20, 4);
  surface.evaluator = std::make_unique<LagrangeBasisEvaluator>(mesh);
  int built = 0;
  surface.make_embedding = [&built](const EmbeddedSurface& embedded) {
    ++built;
    return EmbeddedSurface::embed_in_basis(embedded);
  };
  EXPECT_EQ(built, 0);
  const Eigen::Vector3d shift(0.3, -0.2, 0.1);
  const Eigen::VectorXd u =
      test::nodal_values(mesh, [&](const Eigen::Vector3d& x) -> Eigen::Vector3d { return x + shift; });
  const Eigen::MatrixXd expected = surface.surface.vertices.rowwise() + shift.transpose();
  EXPECT_LT((surface.embedding().displacement(u) - expected).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(surface.facts()["surface_vertices"], 20);
  EXPECT_EQ(built, 1);
}

INSTANTIATE_TEST_SUITE_P(PointEmbedding, EmbeddingOfType, ::testing::ValuesIn(test::all_element_types),
                         [](const auto& info) { return std::string(element_name(info.param)); });

}  // namespace
}  // namespace altfem
