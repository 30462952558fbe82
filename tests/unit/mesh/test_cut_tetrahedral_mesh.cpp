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
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "shared/geometry/clip_convex.hpp"
#include "shared/geometry/exact_orientation.hpp"
#include "shared/mesh/cut_tetrahedral_mesh.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
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

// Whether `point` lies on one of the triangles `faces` of `mesh` (to 1e-12).
bool on_triangles(const VolumeMesh& mesh, const std::vector<std::array<int, 3>>& faces, const Eigen::Vector3d& point) {
  for (const auto& face : faces) {
    const Eigen::Vector3d a = mesh.nodes.row(face[0]), b = mesh.nodes.row(face[1]), c = mesh.nodes.row(face[2]);
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    const double area2 = normal.squaredNorm();
    if (std::abs((point - a).dot(normal)) > 1e-12 * std::sqrt(area2)) continue;
    const double u = (c - b).cross(point - b).dot(normal) / area2, v = (a - c).cross(point - c).dot(normal) / area2;
    if (u >= -1e-12 && v >= -1e-12 && u + v <= 1 + 1e-12) return true;
  }
  return false;
}

::testing::AssertionResult is_valid_cut(const FragmentedTetrahedra& input, const TetrahedralCut& cut,
                                        const CuttingPlane& plane) {
  const VolumeMesh& mesh = cut.result.mesh;
  if (cut.parent_fragment.size() != static_cast<std::size_t>(cut.result.fragment_count()))
    return ::testing::AssertionFailure() << "a parent per fragment";
  std::vector<std::set<int>> fragment_nodes(static_cast<std::size_t>(input.fragment_count()));
  if (input.fragments.cell_count() > 0) {  // the fragment's corners: its slivers' too
    for (int fragment = 0; fragment < input.fragments.cell_count(); ++fragment)
      for (const int face : input.fragments.cell_faces[fragment])
        fragment_nodes[fragment].insert(input.fragments.faces[face].begin(), input.fragments.faces[face].end());
  } else {
    for (Eigen::Index cell = 0; cell < input.mesh.cells.rows(); ++cell)
      for (int k = 0; k < 4; ++k) fragment_nodes[cell].insert(input.mesh.cells(cell, k));
  }
  std::vector<bool> on_a_fragment_face;  // else a node inside a fragment: a cone's centroid
  if (input.fragments.cell_count() > 0) {
    on_a_fragment_face.assign(static_cast<std::size_t>(input.mesh.nodes.rows()), false);
    for (const std::vector<int>& loop : input.fragments.faces)
      for (const int node : loop) on_a_fragment_face[node] = true;
  }
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
    for (int k = 0; k < 4 && !plane.piece_at; ++k) {
      int& node_side = side_of_node[mesh.cells(cell, k)];
      if (node_side == -side)
        return ::testing::AssertionFailure() << "node " << mesh.cells(cell, k) << " on both sides";
      node_side = side;
    }
    // The child lies in its parent fragment (convex): each of its nodes is a node of the
    // parent or on a segment between two.
    const std::set<int>& parent_nodes =
        fragment_nodes[cut.parent_fragment[cut.result.fragment_of(static_cast<int>(cell))]];
    for (int k = 0; k < 4; ++k) {
      // A centroid the cones added (cone_tetrahedra.hpp) lies inside its piece.
      if (mesh.cells(cell, k) >= static_cast<int>(cut.node_sources.size())) continue;
      const NodeSource& source = cut.node_sources[mesh.cells(cell, k)];
      if (source.weight == 0 && !on_a_fragment_face.empty() && !on_a_fragment_face[source.first])
        continue;  // one before
      if (!parent_nodes.count(source.first) || !parent_nodes.count(source.second))
        return ::testing::AssertionFailure() << "tetrahedron " << cell << " outside its parent";
    }
  }
  const double input_volume = volume_mesh_volume(input.mesh);
  if (std::abs(volume - input_volume) > 1e-12 * input_volume)  // the slivers left out: issue #33's bound
    return ::testing::AssertionFailure() << "volume " << volume << " of " << input_volume;
  const double expected_beyond = clipped_volume_beyond(input.mesh, plane);
  if (!plane.piece_at && std::abs(beyond - expected_beyond) > 1e-9)
    return ::testing::AssertionFailure() << "volume beyond the blade " << beyond << ", clipped " << expected_beyond;
  const std::vector<std::array<int, 3>> input_boundary = unmatched_faces(input.mesh);
  for (const auto& face : unmatched_faces(mesh)) {
    const bool on_blade = std::all_of(face.begin(), face.end(), [&](int node) {
      return std::abs(signed_distance(plane, mesh.nodes.row(node).transpose())) <= 1e-12;
    });
    // Left-out slivers leave their neighbours' faces unmatched (in pairs a sliver apart).
    if (on_blade || cut.flat_tetrahedra > 0) continue;
    // On the input's boundary: one of its boundary triangles (an earlier cut's slivers
    // leave some of those nearly flat), or within one.
    std::array<int, 3> source_face{};
    const auto sources = static_cast<int>(cut.node_sources.size());  // the cones' centroids after them
    for (int k = 0; k < 3; ++k)
      source_face[k] =
          face[k] < sources && cut.node_sources[face[k]].weight == 0 ? cut.node_sources[face[k]].first : -1;
    std::sort(source_face.begin(), source_face.end());
    const Eigen::Vector3d centroid =
        (mesh.nodes.row(face[0]) + mesh.nodes.row(face[1]) + mesh.nodes.row(face[2])).transpose() / 3;
    if (!std::binary_search(input_boundary.begin(), input_boundary.end(), source_face) &&
        !on_triangles(input.mesh, input_boundary, centroid))
      return ::testing::AssertionFailure() << "an unmatched face inside: the cut is not conforming";
  }
  for (Eigen::Index node = 0; node < static_cast<Eigen::Index>(cut.node_sources.size()); ++node) {
    const NodeSource& source = cut.node_sources[node];
    const Eigen::RowVector3d placed =
        (1 - source.weight) * input.mesh.nodes.row(source.first) + source.weight * input.mesh.nodes.row(source.second);
    if ((mesh.nodes.row(node) - placed).norm() > 1e-15)
      return ::testing::AssertionFailure() << "node " << node << " is not where its sources put it";
  }
  return ::testing::AssertionSuccess();
}

