// Point location in the cells of a sliced torus (cut cells, non-convex ones among them):
// cell_holds reads the winding number from the mesh's faces in place, and must agree with
// the winding number of the cell's polyhedron (cell_polyhedron) for both cells of every
// interior face's orientation; every point inside the torus, away from cell boundaries,
// lies in exactly one cell, and points outside in none.
#include <gtest/gtest.h>

#include <random>

#include "shared/mesh/polyhedral_cell_location.hpp"
#include "shared/mesh/slice_into_polyhedra.hpp"
#include "tests/unit/surfaces.hpp"

namespace altfem {
namespace {

TEST(PolyhedralCellLocation, CellHoldsAgreesWithThePolyhedronsWindingNumberAndPartitionsTheTorus) {
  SlicingOptions options;
  options.resolution = 6;
  const PolyhedralMesh mesh =
      slice_into_polyhedra(test::torus(1.0, 0.4, 48, 24, Eigen::Vector3d::Zero()), options).mesh;
  std::mt19937 generator(11);
  std::uniform_real_distribution<double> uniform(-1.5, 1.5);
  int inside = 0;
  for (int p = 0; p < 400; ++p) {
    const Eigen::Vector3d x(uniform(generator), uniform(generator), 0.3 * uniform(generator));
    int holding = 0;
    for (int cell = 0; cell < mesh.cell_count(); ++cell) {
      const bool holds = cell_holds(mesh, cell, x, 0.0);
      EXPECT_EQ(holds, winding_number(cell_polyhedron(mesh, cell), x) > 0.5) << "cell " << cell;
      holding += holds;
    }
    // The torus (major radius 1, minor 0.4, its facets inside the smooth surface).
    const double ring = std::hypot(std::hypot(x.x(), x.y()) - 1.0, x.z());
    if (ring < 0.35) {
      EXPECT_EQ(holding, 1) << x.transpose();
      ++inside;
    } else if (ring > 0.45) {
      EXPECT_EQ(holding, 0) << x.transpose();
    }
  }
  EXPECT_GT(inside, 40);
}

}  // namespace
}  // namespace altfem
