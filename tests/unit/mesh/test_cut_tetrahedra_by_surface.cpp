// A surface blade's tetrahedra (issue #33) conform: a closed blade inside cuts its volume
// out of tetrahedra and out of hexahedral fragments' cones, every face two tetrahedra
// share matched (the boundary's area is the body's and twice the blade's), and planes
// across what it leaves — fragments split into cones from their centroids, faces into
// triangles about theirs — cut again without leaving a tetrahedron out.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <map>
#include <random>

#include "shared/mesh/cut_by_surface.hpp"
#include "shared/mesh/cut_tetrahedral_mesh.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "tests/unit/mesh/ball_blade.hpp"
#include "tests/unit/mesh/tetrahedral_pieces.hpp"

namespace altfem {
namespace {

using test::ball_blade;
using test::enclosed_volume;
using test::tetrahedral_pieces;
using test::TetrahedralPieces;

VolumeMesh unit_cube_grid(ElementType type, int cells_per_axis) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  return structured_grid(box, Eigen::Vector3i::Constant(cells_per_axis), type);
}

double area_of(const SurfaceBlade& blade) {
  double area = 0;
  for (Eigen::Index t = 0; t < blade.triangles.rows(); ++t) {
    const Eigen::Vector3d a = blade.vertices.row(blade.triangles(t, 0)), b = blade.vertices.row(blade.triangles(t, 1)),
                          c = blade.vertices.row(blade.triangles(t, 2));
    area += (b - a).cross(c - a).norm() / 2;
  }
  return area;
}

// The ball's tetrahedra: out of a tetrahedral grid, or out of a hexahedral grid's cells as
// fragments (each split by its cone).
FragmentedTetrahedra cube_of(bool hexahedral_fragments) {
  return hexahedral_fragments
             ? convex_cells_as_fragments(polyhedral_mesh_from_volume_mesh(unit_cube_grid(ElementType::hex8, 2)))
             : FragmentedTetrahedra{unit_cube_grid(ElementType::tet4, 3)};
}

TEST(CutBySurface, AClosedBladeInsideCutsItsVolumeOutOfConformingTetrahedra) {
  const SurfaceBlade blade = ball_blade();
  const double inside_volume = enclosed_volume(blade);
  const double ball_area = area_of(blade);
  for (const bool hexahedral_fragments : {false, true}) {
    const TetrahedralCut cut = cut_tetrahedral_mesh_by_surface(cube_of(hexahedral_fragments), blade);
    EXPECT_EQ(cut.flat_tetrahedra, 0) << hexahedral_fragments;
    const TetrahedralPieces pieces = tetrahedral_pieces(cut.result.mesh);
    ASSERT_EQ(pieces.volumes.size(), 2u) << hexahedral_fragments;
    EXPECT_NEAR(pieces.volumes[0], inside_volume, 1e-13) << hexahedral_fragments;
    EXPECT_NEAR(pieces.volumes[1], 1 - inside_volume, 1e-13) << hexahedral_fragments;
    EXPECT_NEAR(pieces.boundary_area, 6 + 2 * ball_area, 1e-12) << hexahedral_fragments;
    EXPECT_EQ(static_cast<int>(cut.parent_fragment.size()), cut.result.fragment_count());
    // A plane cut after it, through fragments the ball's steps split into cones from
    // their centroids (whose faces are triangles about theirs, some in one plane): a slab
    // z < 0.1 comes off, the tetrahedra still conforming.
    const TetrahedralCut again =
        cut_tetrahedral_mesh(cut.result, CuttingPlane(Eigen::Vector3d(0.5, 0.5, 0.1), Eigen::Vector3d::UnitZ()));
    const TetrahedralPieces three = tetrahedral_pieces(again.result.mesh);
    ASSERT_EQ(three.volumes.size(), 3u) << hexahedral_fragments;
    EXPECT_NEAR(three.volumes[0], inside_volume, 1e-13) << hexahedral_fragments;
    EXPECT_NEAR(three.volumes[1], 0.1, 1e-13) << hexahedral_fragments;
    EXPECT_NEAR(three.boundary_area, 6 + 2 * ball_area + 2, 1e-12) << hexahedral_fragments;
  }
}

TEST(CutBySurface, SeededPlanesAcrossTheBallsConesLeaveNoTetrahedronOut) {
  // A plane through a fragment the ball split by a cone from its centroid meets faces that
  // are triangles about their rounded centroids: a piece's lowest node then lies in the
  // plane of a face it does not hold to a rounding, and its cone over that face was flat
  // (left out, its faces unmatched: up to 200 tetrahedra a plane). Seeded planes along
  // each axis leave none out; the body's volume stays and every inner face is matched.
  const SurfaceBlade blade = ball_blade();
  const double boundary_area = 6 + 2 * area_of(blade) + 2;  // + the section, both sides
  std::mt19937 generator(33);
  std::uniform_real_distribution<double> height(0.02, 0.98);
  for (const bool hexahedral_fragments : {false, true}) {
    const TetrahedralCut cut = cut_tetrahedral_mesh_by_surface(cube_of(hexahedral_fragments), blade);
    for (int plane = 0; plane < 6; ++plane) {
      const int axis = plane % 3;
      Eigen::Vector3d point = Eigen::Vector3d::Constant(0.5);
      point(axis) = height(generator);
      const TetrahedralCut again = cut_tetrahedral_mesh(cut.result, CuttingPlane(point, Eigen::Vector3d::Unit(axis)));
      EXPECT_EQ(again.flat_tetrahedra, 0) << hexahedral_fragments << " " << point.transpose();
      const TetrahedralPieces pieces = tetrahedral_pieces(again.result.mesh);
      double volume = 0;
      for (const double piece : pieces.volumes) volume += piece;
      EXPECT_NEAR(volume, 1, 1e-13) << hexahedral_fragments << " " << point.transpose();
      EXPECT_NEAR(pieces.boundary_area, boundary_area, 1e-12) << hexahedral_fragments << " " << point.transpose();
    }
  }
}

// A notch of two flat parts, each a quadrilateral of two triangles whose shared diagonal
// runs through the body: from the cube's floor up to (0.6, 0.4) in (x, z), then bent up to
// (0.7, 0.5), where it ends; across y beyond the body. The second part lies in one cell,
// whose section by its plane its first triangle does not open (the section's centroid lies
// in the second, which holds the fold): each flat part's pieces are joined once all its
// triangles are cut. Joined after each triangle, the cell came back whole, and the second
// triangle's section reached past the first's edge at the notch's end, its centroid
// beyond the second: the notch did not open that cell.
SurfaceBlade bent_notch() {
  SurfaceBlade blade;
  blade.vertices.resize(6, 3);
  const double xs[3] = {0.3, 0.6, 0.7}, zs[3] = {-0.2, 0.4, 0.5};
  for (int row = 0; row < 3; ++row) {
    blade.vertices.row(2 * row) << xs[row], -0.8, zs[row];
    blade.vertices.row(2 * row + 1) << xs[row], 1.2, zs[row];
  }
  blade.triangles.resize(4, 3);
  blade.triangles << 0, 2, 3, 0, 3, 1, 2, 4, 5, 2, 5, 3;
  return blade;
}

TEST(CutBySurface, ABentNotchPartsTheFragmentsItCrossesAndOpensWhereItReaches) {
  const FragmentedTetrahedra bar = convex_cells_as_fragments(polyhedral_mesh_from_volume_mesh(
      structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()), Eigen::Vector3i(4, 1, 1),
                      ElementType::hex8)));
  const TetrahedralCut cut = cut_tetrahedral_mesh_by_surface(bar, bent_notch());
  EXPECT_EQ(cut.flat_tetrahedra, 0);
  std::vector<int> input_fragment;
  for (Eigen::Index tetrahedron = 0; tetrahedron < cut.result.mesh.cells.rows(); ++tetrahedron)
    input_fragment.push_back(cut.parent_fragment[cut.result.fragment_of(static_cast<int>(tetrahedron))]);
  // The notch crosses the cell x ∈ [0.25, 0.5] (from the floor at x = 0.4 to z = 0.2) and
  // ends in [0.5, 0.75].
  const TetrahedralPieces parts = tetrahedral_pieces(cut.result.mesh, input_fragment);
  EXPECT_EQ(parts.pieces_of_group, (std::map<int, int>{{0, 1}, {1, 2}, {2, 1}, {3, 1}}));
  // One body, its boundary the cube's and both sides of the notch inside it.
  const TetrahedralPieces body = tetrahedral_pieces(cut.result.mesh);
  ASSERT_EQ(body.volumes.size(), 1u);
  EXPECT_NEAR(body.volumes[0], 1, 1e-13);
  const double notch = std::hypot(0.2, 0.4) + std::hypot(0.1, 0.1);
  EXPECT_NEAR(body.boundary_area, 6 + 2 * notch, 1e-12);
}

}  // namespace
}  // namespace altfem