TEST(CutTetrahedralMesh, AnAxisPlaneThroughCellsSplitsTheCrossedTetrahedra) {
  const VolumeMesh mesh = cube_tetrahedra(2);
  const CuttingPlane plane{Eigen::Vector3d(0.3, 0, 0), Eigen::Vector3d::UnitX()};
  const TetrahedralCut cut = cut_tetrahedral_mesh({mesh}, plane);
  EXPECT_EQ(cut.crossed_fragments, mesh.cells.rows() / 2);  // every tetrahedron of the slab x < 0.5
  EXPECT_EQ(cut.separated_faces, 0);
  EXPECT_EQ(cut.flat_tetrahedra, 0);
  EXPECT_EQ(cut.result.fragment_count(), mesh.cells.rows() + cut.crossed_fragments);
  EXPECT_GT(cut.result.mesh.cells.rows(), mesh.cells.rows() + cut.crossed_fragments);
  EXPECT_TRUE(is_valid_cut({mesh}, cut, plane));
}

TEST(CutTetrahedralMesh, APlaneAlongFacesKeepsEveryRowAndSeparatesTheSides) {
  const VolumeMesh mesh = cube_tetrahedra(2);
  const CuttingPlane plane{Eigen::Vector3d(0.5, 0.5, 0.5), Eigen::Vector3d(-3, 0, 0)};
  const TetrahedralCut cut = cut_tetrahedral_mesh({mesh}, plane);
  EXPECT_EQ(cut.crossed_fragments, 0);
  EXPECT_EQ(cut.duplicated_nodes, 9);  // the 3 × 3 grid nodes at x = 0.5
  EXPECT_EQ(cut.separated_faces, 8);   // the 2 × 2 grid faces at x = 0.5, two triangles each
  ASSERT_EQ(cut.result.mesh.cells.rows(), mesh.cells.rows());
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell) {
    ASSERT_EQ(cut.parent_fragment[cut.result.fragment_of(static_cast<int>(cell))], cell);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(cut.node_sources[cut.result.mesh.cells(cell, k)].first, mesh.cells(cell, k));
  }
  EXPECT_TRUE(is_valid_cut({mesh}, cut, plane));
}

