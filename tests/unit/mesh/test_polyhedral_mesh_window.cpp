// A surface blade cuts a window of the mesh at a time (polyhedral_mesh_window.hpp): a
// planar step on the window about its region, put back, must make the mesh the same step
// makes on the whole mesh — the same cells in the same order, each with its parent, kind,
// volume and centroid, the same faces and nodes — for seeded planes (through nodes and
// along faces as well as anywhere), split and separate steps, on hexahedra, tetrahedra and
// a mesh already cut; and a window about a box the mesh misses holds nothing.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "shared/mesh/cut_polyhedral_mesh.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/mesh/polyhedral_mesh_window.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "tests/unit/mesh/every_cell_closed.hpp"

namespace altfem {
namespace {

PolyhedralMesh unit_cube_cells(ElementType type, int cells_per_axis) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  return polyhedral_mesh_from_volume_mesh(structured_grid(box, Eigen::Vector3i::Constant(cells_per_axis), type));
}

double diagonal_of(const PolyhedralMesh& mesh) {
  return (mesh.nodes.colwise().maxCoeff() - mesh.nodes.colwise().minCoeff()).norm();
}

// `mesh` cut by `plane` in `scope` on its window about the scope's region, put back.
PolyhedralCut windowed_cut(const PolyhedralMesh& mesh, const CuttingPlane& plane, const CutScope& scope) {
  std::vector<Eigen::AlignedBox3d> boxes = polyhedral_cell_boxes(mesh);
  const PolyhedralMeshWindow window = polyhedral_mesh_window(mesh, boxes, *scope.region);
  PolyhedralCut step = cut_polyhedral_mesh(window.mesh, plane, false, scope);
  PolyhedralCut result;
  result.mesh = mesh;
  result.parent_cell.resize(static_cast<std::size_t>(mesh.cell_count()));
  for (int cell = 0; cell < mesh.cell_count(); ++cell) result.parent_cell[cell] = cell;
  splice_polyhedral_mesh_window(result.mesh, boxes, result.parent_cell, window, std::move(step.mesh), step.parent_cell);
  compute_polyhedral_geometry(result.mesh);
  return result;
}

void expect_same_cut(const PolyhedralCut& whole, const PolyhedralCut& windowed) {
  const PolyhedralMesh &a = whole.mesh, &b = windowed.mesh;
  ASSERT_EQ(a.cell_count(), b.cell_count());
  ASSERT_EQ(a.face_count(), b.face_count());
  ASSERT_EQ(a.nodes.rows(), b.nodes.rows());
  EXPECT_TRUE(every_cell_closed(b));
  int boundary_a = 0, boundary_b = 0;
  for (int face = 0; face < a.face_count(); ++face) {
    boundary_a += a.is_boundary_face(face) ? 1 : 0;
    boundary_b += b.is_boundary_face(face) ? 1 : 0;
  }
  EXPECT_EQ(boundary_a, boundary_b);
  for (int cell = 0; cell < a.cell_count(); ++cell) {
    EXPECT_EQ(whole.parent_cell[cell], windowed.parent_cell[cell]) << "cell " << cell;
    EXPECT_EQ(a.cell_kinds[cell], b.cell_kinds[cell]) << "cell " << cell;
    EXPECT_EQ(a.cell_faces[cell].size(), b.cell_faces[cell].size()) << "cell " << cell;
    EXPECT_NEAR(a.cell_volumes(cell), b.cell_volumes(cell), 1e-15) << "cell " << cell;
    EXPECT_LT((a.cell_centroids.row(cell) - b.cell_centroids.row(cell)).norm(), 1e-14) << "cell " << cell;
  }
}

TEST(PolyhedralMeshWindow, AStepOnTheWindowMakesTheCellsOfTheStepOnTheWholeMesh) {
  std::mt19937 random(20261206);
  std::uniform_real_distribution<double> unit(0, 1), signed_unit(-1, 1);
  std::vector<PolyhedralMesh> meshes = {unit_cube_cells(ElementType::hex8, 5), unit_cube_cells(ElementType::tet4, 5)};
  // A mesh cut before: cells of kind split, faces holding crossing nodes of their edges.
  meshes.push_back(cut_polyhedral_mesh(meshes[0], CuttingPlane({0.5, 0.5, 0.5}, {1, 2, 3}), true,
                                       {CutAction::split, Eigen::AlignedBox3d(Eigen::Vector3d::Constant(0.3),
                                                                              Eigen::Vector3d::Constant(0.7))})
                       .mesh);
  int compared = 0;
  for (const PolyhedralMesh& mesh : meshes)
    for (int trial = 0; trial < 12; ++trial) {
      // Through the region's centre, or the grid node nearest it half the time; along grid
      // faces a quarter of it.
      const Eigen::Vector3d centre(unit(random), unit(random), unit(random));
      Eigen::Vector3d point = centre;
      if (trial % 2 == 0) point = (centre * 5).array().round() / 5;
      Eigen::Vector3d normal(signed_unit(random), signed_unit(random), signed_unit(random));
      if (trial % 4 == 0) normal = Eigen::Vector3d::Unit(trial / 4 % 3);
      CutScope scope{CutAction::split, Eigen::AlignedBox3d(centre.array() - 0.15, centre.array() + 0.15)};
      scope.snap_length = diagonal_of(mesh);
      const PolyhedralCut whole = cut_polyhedral_mesh(mesh, CuttingPlane(point, normal), true, scope);
      SCOPED_TRACE("mesh of " + std::to_string(mesh.cell_count()) + " cells, trial " + std::to_string(trial));
      expect_same_cut(whole, windowed_cut(mesh, CuttingPlane(point, normal), scope));
      compared += whole.crossed_cells > 0 ? 1 : 0;
    }
  EXPECT_GE(compared, 24);  // most regions hold cells the plane crosses (one along grid faces crosses none)
}

TEST(PolyhedralMeshWindow, ASeparationOnTheWindowOpensTheFacesItOpensOnTheWholeMesh) {
  // A triangle in the grid plane z = 0.4, covering some faces of it whole and some in part.
  for (const ElementType type : {ElementType::hex8, ElementType::tet4}) {
    const PolyhedralMesh mesh = unit_cube_cells(type, 5);
    const CuttingPlane blade = polygon_blade({{0.1, 0.1, 0.4}, {0.9, 0.2, 0.4}, {0.3, 0.8, 0.4}});
    Eigen::AlignedBox3d box;
    for (const Eigen::Vector3d& corner : blade.polygon) box.extend(corner);
    const CutScope scope{CutAction::separate, box};
    const PolyhedralCut whole = cut_polyhedral_mesh(mesh, blade, true, scope);
    ASSERT_GT(whole.separated_faces, 0);
    const PolyhedralCut windowed = windowed_cut(mesh, blade, scope);
    expect_same_cut(whole, windowed);
  }
}

TEST(PolyhedralMeshWindow, AWindowAboutABoxTheMeshMissesHoldsNothing) {
  const PolyhedralMesh mesh = unit_cube_cells(ElementType::hex8, 3);
  const Eigen::AlignedBox3d away(Eigen::Vector3d::Constant(1.5), Eigen::Vector3d::Constant(2));
  EXPECT_TRUE(polyhedral_mesh_window(mesh, polyhedral_cell_boxes(mesh), away).cells.empty());
  // A box touching the mesh's corner takes the corner cell and its neighbours around it.
  const Eigen::AlignedBox3d corner(Eigen::Vector3d::Constant(1), Eigen::Vector3d::Constant(2));
  const PolyhedralMeshWindow window = polyhedral_mesh_window(mesh, polyhedral_cell_boxes(mesh), corner);
  EXPECT_EQ(window.cells.size(), 8u);
  EXPECT_EQ(window.shell_faces.size(), 3u * 4u);  // the 2³ block's faces towards the other cells
}

}  // namespace
}  // namespace altfem
