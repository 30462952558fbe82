// The check a cut's new cells pass before they become harmonic elements
// (polyhedral/cut_piece_fits.hpp): a new shape is fitted once, and its fit kept for the
// build on the cut mesh, which then fits nothing again; a fit that misses its boundary
// data by more than the tolerance, or a cell with no volume whose fit fails, is refused.
#include <gtest/gtest.h>

#include "polyhedral/cut_piece_fits.hpp"
#include "polyhedral/harmonic_element_bases.hpp"
#include "shared/mesh/cut_polyhedral_mesh.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/mesh/structured_grid.hpp"

namespace altfem::harmonic {
namespace {

struct CutHexahedra {
  PolyhedralMesh before;
  PolyhedralCut cut;
  std::vector<int> cells;  // every cell of the cut mesh
};

// 2 × 2 × 1 cells of [0, 2] × [0, 1.2] × [0, 0.8]; x = 0.5 crosses the two of x in [0, 1]
// into four boxes, translates of one another; the two of [1, 2] keep their shape.
CutHexahedra cut_hexahedra() {
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 1.2, 0.8));
  CutHexahedra result{polyhedral_mesh_from_volume_mesh(structured_grid(box, {2, 2, 1}, ElementType::hex8)), {}, {}};
  result.cut = cut_polyhedral_mesh(result.before, CuttingPlane(Eigen::Vector3d(0.5, 0, 0), Eigen::Vector3d::UnitX()));
  for (int cell = 0; cell < result.cut.mesh.cell_count(); ++cell) result.cells.push_back(cell);
  return result;
}

TEST(CutPieceFits, ANewShapeIsFittedOnceAndTheBuildOnTheCutMeshFitsNothing) {
  const CutHexahedra hexahedra = cut_hexahedra();
  const MfsOptions options;
  HarmonicBasisMemory memory(options);
  const HarmonicElementBases before(hexahedra.before, HarmonicBasisKind::mfs, options, nullptr, &memory);
  ASSERT_EQ(memory.size(), 1);
  const std::vector<bool> fails =
      cells_whose_fit_fails(hexahedra.cut.mesh, hexahedra.cells, HarmonicBasisKind::mfs, options, 1e-2, memory);
  EXPECT_EQ(std::count(fails.begin(), fails.end(), true), 0);
  EXPECT_EQ(memory.size(), 2);  // the pieces' one shape
  const HarmonicElementBases after(hexahedra.cut.mesh, HarmonicBasisKind::mfs, options, &memory);
  EXPECT_EQ(after.remembered_bases(), hexahedra.cut.mesh.cell_count());
  // With `auto` the cells the cut left whole keep their trilinear basis: never refused.
  HarmonicBasisMemory empty(options);
  const std::vector<bool> refused =
      cells_whose_fit_fails(hexahedra.cut.mesh, hexahedra.cells, HarmonicBasisKind::automatic, options, 0, empty);
  for (const int cell : hexahedra.cells)
    EXPECT_EQ(refused[cell], hexahedra.before.cell_centroids(hexahedra.cut.parent_cell[cell], 0) < 1)
        << "cell " << cell;
  EXPECT_EQ(empty.size(), 0);
}

TEST(CutPieceFits, AFitAboveTheToleranceIsRefusedAndNotKept) {
  const CutHexahedra hexahedra = cut_hexahedra();
  const MfsOptions options;
  HarmonicBasisMemory memory(options);
  const HarmonicElementBases before(hexahedra.before, HarmonicBasisKind::mfs, options, nullptr, &memory);
  const HarmonicElementBases fresh(hexahedra.cut.mesh, HarmonicBasisKind::mfs, options);
  int piece = 0;  // a cell of a crossed parent
  while (hexahedra.before.cell_centroids(hexahedra.cut.parent_cell[piece], 0) > 1) ++piece;
  const double residual = fresh.mfs_basis(piece)->boundary_residual();
  const std::vector<bool> fails = cells_whose_fit_fails(hexahedra.cut.mesh, hexahedra.cells, HarmonicBasisKind::mfs,
                                                        options, 0.5 * residual, memory);
  for (const int cell : hexahedra.cells)  // the pieces refused; the cells the cut left whole were fitted before
    EXPECT_EQ(fails[cell], hexahedra.before.cell_centroids(hexahedra.cut.parent_cell[cell], 0) < 1) << "cell " << cell;
  EXPECT_EQ(memory.size(), 1);
}

// A hexahedron squashed flat after the mesh was built (its right face moved onto its left
// one; the mesh refuses such a cell): its faces across have no area, and no fit exists.
TEST(CutPieceFits, ACellWithoutVolumeIsRefused) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 1, 1));
  PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(structured_grid(box, {2, 1, 1}, ElementType::hex8));
  for (Eigen::Index node = 0; node < mesh.nodes.rows(); ++node)
    if (mesh.nodes(node, 0) > 0.75) mesh.nodes(node, 0) = 0.5;
  const MfsOptions options;
  HarmonicBasisMemory memory(options);
  const std::vector<bool> fails = cells_whose_fit_fails(mesh, {0, 1}, HarmonicBasisKind::mfs, options, 1e-2, memory);
  EXPECT_FALSE(fails[0]);
  EXPECT_TRUE(fails[1]);
}

}  // namespace
}  // namespace altfem::harmonic