// 200 seeded planes of every degenerate kind on a 3³ grid of Kuhn tetrahedra, each
// valid; and every thirteenth of the first 200 (every kind in turn) made on the previous one's result, so cuts of cuts
// (pieces of pieces, copies of copies) are exercised too.
TEST(CutTetrahedralMesh, SeededPlanesAndCutsOfCutsGiveValidMeshes) {
  const VolumeMesh grid = cube_tetrahedra(3);
  FragmentedTetrahedra chained{grid};
  int trial = 0, flat = 0;
  for (const CuttingPlane& plane : seeded_cut_planes(grid.nodes, 200)) {
    SCOPED_TRACE(::testing::Message() << "trial " << trial << ": point " << plane.point.transpose() << ", normal "
                                      << plane.normal.transpose());
    TetrahedralCut cut;
    ASSERT_NO_THROW(cut = cut_tetrahedral_mesh({grid}, plane));
    ASSERT_TRUE(is_valid_cut({grid}, cut, plane));
    flat += cut.flat_tetrahedra;
    if (trial++ % 13 == 0 && trial <= 200) {
      ASSERT_NO_THROW(cut = cut_tetrahedral_mesh(chained, plane));
      ASSERT_TRUE(is_valid_cut(chained, cut, plane));
      flat += cut.flat_tetrahedra;
      chained = cut.result;
    }
  }
  EXPECT_GT(chained.mesh.cells.rows(), 4 * grid.cells.rows());
  std::printf("%d cuts, %lld tetrahedra in %d fragments after the chain, %d flat tetrahedra left out\n", trial,
              static_cast<long long>(chained.mesh.cells.rows()), chained.fragment_count(), flat);
}

// Kaufmann et al. 2009 Fig. 10's pencil on a tetrahedral bar: 30 planes through its axis
// near the tip, tilted 14° and turned a little more than a seventh of a turn each, each
// cutting the piece that holds the base. Every cut is valid, and the tetrahedra grow only
// linearly: the piece kept is the bar cut by half-spaces, so each tetrahedron of the bar
// has one convex fragment in it, and a cut crosses at most one fragment per tetrahedron of
// the bar; each becomes two, split into a few tetrahedra afresh. Cut as tetrahedra (each
// piece's tetrahedra cut again) the fcm pencil's grew 27-fold in 12 cuts, the later cuts
// crossing ever more of them.
void expect_repeated_cuts_keep_the_tetrahedra_few(FragmentedTetrahedra pencil, std::size_t cell_faces, int cuts,
                                                  int planned) {
  const auto bar_fragments = static_cast<long long>(pencil.fragment_count());
  long long crossed = 0;
  for (int k = 0; k < cuts; ++k) {
    const double turn = 2 * M_PI * k * (1.0 / 7 + 0.013), depth = 0.02 + 0.06 * k / (planned - 1);
    CuttingPlane plane{Eigen::Vector3d(0.05, 0.05, 1 - depth),
                       Eigen::Vector3d(std::cos(turn), std::sin(turn), std::tan(14 * M_PI / 180))};
    plane.piece_at = Eigen::Vector3d(0.05, 0.05, 0);
    SCOPED_TRACE(::testing::Message() << "cut " << k);
    TetrahedralCut cut;
    ASSERT_NO_THROW(cut = cut_tetrahedral_mesh(pencil, plane));
    ASSERT_TRUE(is_valid_cut(pencil, cut, plane));
    ASSERT_EQ(cut.flat_tetrahedra, 0);
    ASSERT_LE(cut.crossed_fragments, bar_fragments);
    crossed += cut.crossed_fragments;
    pencil = std::move(cut.result);
  }
  EXPECT_EQ(pencil.fragment_count(), bar_fragments + crossed);
  // A fragment is a cell of the bar cut by half-spaces: a face per blade at most, beside
  // the cell's own (the polygons of the cut fragments, however their tetrahedra split them).
  std::size_t most_faces = 0;
  for (int fragment = 0; fragment < pencil.fragments.cell_count(); ++fragment)
    most_faces = std::max(most_faces, pencil.fragments.cell_faces[fragment].size());
  EXPECT_LE(most_faces, cell_faces + static_cast<std::size_t>(cuts));
  std::printf("%lld tetrahedra in %d fragments (at most %zu faces) after %d cuts of %lld fragments\n",
              static_cast<long long>(pencil.mesh.cells.rows()), pencil.fragment_count(), most_faces, cuts,
              bar_fragments);
}

