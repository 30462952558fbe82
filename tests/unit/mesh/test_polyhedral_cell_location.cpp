// Point location in the cells of a sliced torus (cut cells, non-convex ones among them):
// cell_holds reads the winding number from the mesh's faces in place, and must agree with
// the winding number of the cell's polyhedron (cell_polyhedron) for both cells of every
// interior face's orientation; every point inside the torus, away from cell boundaries,
// lies in exactly one cell, and points outside in none. The convex pieces of cells a
// blade crossed (kind split) are decided by their face planes alone: the same answers.
#include <gtest/gtest.h>

#include <random>

#include "shared/mesh/cut_polyhedral_mesh.hpp"
#include "shared/mesh/polyhedral_cell_location.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/mesh/slice_into_polyhedra.hpp"
#include "shared/mesh/structured_grid.hpp"
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

TEST(PolyhedralCellLocation, SplitPiecesOfABladeAreDecidedByTheirPlanesAsByTheWindingNumber) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  PolyhedralMesh mesh =
      polyhedral_mesh_from_volume_mesh(structured_grid(box, Eigen::Vector3i(2, 2, 2), ElementType::hex8));
  mesh = cut_polyhedral_mesh(mesh, CuttingPlane(Eigen::Vector3d(0.3, 0.4, 0.5), Eigen::Vector3d(1, 0.3, 0.2))).mesh;
  mesh = cut_polyhedral_mesh(mesh, CuttingPlane(Eigen::Vector3d(0.6, 0.5, 0.4), Eigen::Vector3d(-0.2, 1, 0.5))).mesh;
  int split = 0;
  for (const PolyhedralCellKind kind : mesh.cell_kinds) split += kind == PolyhedralCellKind::split;
  ASSERT_GT(split, 8);
  std::mt19937 generator(5);
  std::uniform_real_distribution<double> uniform(-0.1, 1.1);
  for (int p = 0; p < 300; ++p) {
    const Eigen::Vector3d x(uniform(generator), uniform(generator), uniform(generator));
    int holding = 0;
    for (int cell = 0; cell < mesh.cell_count(); ++cell) {
      const bool holds = cell_holds(mesh, cell, x, 0.0);
      EXPECT_EQ(holds, winding_number(cell_polyhedron(mesh, cell), x) > 0.5) << "cell " << cell;
      holding += holds;
    }
    if (box.contains(x)) EXPECT_GE(holding, 1) << x.transpose();
    else EXPECT_EQ(holding, 0) << x.transpose();
  }
}

}  // namespace
}  // namespace altfem
