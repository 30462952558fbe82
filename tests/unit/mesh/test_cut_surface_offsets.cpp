// The embedding offsets cut_surface gives the vertices of its cuts (issue #33): each
// copy of a cut point reads its field a hair inside its own side, and keeps that offset
// through later cuts that leave its piece whole.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "shared/mesh/cut_surface.hpp"
#include "shared/mesh/mesh_components.hpp"
#include "tests/unit/surfaces.hpp"

namespace altfem {
namespace {

using test::box_surface;

TEST(CutSurface, EachCopyOfACutPointReadsItsFieldInsideItsOwnSide) {
  const SurfaceMesh box = box_surface(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  const SurfaceCut cut = cut_surface(box, CuttingPlane(Eigen::Vector3d(0.5, 0, 0), Eigen::Vector3d::UnitX()));
  const Eigen::MatrixXd points = embedding_points(cut.surface);
  const double hair = 1e-7 * std::sqrt(3.0);
  // Which side a vertex bounds: where its piece's vertices lie on average.
  const std::vector<int> piece_of = surface_vertex_pieces(cut.surface);
  std::map<int, double> x_sum_of;
  for (Eigen::Index v = 0; v < cut.surface.vertices.rows(); ++v)
    x_sum_of[piece_of[v]] += cut.surface.vertices(v, 0) - 0.5;
  int on_cut = 0;
  for (Eigen::Index v = 0; v < cut.surface.vertices.rows(); ++v) {
    if (std::abs(cut.surface.vertices(v, 0) - 0.5) > 1e-12) {
      EXPECT_EQ(points.row(v), cut.surface.vertices.row(v)) << "vertex " << v;
      continue;
    }
    ++on_cut;
    const double side = x_sum_of[piece_of[v]];
    ASSERT_NE(side, 0) << "vertex " << v;
    const Eigen::Vector3d offset = points.row(v) - cut.surface.vertices.row(v);
    EXPECT_NEAR(offset.norm(), hair, 1e-8 * hair);
    EXPECT_GT(offset.x() * side, 0) << "vertex " << v;
    // Into the box, not out of it.
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_GE(points(v, axis), 0.0);
      EXPECT_LE(points(v, axis), 1.0);
    }
  }
  EXPECT_GE(on_cut, 8);  // the four corners of the section, each twice, at least
}

TEST(CutSurface, ACutKeepsTheOffsetsOfThePiecesItLeavesWhole) {
  // x = 0.5, then x = 0.8: the side x < 0.5 keeps its cap's offsets bit for bit, and the
  // side the second plane opens still reads its first cap from inside.
  const SurfaceMesh box = box_surface(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  const SurfaceCut first = cut_surface(box, CuttingPlane(Eigen::Vector3d(0.5, 0, 0), Eigen::Vector3d::UnitX()));
  const SurfaceCut second =
      cut_surface(first.surface, CuttingPlane(Eigen::Vector3d(0.8, 0, 0), Eigen::Vector3d::UnitX()));
  const double hair = 1e-7 * std::sqrt(3.0);
  const std::vector<int> piece_of = surface_vertex_pieces(second.surface);
  std::map<int, double> x_sum_of;
  for (Eigen::Index v = 0; v < second.surface.vertices.rows(); ++v)
    x_sum_of[piece_of[v]] += second.surface.vertices(v, 0) - 0.5;
  int kept = 0, renewed = 0;
  for (Eigen::Index v = 0; v < first.surface.vertices.rows(); ++v) {
    if (std::abs(first.surface.vertices(v, 0) - 0.5) > 1e-12) continue;
    const Eigen::RowVector3d offset = second.surface.embedding_offsets.row(v);
    if (x_sum_of[piece_of[v]] < 0) {
      EXPECT_EQ(offset, first.surface.embedding_offsets.row(v)) << "vertex " << v;
      EXPECT_LT(offset.x(), 0) << "vertex " << v;
      ++kept;
    } else {
      EXPECT_NEAR(offset.norm(), hair, 1e-8 * hair) << "vertex " << v;
      EXPECT_GT(offset.x(), 0) << "vertex " << v;
      ++renewed;
    }
  }
  EXPECT_GE(kept, 4);
  EXPECT_GE(renewed, 4);
}

}  // namespace
}  // namespace altfem
