// A tetrahedral mesh cut by a plane (the finite cell method's embedded tetrahedra after a
// cut event, issue #33): every tetrahedron positively oriented (exact predicate and
// rounded volume), the mesh conforming (an
// unmatched face lies on the cube's boundary or in the blade), the two sides sharing no
// node, volume conserved, each child inside its parent and the volume beyond the blade
// equal to the input tetrahedra clipped by it (clip_tetrahedron: an independent
// construction). Blades through nodes, along edges and in faces, and cuts of cuts, are
// ordinary cases.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cstdio>
#include <map>
#include <set>

#include "shared/geometry/clip_convex.hpp"
#include "shared/geometry/exact_orientation.hpp"
#include "shared/mesh/cut_tetrahedral_mesh.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "tests/unit/mesh/seeded_cut_planes.hpp"

namespace altfem {
namespace {

VolumeMesh cube_tetrahedra(int cells_per_axis) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  return structured_grid(box, Eigen::Vector3i::Constant(cells_per_axis), ElementType::tet4);
}

TetrahedronCorners corners_of(const VolumeMesh& mesh, Eigen::Index cell) {
  TetrahedronCorners corners;
  for (int k = 0; k < 4; ++k) corners.row(k) = mesh.nodes.row(mesh.cells(cell, k));
  return corners;
}

double signed_volume(const TetrahedronCorners& corners) {
  return (corners.row(1) - corners.row(0)).cross(corners.row(2) - corners.row(0)).dot(corners.row(3) - corners.row(0)) /
         6;
}

double signed_distance(const CuttingPlane& plane, const Eigen::Vector3d& x) {
  return (x - plane.point).dot(plane.normal.normalized());
}

// The volume of the input beyond the blade, by clipping each input tetrahedron.
double clipped_volume_beyond(const VolumeMesh& mesh, const CuttingPlane& plane) {
  Eigen::Index smallest = 0;
  plane.normal.cwiseAbs().minCoeff(&smallest);
  const Eigen::Vector3d first = plane.normal.cross(Eigen::Vector3d::Unit(smallest));
  // ClipPlane keeps the side behind (b − a) × (c − a): point that against the normal.
  const ClipPlane clip{plane.point, plane.point + plane.normal.cross(first), plane.point + first};
  double volume = 0;
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell)
    for (const TetrahedronCorners& piece : clip_tetrahedron(corners_of(mesh, cell), {clip}))
      volume += signed_volume(piece);
  return volume;
}

// The faces of one tetrahedron only (sorted corners); a face of three fails the test.
std::vector<std::array<int, 3>> unmatched_faces(const VolumeMesh& mesh) {
  std::map<std::array<int, 3>, int> face_count;
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell)
    for (const auto& face : std::array<std::array<int, 3>, 4>{{{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}}}) {
      std::array<int, 3> key{mesh.cells(cell, face[0]), mesh.cells(cell, face[1]), mesh.cells(cell, face[2])};
      std::sort(key.begin(), key.end());
      ++face_count[key];
    }
  std::vector<std::array<int, 3>> unmatched;
  for (const auto& [face, count] : face_count) {
    EXPECT_LE(count, 2) << "a face of " << count << " tetrahedra";
    if (count == 1) unmatched.push_back(face);
  }
  return unmatched;
}

::testing::AssertionResult is_valid_cut(const VolumeMesh& input, const TetrahedralCut& cut, const CuttingPlane& plane) {
  const VolumeMesh& mesh = cut.mesh;
  if (cut.parent_tetrahedron.size() != static_cast<std::size_t>(mesh.cells.rows()))
    return ::testing::AssertionFailure() << "a parent per tetrahedron";
  double volume = 0, beyond = 0;
  std::vector<int> side_of_node(mesh.nodes.rows(), 0);
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell) {
    const TetrahedronCorners corners = corners_of(mesh, cell);
    const double cell_volume = signed_volume(corners);
    if (orientation_sign(corners.row(1), corners.row(2), corners.row(3), corners.row(0)) != -1 || !(cell_volume > 0))
      return ::testing::AssertionFailure() << "tetrahedron " << cell << ": volume " << cell_volume;
    volume += cell_volume;
    const Eigen::Vector3d centroid = corners.colwise().mean().transpose();
    const int side = signed_distance(plane, centroid) > 0 ? 1 : -1;
    if (side > 0) beyond += cell_volume;
    for (int k = 0; k < 4; ++k) {
      int& node_side = side_of_node[mesh.cells(cell, k)];
      if (node_side == -side)
        return ::testing::AssertionFailure() << "node " << mesh.cells(cell, k) << " on both sides";
      node_side = side;
    }
    // The child lies in its parent: each of its nodes is a parent's node or on a parent's edge.
    const auto parent_row = input.cells.row(cut.parent_tetrahedron[cell]);
    const auto in_parent = [&](int node) { return (parent_row.array() == node).any(); };
    for (int k = 0; k < 4; ++k) {
      const NodeSource& source = cut.node_sources[mesh.cells(cell, k)];
      if (!in_parent(source.first) || !in_parent(source.second))
        return ::testing::AssertionFailure() << "tetrahedron " << cell << " outside its parent";
    }
  }
  const double input_volume = volume_mesh_volume(input);
  if (std::abs(volume - input_volume) > 1e-12 * input_volume)  // the slivers left out: issue #33's bound
    return ::testing::AssertionFailure() << "volume " << volume << " of " << input_volume;
  const double expected_beyond = clipped_volume_beyond(input, plane);
  if (std::abs(beyond - expected_beyond) > 1e-9)
    return ::testing::AssertionFailure() << "volume beyond the blade " << beyond << ", clipped " << expected_beyond;
  const std::vector<std::array<int, 3>> boundary = unmatched_faces(input);
  const std::set<std::array<int, 3>> input_boundary(boundary.begin(), boundary.end());
  for (const auto& face : unmatched_faces(mesh)) {
    const bool on_blade = std::all_of(face.begin(), face.end(), [&](int node) {
      return std::abs(signed_distance(plane, mesh.nodes.row(node).transpose())) <= 1e-12;
    });
    // In a boundary face of the input: its nodes are that face's nodes or on its edges.
    std::set<int> sources;
    for (const int node : face) sources.insert({cut.node_sources[node].first, cut.node_sources[node].second});
    std::array<int, 3> source_face{-1, -1, -1};
    if (sources.size() == 3) std::copy(sources.begin(), sources.end(), source_face.begin());
    const bool on_boundary = input_boundary.count(source_face) > 0;
    // Left-out slivers leave their neighbours' faces unmatched (in pairs a sliver apart).
    // Left-out slivers leave their neighbours' faces unmatched (in pairs a sliver apart).
    if (!on_boundary && !on_blade && cut.flat_tetrahedra == 0)
      return ::testing::AssertionFailure() << "an unmatched face inside: the cut is not conforming";
  }
  for (Eigen::Index node = 0; node < mesh.nodes.rows(); ++node) {
    const NodeSource& source = cut.node_sources[node];
    const Eigen::RowVector3d placed =
        (1 - source.weight) * input.nodes.row(source.first) + source.weight * input.nodes.row(source.second);
    if ((mesh.nodes.row(node) - placed).norm() > 1e-15)
      return ::testing::AssertionFailure() << "node " << node << " is not where its sources put it";
  }
  return ::testing::AssertionSuccess();
}

