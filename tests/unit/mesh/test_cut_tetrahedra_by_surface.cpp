// A surface blade's tetrahedra (issue #33) conform: a closed blade inside cuts its volume
// out of tetrahedra and out of hexahedral fragments' cones, every face two tetrahedra
// share matched (the boundary's area is the body's and twice the blade's), and planes
// across what it leaves — fragments split into cones from their centroids, faces into
// triangles about theirs — cut again without leaving a tetrahedron out.
#include <gtest/gtest.h>

#include <Eigen/Core>
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

}  // namespace
}  // namespace altfem
