// cut_surface (issue #33): the surface a method deforms, opened by a blade and closed by
// caps. Every figure here is exact: a cut moves no material, so each side's enclosed
// volume is the box's part on that side and the caps cover the cross-section.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <random>

#include "shared/mesh/cut_surface.hpp"
#include "shared/mesh/mesh_components.hpp"
#include "shared/scene/scene.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "tests/unit/mesh/surface_pieces.hpp"
#include "tests/unit/surfaces.hpp"

namespace altfem {
namespace {

using test::area_in_plane;
using test::closed_and_oriented;
using test::pieces_of;
using test::volume_of_closed_pieces;

using test::box_surface;

TEST(CutSurface, APlaneSplitsABoxIntoTwoClosedPiecesWithTheirExactVolumes) {
  const SurfaceMesh box = box_surface(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  const SurfaceCut cut = cut_surface(box, CuttingPlane(Eigen::Vector3d(0.3, 0, 0), Eigen::Vector3d::UnitX()));
  // The input's vertices keep their indices.
  EXPECT_EQ(cut.surface.vertices.topRows(8), box.vertices);
  const std::vector<SurfaceMesh> pieces = pieces_of(cut.surface);
  ASSERT_EQ(pieces.size(), 2u);
  std::vector<double> volumes = {surface_volume(pieces[0]), surface_volume(pieces[1])};
  std::sort(volumes.begin(), volumes.end());
  EXPECT_NEAR(volumes[0], 0.3, 1e-15);
  EXPECT_NEAR(volumes[1], 0.7, 1e-15);
  for (const SurfaceMesh& piece : pieces) EXPECT_TRUE(closed_and_oriented(piece));
  // A cap per side over the unit cross-section, to the round-off of a sum over its
  // remeshed triangles.
  EXPECT_NEAR(area_in_plane(cut.surface, 0.3), 2.0, 1e-14);
  EXPECT_GT(cut.facts["cap_triangles"].get<int>(), 0);
}

TEST(CutSurface, ABladeThroughVerticesAndAlongEdgesIsAnOrdinaryCut) {
  // The plane x + y = 1 holds the box edges (1, 0, z) and (0, 1, z) and its faces' diagonals.
  const SurfaceMesh box = box_surface(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  const SurfaceCut cut = cut_surface(box, CuttingPlane(Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 1, 0)));
  const std::vector<SurfaceMesh> pieces = pieces_of(cut.surface);
  ASSERT_EQ(pieces.size(), 2u);
  for (const SurfaceMesh& piece : pieces) {
    EXPECT_NEAR(surface_volume(piece), 0.5, 1e-15);
    EXPECT_TRUE(closed_and_oriented(piece));
  }
}

TEST(CutSurface, ABladeOnAFaceOrMissingTheBodySeparatesNothing) {
  const SurfaceMesh box = box_surface(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  for (const double x : {0.0, 1.0, 2.0}) {
    const SurfaceCut cut = cut_surface(box, CuttingPlane(Eigen::Vector3d(x, 0, 0), Eigen::Vector3d::UnitX()));
    EXPECT_EQ(cut.surface.vertices, box.vertices);
    EXPECT_EQ(cut.surface.triangles, box.triangles);
    EXPECT_EQ(cut.surface.embedding_offsets.size(), 0);
    EXPECT_EQ(cut.facts["cap_triangles"], 0);
  }
}

TEST(CutSurface, AFiniteBladeNotchesTheBoxWithoutSeparatingIt) {
  // The plane x = 0.5 where y < `depth`: a notch from the face y = 0, through z. The deep
  // one's caps are remeshed with vertices inside them, which both caps shared (neither
  // side closed, the caps could not part) before each side got its own.
  const SurfaceMesh box = box_surface(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  for (const double depth : {0.4, 0.8}) {
    SCOPED_TRACE(::testing::Message() << "depth " << depth);
    const CuttingPlane blade = polygon_blade({Eigen::Vector3d(0.5, -1, -1), Eigen::Vector3d(0.5, depth, -1),
                                              Eigen::Vector3d(0.5, depth, 2), Eigen::Vector3d(0.5, -1, 2)});
    const SurfaceCut cut = cut_surface(box, blade);
    ASSERT_EQ(pieces_of(cut.surface).size(), 1u);
    EXPECT_TRUE(closed_and_oriented(cut.surface));
    EXPECT_NEAR(surface_volume(cut.surface), 1.0, 1e-15);
    EXPECT_NEAR(area_in_plane(cut.surface, 0.5), 2 * depth, 1e-14);
  }
}

TEST(CutSurface, APieceAtAPointCutsThatPieceAlone) {
  SurfaceMesh two = box_surface(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  const SurfaceMesh other = box_surface(Eigen::Vector3d(0, 2, 0), Eigen::Vector3d(1, 3, 1));
  two.vertices.conservativeResize(16, 3);
  two.vertices.bottomRows(8) = other.vertices;
  two.triangles.conservativeResize(24, 3);
  two.triangles.bottomRows(12) = other.triangles.array() + 8;
  CuttingPlane blade(Eigen::Vector3d(0.5, 0, 0), Eigen::Vector3d::UnitX());
  blade.piece_at = Eigen::Vector3d(0.5, 2.5, 0.5);
  const SurfaceCut cut = cut_surface(two, blade);
  EXPECT_NEAR(volume_of_closed_pieces(cut.surface, 3), 2.0, 1e-14);
  // The first box is as it was.
  EXPECT_EQ(cut.surface.triangles.topRows(12), two.triangles.topRows(12));
}

TEST(CutSurface, ASecondCutAcrossTheFirstKeepsEveryPieceClosed) {
  const SurfaceMesh sphere = test::sphere(1.0, 12, 24, Eigen::Vector3d::Zero());
  const SurfaceCut first = cut_surface(sphere, CuttingPlane(Eigen::Vector3d(0.1, 0, 0), Eigen::Vector3d(1, 0.2, 0)));
  EXPECT_TRUE(closed_and_oriented(first.surface));
  const SurfaceCut second =
      cut_surface(first.surface, CuttingPlane(Eigen::Vector3d(0, 0.05, 0), Eigen::Vector3d(0.1, 1, 0.3)));
  EXPECT_NEAR(volume_of_closed_pieces(second.surface, 4), surface_volume(sphere), 1e-13);
  EXPECT_EQ(second.surface.vertices.topRows(sphere.vertices.rows()), sphere.vertices);
}

TEST(CutSurface, TheSameCutGivesTheSameSurfaceBitForBit) {
  // CGAL numbers what corefinement makes by heap addresses, and the caps' remeshing
  // followed that numbering: the pencil's surface differed from run to run. Three runs in
  // one process (each leaves the heap otherwise than it found it) of a plane and a finite
  // blade through a sphere must give identical vertices and triangles.
  const SurfaceMesh sphere = test::sphere(1.0, 12, 24, Eigen::Vector3d(0.01, 0.02, 0.03));
  const CuttingPlane plane(Eigen::Vector3d(-0.3, 0, 0), Eigen::Vector3d(1, 0.2, 0.1));
  const CuttingPlane notch = polygon_blade({Eigen::Vector3d(0.2, -2, -0.3), Eigen::Vector3d(0.2, 2, -0.3),
                                            Eigen::Vector3d(0.3, 2, 2), Eigen::Vector3d(0.3, -2, 2)});
  std::vector<SurfaceMesh> runs;
  for (int run = 0; run < 3; ++run) runs.push_back(cut_surface(cut_surface(sphere, plane).surface, notch).surface);
  ASSERT_GT(runs[0].vertices.rows(), sphere.vertices.rows());
  for (int run = 1; run < 3; ++run) {
    ASSERT_EQ(runs[run].vertices.rows(), runs[0].vertices.rows());
    ASSERT_EQ(runs[run].triangles.rows(), runs[0].triangles.rows());
    EXPECT_EQ(runs[run].vertices, runs[0].vertices);
    EXPECT_EQ(runs[run].triangles, runs[0].triangles);
  }
}

// The square [y0, y1] × [z0, z1] of the plane through `point` with normal `normal`.
CuttingPlane square_blade(const Eigen::Vector3d& point, const Eigen::Vector3d& normal, double y0, double y1, double z0,
                          double z1) {
  const auto corner = [&](double y, double z) {
    return Eigen::Vector3d(point.x() - (normal.y() * (y - point.y()) + normal.z() * (z - point.z())) / normal.x(), y,
                           z);
  };
  return polygon_blade({corner(y0, z0), corner(y1, z0), corner(y1, z1), corner(y0, z1)});
}

TEST(CutSurface, APieceThatIntersectsItselfIsLeftWholeByANotchAndRemembered) {
  // Two boxes, the second's vertex (1, 3, 1) pushed through the first box's top: its
  // faces cross it, so the second box's piece intersects itself, which corefinement cannot
  // cut. A notch (the lower half of a plane) through both opens the first, leaves the
  // second whole and marks its triangles; given those marks, a notch leaves even a sound
  // piece whole without testing it (the same box unmarked opens). A whole plane, or a
  // polygon over the whole section, splits a marked piece all the same.
  SurfaceMesh two = box_surface(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  SurfaceMesh crossed = box_surface(Eigen::Vector3d(0, 2, 0), Eigen::Vector3d(1, 3, 1));
  crossed.vertices.row(7) << 0.5, 0.5, 0.5;
  two.vertices.conservativeResize(16, 3);
  two.vertices.bottomRows(8) = crossed.vertices;
  two.triangles.conservativeResize(24, 3);
  two.triangles.bottomRows(12) = crossed.triangles.array() + 8;
  const Eigen::Vector3d tilted(1, 0.1, 0.2);
  const SurfaceCut cut = cut_surface(two, square_blade(Eigen::Vector3d(0.5, 0, 0), tilted, -1, 4, -1, 0.4));
  EXPECT_EQ(cut.facts["pieces_left_whole"], 1);
  EXPECT_GT(cut.facts["cap_triangles"].get<int>(), 0);
  ASSERT_EQ(cut.surface.self_intersecting.size(), static_cast<std::size_t>(cut.surface.triangles.rows()));
  int marked = 0;
  for (Eigen::Index t = 0; t < cut.surface.triangles.rows(); ++t) {
    const bool of_crossed_box =
        cut.surface.triangles.row(t).minCoeff() >= 8 && cut.surface.triangles.row(t).maxCoeff() < 16;
    EXPECT_EQ(cut.surface.self_intersecting[t] != 0, of_crossed_box) << t;
    marked += cut.surface.self_intersecting[t];
  }
  EXPECT_EQ(marked, 12);
  // Notched again, at the crossed box only: it stays whole, counted and marked.
  CuttingPlane again_blade = square_blade(Eigen::Vector3d(0.3, 0, 0), Eigen::Vector3d::UnitX(), -1, 4, -1, 0.4);
  again_blade.piece_at = Eigen::Vector3d(0.5, 2.5, 0.5);
  const SurfaceCut again = cut_surface(cut.surface, again_blade);
  EXPECT_EQ(again.facts["pieces_left_whole"], 1);
  EXPECT_EQ(std::count(again.surface.self_intersecting.begin(), again.surface.self_intersecting.end(), 1), 12);

  SurfaceMesh sound = box_surface(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  const CuttingPlane notch = square_blade(Eigen::Vector3d(0.5, 0, 0), Eigen::Vector3d::UnitX(), -1, 2, -1, 0.4);
  EXPECT_EQ(cut_surface(sound, notch).facts["pieces_left_whole"], 0);
  sound.self_intersecting.assign(12, 1);
  const SurfaceCut trusted = cut_surface(sound, notch);
  EXPECT_EQ(trusted.facts["pieces_left_whole"], 1);
  EXPECT_EQ(trusted.surface.triangles, sound.triangles);
  for (const CuttingPlane& through : {CuttingPlane(Eigen::Vector3d(0.5, 0, 0), tilted),
                                      square_blade(Eigen::Vector3d(0.5, 0, 0), tilted, -1, 4, -1, 2)}) {
    const SurfaceCut split = cut_surface(sound, through);
    EXPECT_EQ(split.facts["pieces_left_whole"], 0);
    EXPECT_NEAR(volume_of_closed_pieces(split.surface, 2), 1.0, 1e-15);
    EXPECT_EQ(split.surface.self_intersecting, std::vector<char>(split.surface.triangles.rows(), 1));
  }
}

TEST(CutSurface, APolygonOverTheWholeSectionSeparatesLikeThePlane) {
  // The square spans the box's section: corefinement left both sides joined along the cut,
  // neither closed, so that the next cut left the box whole. Now two closed pieces, which a
  // second cut opens again.
  const SurfaceMesh box = box_surface(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  const SurfaceCut first =
      cut_surface(box, square_blade(Eigen::Vector3d(0.5, 0, 0), Eigen::Vector3d(1, 0.1, 0.2), -1, 4, -1, 2));
  EXPECT_NEAR(volume_of_closed_pieces(first.surface, 2), 1.0, 1e-15);
  const SurfaceCut second =
      cut_surface(first.surface, square_blade(Eigen::Vector3d(0.2, 0, 0), Eigen::Vector3d::UnitX(), -1, 4, -1, 2));
  EXPECT_EQ(second.facts["pieces_left_whole"], 0);
  EXPECT_NEAR(volume_of_closed_pieces(second.surface, 3), 1.0, 1e-15);
}

TEST(CutSurface, EachCutOfASweepOpensTheNotchFurtherUntilItSeparates) {
  // A notch into the box at x = 0.5, z < 0.2, swept up by 0.6 in three more cuts: each
  // covers z < 0.5, 0.8, then z < 1.1 — the blades a sweep's events hold (swept_blade).
  // Cut one after the other, the second found the notched box intersecting itself (its
  // caps on one another) and left it whole; each cut now opens the notch further (the box
  // before the sweep cut again by its blade alone, the earlier ones left out since it
  // covers them): one closed piece of the box's volume whose caps cover 2 × the notch's
  // section, until the last, which covers the whole section, separates it.
  const SurfaceMesh box = box_surface(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  const CuttingPlane start = square_blade(Eigen::Vector3d(0.5, 0, 0), Eigen::Vector3d::UnitX(), -1, 2, -1, 0.2);
  SurfaceMesh surface = box;
  for (int cut = 0; cut <= 3; ++cut) {
    SCOPED_TRACE(::testing::Message() << "cut " << cut);
    CuttingPlane blade = cut == 0 ? start : swept_blade(start, Eigen::Vector3d(0, 0, 0.3 * cut));
    blade.sweep = "/events/0";
    const SurfaceCut result = cut_surface(surface, blade);
    EXPECT_EQ(result.facts["pieces_left_whole"], 0);
    EXPECT_EQ(result.facts.contains("blades_cut_again"), cut == 1 || cut == 2);
    EXPECT_EQ(result.surface.vertices.topRows(8), box.vertices);
    const double top = std::min(1.0, 0.2 + 0.3 * cut);
    EXPECT_NEAR(area_in_plane(result.surface, 0.5), 2 * top, 1e-14);
    if (top < 1) {
      ASSERT_EQ(pieces_of(result.surface).size(), 1u);
      EXPECT_TRUE(closed_and_oriented(result.surface));
      EXPECT_NEAR(surface_volume(result.surface), 1.0, 1e-15);
    } else {
      EXPECT_NEAR(volume_of_closed_pieces(result.surface, 2), 1.0, 1e-15);
    }
    surface = result.surface;
    // A blade that misses the body between two of the sweep's cuts changes nothing.
    if (cut == 1)
      surface = cut_surface(surface, CuttingPlane(Eigen::Vector3d(5, 0, 0), Eigen::Vector3d::UnitX())).surface;
  }
  // Not of one sweep, two overlapping blades of one plane (the second covers the first): their
  // caps would lie on one another, so the second cuts from before the first as their union,
  // one convex polygon (coplanar_blades.hpp), and the notch opens to z = 0.5.
  const CuttingPlane first = start, second = swept_blade(start, Eigen::Vector3d(0, 0, 0.3));
  const SurfaceCut both = cut_surface(cut_surface(box, first).surface, second);
  EXPECT_EQ(both.facts["pieces_left_whole"], 0);
  ASSERT_EQ(pieces_of(both.surface).size(), 1u);
  EXPECT_TRUE(closed_and_oriented(both.surface));
  EXPECT_NEAR(surface_volume(both.surface), 1.0, 1e-15);
  EXPECT_NEAR(area_in_plane(both.surface, 0.5), 2 * 0.5, 1e-14);
  // Two that overlap but whose union is not convex (a notch z < 0.2 and a strip y in [0.3,
  // 0.6] up to z = 0.7 across it: a T) leave the notched box whole, counted.
  const CuttingPlane strip = square_blade(Eigen::Vector3d(0.5, 0, 0), Eigen::Vector3d::UnitX(), 0.3, 0.6, -1, 0.7);
  EXPECT_EQ(cut_surface(cut_surface(box, first).surface, strip).facts["pieces_left_whole"], 1);
}

TEST(CutSurface, ASecondNotchOrAPlaneAcrossTheNotchCutsANotchedBox) {
  // A notch from the face z = 0 up to z = 0.5 at x = 0.3 leaves the box with its caps on
  // one another, which corefinement cannot cut and no plane's section closes: a second
  // notch (tilted, about x = 0.7), or a plane across the notch (z = 0.25), left it whole.
  // Now the box before the notch is cut again, with the notch's blade and the new one.
  const SurfaceMesh box = box_surface(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  const SurfaceCut notched =
      cut_surface(box, square_blade(Eigen::Vector3d(0.3, 0, 0), Eigen::Vector3d::UnitX(), -1, 2, -1, 0.5));
  // Both notches open: one closed piece of the box's volume, the caps over the first
  // notch's section on both sides.
  const SurfaceCut second = cut_surface(
      notched.surface, square_blade(Eigen::Vector3d(0.7, 0, 0), Eigen::Vector3d(1, 0.1, 0.2), -1, 2, -1, 0.5));
  EXPECT_EQ(second.facts["pieces_left_whole"], 0);
  EXPECT_EQ(second.facts["blades_cut_again"], 1);
  EXPECT_EQ(second.surface.vertices.topRows(8), box.vertices);
  ASSERT_EQ(pieces_of(second.surface).size(), 1u);
  EXPECT_TRUE(closed_and_oriented(second.surface));
  EXPECT_NEAR(surface_volume(second.surface), 1.0, 1e-15);
  EXPECT_NEAR(area_in_plane(second.surface, 0.3), 2 * 0.5, 1e-14);
  // The plane separates the slab below it, which the notch then cuts through, from the
  // notched rest: three closed pieces, their volumes the box's parts. (The plane first,
  // then the polygon that spans the slab's section, then those that notch.)
  const SurfaceCut across =
      cut_surface(notched.surface, CuttingPlane(Eigen::Vector3d(0, 0, 0.25), Eigen::Vector3d::UnitZ()));
  EXPECT_EQ(across.facts["pieces_left_whole"], 0);
  const std::vector<SurfaceMesh> pieces = pieces_of(across.surface);
  ASSERT_EQ(pieces.size(), 3u);
  std::vector<double> volumes;
  for (const SurfaceMesh& piece : pieces) {
    EXPECT_TRUE(closed_and_oriented(piece));
    volumes.push_back(surface_volume(piece));
  }
  std::sort(volumes.begin(), volumes.end());
  EXPECT_NEAR(volumes[0], 0.3 * 0.25, 1e-15);
  EXPECT_NEAR(volumes[1], 0.7 * 0.25, 1e-15);
  EXPECT_NEAR(volumes[2], 0.75, 1e-15);
  // Across both notches: the slab below falls into three, each closed.
  const SurfaceCut across_both =
      cut_surface(second.surface, CuttingPlane(Eigen::Vector3d(0, 0, 0.25), Eigen::Vector3d::UnitZ()));
  EXPECT_EQ(across_both.facts["pieces_left_whole"], 0);
  EXPECT_EQ(across_both.facts["blades_cut_again"], 2);
  EXPECT_NEAR(volume_of_closed_pieces(across_both.surface, 4), 1.0, 1e-15);
}

TEST(CutSurface, SeededNotchesAndPlanesOneAfterAnotherKeepEveryPieceClosedAndTheVolume) {
  // 60 boxes, each cut four times: tilted notches from the face z = 0 of random depths
  // (a quarter through the whole section) and planes across, at random. Whatever each cut
  // opens or leaves whole (notches that meet one another), every piece stays closed and
  // the pieces' volumes sum to the box's. A tilted notch's caps once met the piece's cut
  // curve a unit in the last place off, and neither side closed (8 of these sequences).
  // Every cut opens what it crosses: the last piece left whole (box 8's fourth cut, a plane
  // just above a notch's top) was the notch's half of a slab, which the notch again
  // replayed from before it "crossed" by the rounding of its own cut's points, and whose
  // whole-plane split could not close; a blade must now separate a piece by more than that.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0, 1);
  int cuts = 0, left_whole = 0, cut_again = 0;
  for (int box = 0; box < 60; ++box) {
    SurfaceMesh surface = box_surface(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
    for (int cut = 0; cut < 4; ++cut) {
      const Eigen::Vector3d normal(1, 0.3 * (unit(random) - 0.5), 0.3 * (unit(random) - 0.5));
      const double x = 0.1 + 0.8 * unit(random);
      const double depth = unit(random) < 0.25 ? 2.0 : 0.2 + 0.6 * unit(random);
      const bool plane = unit(random) < 0.2;
      const double z = 0.1 + 0.8 * unit(random), tilt_x = 0.1 * unit(random), tilt_y = 0.1 * unit(random);
      const CuttingPlane blade = plane ? CuttingPlane(Eigen::Vector3d(0, 0, z), Eigen::Vector3d(tilt_x, tilt_y, 1))
                                       : square_blade(Eigen::Vector3d(x, 0, 0), normal, -1, 2, -1, depth);
      const SurfaceCut result = cut_surface(surface, blade);
      SCOPED_TRACE(::testing::Message() << "box " << box << ", cut " << cut << ": " << result.facts);
      double volume = 0;
      for (const SurfaceMesh& piece : pieces_of(result.surface)) {
        ASSERT_TRUE(closed_and_oriented(piece));
        volume += surface_volume(piece);
      }
      ASSERT_NEAR(volume, 1.0, 1e-13);
      left_whole += result.facts["pieces_left_whole"].get<int>();
      cut_again += result.facts.contains("blades_cut_again");
      surface = result.surface;
      ++cuts;
    }
  }
  std::cout << cuts << " cuts, " << cut_again << " from before earlier notches, " << left_whole
            << " pieces left whole\n";
  EXPECT_EQ(left_whole, 0);
}

TEST(CutSurface, ThePencilsFiftyCutsEachOpenASoundPieceAndKeepItsSurfaceBounded) {
  // scenes/pencil.json (Kaufmann et al. 2009 §9.4, Fig. 10): 50 planes through points near
  // the tip, each turned about the axis from the last. Their points pile up near the tip:
  // before the cut curve was cleaned, the 14th cut found the pencil intersecting itself and
  // left it whole, and the caps' triangles grew by a third per cut. Each cut must open
  // the pencil (a piece it cannot cut is counted in pieces_left_whole), every piece stay
  // closed, the volume stay the block's, and the pencil keep about its initial size.
  const Scene scene = load_scene(std::filesystem::path(ALTFEM_SOURCE_DIR) / "scenes" / "pencil.json");
  SurfaceMesh surface = *load_scene_geometry(scene).common_surface();
  const Eigen::Index initial_triangles = surface.triangles.rows();
  int cuts = 0;
  for (const SceneEvent& event : scene.events) {
    if (event.kind != EventKind::cut) continue;
    const SurfaceCut cut = cut_surface(surface, event.blade);
    ASSERT_EQ(cut.facts["pieces_left_whole"], 0) << "cut " << cuts;
    ASSERT_GT(cut.facts["cap_triangles"].get<int>(), 0) << "cut " << cuts;
    surface = cut.surface;
    ++cuts;
  }
  ASSERT_EQ(cuts, 50);
  // The block and its 50 chips.
  EXPECT_NEAR(volume_of_closed_pieces(surface, 51), 0.1 * 0.1 * 1.0, 1e-14);
  const std::vector<int> piece_of = surface_vertex_pieces(surface);
  Eigen::Index held = 0;  // the vertex nearest the centre of the held base
  (surface.vertices.rowwise() - Eigen::RowVector3d(0.05, 0.05, 0)).rowwise().squaredNorm().minCoeff(&held);
  const int pencil = piece_of[held];
  const auto pencil_triangles = std::count_if(surface.triangles.col(0).begin(), surface.triangles.col(0).end(),
                                              [&](int vertex) { return piece_of[vertex] == pencil; });
  EXPECT_GT(pencil_triangles, initial_triangles / 2);
  EXPECT_LT(pencil_triangles, 2 * initial_triangles);
}

}  // namespace
}  // namespace altfem