TEST(CutTetrahedralMesh, RepeatedCutsOfAPencilKeepTheTetrahedraFew) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d(0.1, 0.1, 1));
  expect_repeated_cuts_keep_the_tetrahedra_few({structured_grid(box, Eigen::Vector3i(2, 2, 10), ElementType::tet4)}, 4,
                                               30, 30);
}

// fem's pencil: its hexahedra as fragments, whose square faces lie in one plane with their
// neighbours', so a cut puts nodes in the middle of their edges (a fan from the lowest
// node would have triangles of no area there). Split about a centroid, such a face became
// triangles in the fragments, each crossed by later cuts into more: the faces of the cut
// pieces grew about 1.4-fold a cut, to 75,000 in one piece after 55 (and 218,000
// tetrahedra in all). Their ears keep each face one polygon.
TEST(CutTetrahedralMesh, RepeatedCutsOfAHexahedralPencilKeepTheTetrahedraFew) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d(0.1, 0.1, 1));
  const VolumeMesh bar = structured_grid(box, Eigen::Vector3i(1, 1, 4), ElementType::hex8);
  expect_repeated_cuts_keep_the_tetrahedra_few(convex_cells_as_fragments(polyhedral_mesh_from_volume_mesh(bar)), 6, 60,
                                               200);
}

// A grid's hexahedra as fragments (fem's material before its first cut): 6 tetrahedra
// each, a cone from the first corner by position, conforming without a centroid (every
// face fanned from its own first corner), filling the cube; a cut through them is valid
// and splits each crossed hexahedron into two fragments.
TEST(CutTetrahedralMesh, HexahedraAsFragmentsConformAndCutWhole) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  const VolumeMesh grid = structured_grid(box, Eigen::Vector3i::Constant(3), ElementType::hex8);
  const FragmentedTetrahedra hexahedra = convex_cells_as_fragments(polyhedral_mesh_from_volume_mesh(grid));
  ASSERT_EQ(hexahedra.fragment_count(), 27);
  ASSERT_EQ(hexahedra.mesh.cells.rows(), 27 * 6);
  EXPECT_NEAR(volume_mesh_volume(hexahedra.mesh), 1.0, 1e-14);
  EXPECT_EQ(unmatched_faces(hexahedra.mesh).size(), 6u * 9 * 2);  // the cube's 54 squares, 2 triangles each
  const CuttingPlane plane{Eigen::Vector3d(0.4, 0.5, 0.5), Eigen::Vector3d(1, 0.3, 0.2)};
  const TetrahedralCut cut = cut_tetrahedral_mesh(hexahedra, plane);
  EXPECT_GT(cut.crossed_fragments, 0);
  EXPECT_EQ(cut.result.fragment_count(), 27 + cut.crossed_fragments);
  EXPECT_TRUE(is_valid_cut(hexahedra, cut, plane));
}

TEST(CutTetrahedralMesh, RefusesHexahedra) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  EXPECT_THROW(cut_tetrahedral_mesh({structured_grid(box, Eigen::Vector3i::Ones(), ElementType::hex8)},
                                    {Eigen::Vector3d::Constant(0.5), Eigen::Vector3d::UnitX()}),
               std::invalid_argument);
}

}  // namespace
}  // namespace altfem