TEST(CutTetrahedralMesh, AnAxisPlaneThroughCellsSplitsTheCrossedTetrahedra) {
  const VolumeMesh mesh = cube_tetrahedra(2);
  const CuttingPlane plane{Eigen::Vector3d(0.3, 0, 0), Eigen::Vector3d::UnitX()};
  const TetrahedralCut cut = cut_tetrahedral_mesh(mesh, plane);
  EXPECT_EQ(cut.crossed_tetrahedra, mesh.cells.rows() / 2);  // every tetrahedron of the slab x < 0.5
  EXPECT_EQ(cut.separated_faces, 0);
  EXPECT_EQ(cut.flat_tetrahedra, 0);
  EXPECT_GT(cut.mesh.cells.rows(), mesh.cells.rows() + cut.crossed_tetrahedra);
  EXPECT_TRUE(is_valid_cut(mesh, cut, plane));
}

TEST(CutTetrahedralMesh, APlaneAlongFacesKeepsEveryRowAndSeparatesTheSides) {
  const VolumeMesh mesh = cube_tetrahedra(2);
  const CuttingPlane plane{Eigen::Vector3d(0.5, 0.5, 0.5), Eigen::Vector3d(-3, 0, 0)};
  const TetrahedralCut cut = cut_tetrahedral_mesh(mesh, plane);
  EXPECT_EQ(cut.crossed_tetrahedra, 0);
  EXPECT_EQ(cut.duplicated_nodes, 9);  // the 3 × 3 grid nodes at x = 0.5
  EXPECT_EQ(cut.separated_faces, 8);   // the 2 × 2 grid faces at x = 0.5, two triangles each
  ASSERT_EQ(cut.mesh.cells.rows(), mesh.cells.rows());
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell) {
    ASSERT_EQ(cut.parent_tetrahedron[cell], cell);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(cut.node_sources[cut.mesh.cells(cell, k)].first, mesh.cells(cell, k));
  }
  EXPECT_TRUE(is_valid_cut(mesh, cut, plane));
}

// 200 seeded planes of every degenerate kind on a 3³ grid of Kuhn tetrahedra, each
// valid; and every thirteenth of the first 200 (every kind in turn) made on the previous one's result, so cuts of cuts
// (pieces of pieces, copies of copies) are exercised too.
TEST(CutTetrahedralMesh, SeededPlanesAndCutsOfCutsGiveValidMeshes) {
  const VolumeMesh grid = cube_tetrahedra(3);
  VolumeMesh chained = grid;
  int trial = 0, flat = 0;
  for (const CuttingPlane& plane : seeded_cut_planes(grid.nodes, 200)) {
    SCOPED_TRACE(::testing::Message() << "trial " << trial << ": point " << plane.point.transpose() << ", normal "
                                      << plane.normal.transpose());
    TetrahedralCut cut;
    ASSERT_NO_THROW(cut = cut_tetrahedral_mesh(grid, plane));
    ASSERT_TRUE(is_valid_cut(grid, cut, plane));
    flat += cut.flat_tetrahedra;
    if (trial++ % 13 == 0 && trial <= 200) {
      ASSERT_NO_THROW(cut = cut_tetrahedral_mesh(chained, plane));
      ASSERT_TRUE(is_valid_cut(chained, cut, plane));
      flat += cut.flat_tetrahedra;
      chained = cut.mesh;
    }
  }
  EXPECT_GT(chained.cells.rows(), 4 * grid.cells.rows());
  std::printf("%d cuts, %lld tetrahedra after the chain, %d flat tetrahedra left out\n", trial,
              static_cast<long long>(chained.cells.rows()), flat);
}

TEST(CutTetrahedralMesh, RefusesHexahedra) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  EXPECT_THROW(cut_tetrahedral_mesh(structured_grid(box, Eigen::Vector3i::Ones(), ElementType::hex8),
                                    {Eigen::Vector3d::Constant(0.5), Eigen::Vector3d::UnitX()}),
               std::invalid_argument);
}

}  // namespace
}  // namespace altfem
