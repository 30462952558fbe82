// Cell quadrature: every monomial up to the rule's strength integrated exactly, checked
// against the exact moments (polyhedron_moments), on a hexahedron and on a cell that is
// not star-shaped with respect to the cone apex (an extruded U).
#include <gtest/gtest.h>

#include <cmath>

#include "shared/geometry/monomial_index.hpp"
#include "shared/geometry/polyhedron_moments.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/mesh/polyhedral_quadrature.hpp"
#include "shared/mesh/structured_grid.hpp"

namespace altfem {
namespace {

/// ∫ x^a y^b z^c by the rule, in monomial_index order up to `degree`.
Eigen::VectorXd rule_moments(const QuadratureRule& rule, int degree) {
  Eigen::VectorXd moments = Eigen::VectorXd::Zero(monomial_count(degree));
  for (Eigen::Index q = 0; q < rule.weights.size(); ++q)
    for (int total = 0; total <= degree; ++total)
      for (int a = total; a >= 0; --a)
        for (int b = total - a; b >= 0; --b) {
          const int c = total - a - b;
          moments(monomial_index(a, b, c)) += rule.weights(q) * std::pow(rule.points(q, 0), a) *
                                              std::pow(rule.points(q, 1), b) * std::pow(rule.points(q, 2), c);
        }
  return moments;
}

/// The U-shaped polygon (0,0) (3,0) (3,2) (2,2) (2,½) (1,½) (1,2) (0,2) extruded over
/// z ∈ [0, 1]: its vertex centroid (1.5, 1.125, ½) lies in the gap, outside the cell.
Polyhedron extruded_u() {
  const double outline[8][2] = {{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 0.5}, {1, 0.5}, {1, 2}, {0, 2}};
  Polyhedron polyhedron;
  polyhedron.vertices.resize(16, 3);
  for (int i = 0; i < 8; ++i) {
    polyhedron.vertices.row(i) << outline[i][0], outline[i][1], 0;
    polyhedron.vertices.row(8 + i) << outline[i][0], outline[i][1], 1;
  }
  polyhedron.faces.push_back({7, 6, 5, 4, 3, 2, 1, 0});        // bottom, outward −z
  polyhedron.faces.push_back({8, 9, 10, 11, 12, 13, 14, 15});  // top, outward +z
  for (int i = 0; i < 8; ++i) polyhedron.faces.push_back({i, (i + 1) % 8, 8 + (i + 1) % 8, 8 + i});
  return polyhedron;
}

void expect_exact(const Polyhedron& polyhedron, int strength) {
  const QuadratureRule rule = polyhedron_quadrature(polyhedron, strength);
  ASSERT_GE(rule.strength, strength);
  const Eigen::VectorXd exact = polyhedron_moments(polyhedron, strength);
  const Eigen::VectorXd integrated = rule_moments(rule, strength);
  for (Eigen::Index i = 0; i < exact.size(); ++i)
    EXPECT_NEAR(integrated(i), exact(i), 1e-12 * std::max(1.0, std::abs(exact(i)))) << "monomial " << i;
}

TEST(PolyhedralQuadrature, HexahedronCellsAreExactWithPositiveWeights) {
  const VolumeMesh volume_mesh = structured_grid(
      Eigen::AlignedBox3d(Eigen::Vector3d(0.5, -1, 2), Eigen::Vector3d(1.5, 0.5, 3)), {2, 1, 1}, ElementType::hex8);
  const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(volume_mesh);
  for (int strength : {0, 1, 3, 6}) {
    const QuadratureRule rule = cell_quadrature(mesh, 1, strength);
    EXPECT_GT(rule.weights.minCoeff(), 0);
    EXPECT_NEAR(rule.weights.sum(), mesh.cell_volumes(1), 1e-14);
    expect_exact(cell_polyhedron(mesh, 1), strength);
  }
}

TEST(PolyhedralQuadrature, NonStarShapedCellIsExact) {
  const Polyhedron polyhedron = extruded_u();
  EXPECT_NEAR(polyhedron_moments(polyhedron, 0)(0), 4.5, 1e-14);
  for (int strength : {0, 2, 5}) expect_exact(polyhedron, strength);
  // The apex outside the cell: some cones are negative (the documented signed decomposition).
  EXPECT_LT(polyhedron_quadrature(polyhedron, 1).weights.minCoeff(), 0);
}

}  // namespace
}  // namespace altfem
