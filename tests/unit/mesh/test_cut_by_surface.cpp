// Surface blades (issue #33): a triangulated blade separates exactly its triangles. Two
// triangles spanning a section cut as the plane does; a V of four triangles whose fold
// lies on a grid plane cuts out the wedge between them, of the exact volume, from
// polyhedral cells and from tetrahedra (which stay conforming: their boundary's area is
// the body's plus twice the blade's inside it); a blade ending inside leaves one piece;
// seeded bent blades give closed cells of positive volume and keep the volume, and a
// plane cuts the cells they leave again; a closed blade wholly inside cuts its exact
// volume out, no cell holding nodes a rounding apart, and opens the surface.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <random>

#include "shared/mesh/convex_cell.hpp"
#include "shared/mesh/cut_by_surface.hpp"
#include "shared/mesh/cut_surface.hpp"
#include "shared/mesh/cut_tetrahedral_mesh.hpp"
#include "shared/mesh/disjoint_sets.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "tests/unit/mesh/ball_blade.hpp"
#include "tests/unit/mesh/every_cell_closed.hpp"
#include "tests/unit/mesh/surface_pieces.hpp"
#include "tests/unit/mesh/tetrahedral_pieces.hpp"
#include "tests/unit/surfaces.hpp"

namespace altfem {
namespace {

using test::tetrahedral_pieces;
using test::TetrahedralPieces;

VolumeMesh unit_cube_grid(ElementType type, int cells_per_axis) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  return structured_grid(box, Eigen::Vector3i::Constant(cells_per_axis), type);
}

// A blade of quadrilaterals, each corners (a, b, c, d) as the triangles (a, b, c), (a, c, d).
SurfaceBlade blade_of_quadrilaterals(const std::vector<std::array<Eigen::Vector3d, 4>>& quadrilaterals) {
  SurfaceBlade blade;
  blade.vertices.resize(4 * static_cast<Eigen::Index>(quadrilaterals.size()), 3);
  blade.triangles.resize(2 * static_cast<Eigen::Index>(quadrilaterals.size()), 3);
  for (std::size_t q = 0; q < quadrilaterals.size(); ++q) {
    const int first = 4 * static_cast<int>(q);
    for (int k = 0; k < 4; ++k) blade.vertices.row(first + k) = quadrilaterals[q][k];
    blade.triangles.row(2 * static_cast<Eigen::Index>(q)) << first, first + 1, first + 2;
    blade.triangles.row(2 * static_cast<Eigen::Index>(q) + 1) << first, first + 2, first + 3;
  }
  return blade;
}

// The V whose fold runs along x at (y, z) = (0.5, 0.3), its arms rising to z = 1.2 at y =
// 0.1 and y = 0.9, over x ∈ [−1, 2]. It cuts from the unit cube the wedge of the triangle
// (0.5, 0.3), (0.5 ∓ 0.4 · 7/9, 1) in (y, z), of volume ½ · 0.8 · 7/9 · 0.7.
SurfaceBlade v_blade() {
  const auto at = [](double x, double y, double z) { return Eigen::Vector3d(x, y, z); };
  return blade_of_quadrilaterals({{at(-1, 0.5, 0.3), at(2, 0.5, 0.3), at(2, 0.1, 1.2), at(-1, 0.1, 1.2)},
                                  {at(2, 0.5, 0.3), at(-1, 0.5, 0.3), at(-1, 0.9, 1.2), at(2, 0.9, 1.2)}});
}
constexpr double wedge_volume = 0.5 * 0.8 * 7.0 / 9.0 * 0.7;

// Per connected piece of `mesh` (cells joined through interior faces), its volume, smallest first.
std::vector<double> piece_volumes(const PolyhedralMesh& mesh) {
  DisjointSets pieces(mesh.cell_count());
  for (int face = 0; face < mesh.face_count(); ++face)
    if (mesh.face_cells(face, 1) >= 0) pieces.join(mesh.face_cells(face, 0), mesh.face_cells(face, 1));
  std::map<int, double> volume_of;
  for (int cell = 0; cell < mesh.cell_count(); ++cell) volume_of[pieces.find(cell)] += mesh.cell_volumes(cell);
  std::vector<double> volumes;
  for (const auto& [root, volume] : volume_of) volumes.push_back(volume);
  std::sort(volumes.begin(), volumes.end());
  return volumes;
}

TEST(CutBySurface, TwoTrianglesSpanningTheSectionCutAsThePlane) {
  const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(unit_cube_grid(ElementType::hex8, 3));
  const auto at = [](double y, double z) { return Eigen::Vector3d(0.4, y, z); };
  const PolyhedralCut cut = cut_polyhedral_mesh_by_surface(
      mesh, blade_of_quadrilaterals({{at(-1, -1), at(2, -1), at(2, 2), at(-1, 2)}}), true);
  EXPECT_TRUE(every_cell_closed(cut.mesh));
  EXPECT_EQ(cut.crossed_cells, 9);
  const std::vector<double> volumes = piece_volumes(cut.mesh);
  ASSERT_EQ(volumes.size(), 2u);
  EXPECT_NEAR(volumes[0], 0.4, 1e-14);
  EXPECT_NEAR(volumes[1], 0.6, 1e-14);
  EXPECT_GT(cut.mesh.cell_volumes.minCoeff(), 0);
}

// The area of the faces that only one cell holds.
double boundary_area(const PolyhedralMesh& mesh) {
  double area = 0;
  for (int face = 0; face < mesh.face_count(); ++face)
    if (mesh.face_cells(face, 1) < 0) area += mesh.face_areas(face);
  return area;
}

// A flat notch of two triangles over [−0.2, 0.5]², at heights between grid planes, in a
// 3 × 3 × 3 hexahedral grid: its corner (0.5, 0.5) inside a cell leaves of that cell's
// section, once the pieces each side are joined, an L whose centroid is that corner, so the
// L's triangles about it were flat and fcm's and fem's fragments open there (hanging faces,
// 0.042 of area). Opened, the notch adds both sides of its ½ × ½ inside the cube, to the
// cells and to the tetrahedra alike.
TEST(CutBySurface, ANotchsCornerInsideASectionLeavesTheTetrahedraConforming) {
  const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(unit_cube_grid(ElementType::hex8, 3));
  const FragmentedTetrahedra fragments = convex_cells_as_fragments(mesh);
  for (const double z : {0.5, 0.543, 0.27}) {
    const auto at = [z](double x, double y) { return Eigen::Vector3d(x, y, z); };
    const SurfaceBlade blade = blade_of_quadrilaterals({{at(-0.2, -0.2), at(0.5, -0.2), at(0.5, 0.5), at(-0.2, 0.5)}});
    const PolyhedralCut cut = cut_polyhedral_mesh_by_surface(mesh, blade, true);
    EXPECT_TRUE(every_cell_closed(cut.mesh)) << z;
    EXPECT_NEAR(boundary_area(cut.mesh), 6.5, 1e-13) << z;
    const TetrahedralCut tetrahedra = cut_tetrahedral_mesh_by_surface(fragments, blade);
    EXPECT_EQ(tetrahedra.flat_tetrahedra, 0) << z;
    EXPECT_NEAR(tetrahedral_pieces(tetrahedra.result.mesh).boundary_area, 6.5, 1e-13) << z;
  }
}

TEST(CutBySurface, AVCutsItsWedgeOutOfPolyhedralCells) {
  for (const ElementType type : {ElementType::hex8, ElementType::tet4}) {
    const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(unit_cube_grid(type, 4));
    const PolyhedralCut cut = cut_polyhedral_mesh_by_surface(mesh, v_blade(), true);
    EXPECT_TRUE(every_cell_closed(cut.mesh));
    EXPECT_GT(cut.mesh.cell_volumes.minCoeff(), 0);
    EXPECT_GT(cut.duplicated_nodes, 0);
    EXPECT_TRUE(cut.node_sources.empty());
    const std::vector<double> volumes = piece_volumes(cut.mesh);
    ASSERT_EQ(volumes.size(), 2u) << element_name(type);
    EXPECT_NEAR(volumes[0], wedge_volume, 1e-13);
    EXPECT_NEAR(volumes[0] + volumes[1], 1.0, 1e-13);
    // The pieces of a cell that the V does not part are joined again: a cell the V
    // crosses is its wedge's part and the rest.
    std::vector<int> pieces_of(static_cast<std::size_t>(mesh.cell_count()), 0);
    for (const int parent : cut.parent_cell) ++pieces_of[parent];
    EXPECT_EQ(*std::max_element(pieces_of.begin(), pieces_of.end()), 2);
    // The cells the blade stays away from keep their kind and volume.
    int untouched = 0;
    for (int piece = 0; piece < cut.mesh.cell_count(); ++piece) {
      const int parent = cut.parent_cell[piece];
      if (cut.mesh.cell_kinds[piece] != mesh.cell_kinds[parent]) continue;
      ++untouched;
      EXPECT_DOUBLE_EQ(cut.mesh.cell_volumes(piece), mesh.cell_volumes(parent));
    }
    EXPECT_GT(untouched, 0);
  }
}

TEST(CutBySurface, AVCutsItsWedgeOutOfTetrahedraThatStayConforming) {
  const auto at = [](double y, double z) { return std::hypot(y, z); };
  const double arm = at(0.4 * 7.0 / 9.0, 0.7);  // each arm's length in the cube (y, z)
  for (const bool hexahedral_fragments : {false, true}) {
    const FragmentedTetrahedra input =
        hexahedral_fragments
            ? convex_cells_as_fragments(polyhedral_mesh_from_volume_mesh(unit_cube_grid(ElementType::hex8, 3)))
            : FragmentedTetrahedra{unit_cube_grid(ElementType::tet4, 3)};
    const TetrahedralCut cut = cut_tetrahedral_mesh_by_surface(input, v_blade());
    const TetrahedralPieces pieces = tetrahedral_pieces(cut.result.mesh);
    ASSERT_EQ(pieces.volumes.size(), 2u) << hexahedral_fragments;
    EXPECT_NEAR(pieces.volumes[0], wedge_volume, 1e-13);
    EXPECT_NEAR(pieces.volumes[0] + pieces.volumes[1], 1.0, 1e-13);
    // A face held once that is not the cube's or the blade's (a hanging one) adds area.
    EXPECT_NEAR(pieces.boundary_area, 6 + 4 * arm, 1e-12);
    EXPECT_EQ(static_cast<int>(cut.parent_fragment.size()), cut.result.fragment_count());
  }
}

TEST(CutBySurface, ABladeEndingInsideLeavesOnePiece) {
  const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(unit_cube_grid(ElementType::hex8, 4));
  // Half the V's left arm: from the top down to z = 0.75, so it ends between grid planes.
  const auto at = [](double x, double y, double z) { return Eigen::Vector3d(x, y, z); };
  const double y_top = 0.5 - 0.4 * (1.2 - 0.75) / 0.9;
  const SurfaceBlade notch =
      blade_of_quadrilaterals({{at(-1, y_top, 0.75), at(2, y_top, 0.75), at(2, 0.1, 1.2), at(-1, 0.1, 1.2)}});
  const PolyhedralCut cut = cut_polyhedral_mesh_by_surface(mesh, notch, true);
  EXPECT_TRUE(every_cell_closed(cut.mesh));
  EXPECT_GT(cut.separated_faces, 0);
  EXPECT_GT(cut.duplicated_nodes, 0);
  const std::vector<double> volumes = piece_volumes(cut.mesh);
  ASSERT_EQ(volumes.size(), 1u);
  EXPECT_NEAR(volumes[0], 1.0, 1e-13);
}

// A bent blade over the cube: a 3 × 3 grid of points from −0.2 to 1.2 in x and y, at
// `heights` (row by row), each of its 2 × 2 quadrilaterals two triangles.
SurfaceBlade bent_blade(const std::array<double, 9>& heights) {
  SurfaceBlade blade;
  blade.vertices.resize(9, 3);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) blade.vertices.row(3 * i + j) << -0.2 + 0.7 * i, -0.2 + 0.7 * j, heights[3 * i + j];
  blade.triangles.resize(8, 3);
  for (int i = 0, t = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const int corner = 3 * i + j;
      blade.triangles.row(t++) << corner, corner + 3, corner + 4;
      blade.triangles.row(t++) << corner, corner + 4, corner + 1;
    }
  return blade;
}

// `blade` through a 3 × 3 × 3 grid of `type`, once by polyhedral cells and once by
// tetrahedra, which stay conforming: their boundary is the cells' (the cube's and both
// sides of the blade). The blade parts the cube in two; `label` names it in failures.
void expect_bent_blade_parts_the_cube(const SurfaceBlade& blade, ElementType type, const std::string& label) {
  const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(unit_cube_grid(type, 3));
  const PolyhedralCut cut = cut_polyhedral_mesh_by_surface(mesh, blade, true);
  EXPECT_TRUE(every_cell_closed(cut.mesh)) << label;
  EXPECT_GT(cut.mesh.cell_volumes.minCoeff(), 0) << label;
  EXPECT_NEAR(cut.mesh.cell_volumes.sum(), 1.0, 1e-13) << label;
  EXPECT_EQ(piece_volumes(cut.mesh).size(), 2u) << label;
  // A plane through the cells it joined again cuts them as any non-convex cells.
  const PolyhedralCut again =
      cut_polyhedral_mesh(cut.mesh, CuttingPlane(Eigen::Vector3d(0.5, 0.5, 0.45), Eigen::Vector3d(0.3, 0.1, 1)));
  EXPECT_TRUE(every_cell_closed(again.mesh)) << label;
  EXPECT_NEAR(again.mesh.cell_volumes.sum(), 1.0, 1e-13) << label;
  const FragmentedTetrahedra fragments = type == ElementType::tet4
                                             ? FragmentedTetrahedra{unit_cube_grid(ElementType::tet4, 3)}
                                             : convex_cells_as_fragments(mesh);
  const TetrahedralCut tetrahedra = cut_tetrahedral_mesh_by_surface(fragments, blade);
  EXPECT_EQ(tetrahedra.flat_tetrahedra, 0) << label;
  const TetrahedralPieces pieces = tetrahedral_pieces(tetrahedra.result.mesh);
  EXPECT_EQ(pieces.volumes.size(), 2u) << label;
  EXPECT_NEAR(pieces.volumes.front() + pieces.volumes.back(), 1.0, 1e-13) << label;
  EXPECT_NEAR(pieces.boundary_area, boundary_area(cut.mesh), 1e-12) << label;
}

// Seeded bent blades, every third with its first quadrilateral flat (a flat part of two
// triangles), through tetrahedral and hexahedral grids. 12 blades, or ALTFEM_CUT_PLANES of
// them (docs/verification.md gives the full count's run).
TEST(CutBySurface, SeededBentBladesGiveClosedCellsAndKeepTheVolume) {
  std::mt19937 random(20261205);
  std::uniform_real_distribution<double> offset(-0.3, 0.3);
  int count = 12;
  if (const char* requested = std::getenv("ALTFEM_CUT_PLANES")) count = std::atoi(requested);
  for (int seed = 0; seed < count; ++seed) {
    std::array<double, 9> heights;
    for (double& height : heights) height = 0.5 + offset(random);
    if (seed % 3 == 2)
      for (const int corner : {1, 3, 4}) heights[corner] = heights[0];
    expect_bent_blade_parts_the_cube(bent_blade(heights), seed % 2 == 0 ? ElementType::tet4 : ElementType::hex8,
                                     "seed " + std::to_string(seed));
  }
}

// The seeded blades 755, 893 and 923 (their heights to the last digit): a flat part whose
// two triangles' shared edge runs through the centroid of a grid section at its height,
// off it by a rounding, beside bent ones, on hexahedra. Each triangle separates the faces
// in its plane whose centroid it covers; when each triangle had its own plane and side
// planes, rounded from its own normal, that face's centroid was covered by neither and the
// cube stayed in one piece.
TEST(CutBySurface, AFlatPartsInnerEdgeThroughASectionsCentroidSeparatesIt) {
  const std::array<std::array<double, 9>, 3> seeded{{
      {0.54299426441527776, 0.54299426441527776, 0.31957922680681478, 0.54299426441527776, 0.54299426441527776,
       0.43137951410950082, 0.25022952887074318, 0.74594951260249909, 0.74409611104945639},
      {0.57003854344609783, 0.57003854344609783, 0.6871690504213912, 0.57003854344609783, 0.57003854344609783,
       0.45874046521138584, 0.66202466085821321, 0.2682930208203782, 0.23110391331337582},
      {0.27545874344687765, 0.27545874344687765, 0.67145012087999345, 0.27545874344687765, 0.27545874344687765,
       0.77979428723882682, 0.53086104430611047, 0.62591436524090061, 0.25182214492117783},
  }};
  for (std::size_t blade = 0; blade < seeded.size(); ++blade)
    expect_bent_blade_parts_the_cube(bent_blade(seeded[blade]), ElementType::hex8, "blade " + std::to_string(blade));
}

// The seeded bent blades 1547 (hexahedra) and 4364 (tetrahedra), their heights to the last
// digit: each leaves fragments with a convex face one of whose edges is short beside its
// longest. Split by clipping its ears, as a face its centroid does not see every edge of
// is, such a face gave a sliver, and two flat tetrahedra left the fragment open; its
// triangles about its centroid are thin there but sound.
TEST(CutBySurface, AConvexFaceWithAShortEdgeIsSplitAboutItsCentroid) {
  expect_bent_blade_parts_the_cube(
      bent_blade({0.6556394338327185, 0.6556394338327185, 0.24583125648177817, 0.6556394338327185, 0.6556394338327185,
                  0.6542552584432797, 0.26857484641976093, 0.32079851451251484, 0.2394068419770326}),
      ElementType::hex8, "blade 1547");
  expect_bent_blade_parts_the_cube(bent_blade({0.56157774180843845, 0.56157774180843845, 0.20007385433913805,
                                               0.56157774180843845, 0.56157774180843845, 0.60024950759274343,
                                               0.79055869818312718, 0.69146765203834804, 0.60025978342042918}),
                                   ElementType::tet4, "blade 4364");
}

using test::ball_blade;
using test::enclosed_volume;

// The smallest distance between two nodes of one cell over the cell's diameter, over all cells.
double closest_nodes_of_a_cell(const PolyhedralMesh& mesh) {
  double closest = 1;
  for (int cell = 0; cell < mesh.cell_count(); ++cell) {
    const std::vector<int> nodes = cell_node_set(mesh, cell);
    double diameter = 0, nearest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < nodes.size(); ++i)
      for (std::size_t j = i + 1; j < nodes.size(); ++j) {
        const double distance = (mesh.nodes.row(nodes[i]) - mesh.nodes.row(nodes[j])).norm();
        diameter = std::max(diameter, distance);
        nearest = std::min(nearest, distance);
      }
    closest = std::min(closest, nearest / diameter);
  }
  return closest;
}

TEST(CutBySurface, AClosedBladeInsideCutsItsVolumeOutOfHexahedraAndTetrahedra) {
  const SurfaceBlade blade = ball_blade();
  ASSERT_EQ(blade.triangles.rows(), 80);
  const double inside_volume = enclosed_volume(blade);
  // A hexahedral grid whose planes hold the icosahedron's vertices, a tetrahedral one whose do not.
  for (const auto& [type, cells_per_axis] : {std::pair{ElementType::hex8, 2}, std::pair{ElementType::tet4, 3}}) {
    const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(unit_cube_grid(type, cells_per_axis));
    const PolyhedralCut cut = cut_polyhedral_mesh_by_surface(mesh, blade, true);
    const std::string grid = std::string(element_name(type)) + " " + std::to_string(cells_per_axis);
    EXPECT_TRUE(every_cell_closed(cut.mesh)) << grid;
    EXPECT_GT(cut.mesh.cell_volumes.minCoeff(), 0) << grid;
    // Where five or six triangles meet, their planes cross a cell's edge a rounding apart:
    // one node, not several a few 1e-13 apart (which left harmonic's bases fitted through
    // them singular); and two bodies — the ball and the cube around it — with their exact
    // volumes (before the debris was cleared, a contact of no area at a vertex, or a cell
    // a plane could not split there, kept them one).
    EXPECT_GT(closest_nodes_of_a_cell(cut.mesh), 1e-6) << grid;
    const std::vector<double> volumes = piece_volumes(cut.mesh);
    ASSERT_EQ(volumes.size(), 2u) << grid;
    EXPECT_NEAR(volumes[0], inside_volume, 1e-13) << grid;
    EXPECT_NEAR(volumes[1], 1 - inside_volume, 1e-13) << grid;
  }
}

// The embedded tetrahedra of fcm and fem: the steps split only the fragments near each
// triangle (spreading each through the body multiplied them past any limit), and the
// tetrahedra stay conforming: a face held once is the cube's or the ball's, so the
// boundary's area is the cube's and twice the ball's.
TEST(CutBySurface, AClosedBladeInsideOpensTheSurfaceTwice) {
  // The surface the methods deform gains the blade twice: the inner body's, facing out,
  // and the cavity's, facing in, each its own vertices.
  const SurfaceBlade blade = ball_blade();
  const double inside_volume = enclosed_volume(blade);
  CuttingPlane cutting;
  cutting.surface = std::make_shared<const SurfaceBlade>(blade);
  const SurfaceMesh box = test::box_surface(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  const SurfaceCut cut = cut_surface(box, cutting);
  EXPECT_EQ(cut.surface.vertices.rows(), box.vertices.rows() + 2 * blade.vertices.rows());
  EXPECT_EQ(cut.facts["cap_triangles"].get<int>(), 2 * blade.triangles.rows());
  const std::vector<double> volumes = test::closed_piece_volumes(cut.surface);
  ASSERT_EQ(volumes.size(), 3u);
  EXPECT_NEAR(volumes[0], -inside_volume, 1e-15);
  EXPECT_NEAR(volumes[1], inside_volume, 1e-15);
  EXPECT_NEAR(volumes[2], 1.0, 1e-15);
}

TEST(CutBySurface, APlaneAcrossASurfaceBladesNotchCutsTheSurface) {
  // A blade of two triangles notches the box from z = 0 up to z = 0.5 at x = 0.3, leaving
  // its caps on one another; a plane across the notch (z = 0.25) left that piece whole.
  // Now the box before the notch is cut again, the plane first: the slab below it, which
  // the notch cuts through, and the notched rest, three closed pieces of exact volumes.
  const auto at = [](double y, double z) { return Eigen::Vector3d(0.3, y, z); };
  CuttingPlane notch;
  notch.surface =
      std::make_shared<const SurfaceBlade>(blade_of_quadrilaterals({{at(-1, -1), at(2, -1), at(2, 0.5), at(-1, 0.5)}}));
  const SurfaceMesh box = test::box_surface(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  const SurfaceCut notched = cut_surface(box, notch);
  ASSERT_EQ(test::pieces_of(notched.surface).size(), 1u);
  const SurfaceCut across =
      cut_surface(notched.surface, CuttingPlane(Eigen::Vector3d(0, 0, 0.25), Eigen::Vector3d::UnitZ()));
  EXPECT_EQ(across.facts["pieces_left_whole"], 0);
  EXPECT_EQ(across.facts["blades_cut_again"], 1);
  const std::vector<double> volumes = test::closed_piece_volumes(across.surface);
  ASSERT_EQ(volumes.size(), 3u);
  EXPECT_NEAR(volumes[0], 0.3 * 0.25, 1e-15);
  EXPECT_NEAR(volumes[1], 0.7 * 0.25, 1e-15);
  EXPECT_NEAR(volumes[2], 0.75, 1e-15);
}

TEST(CutBySurface, ANotchBesideASurfaceBladesNotchCutsTheSurface) {
  // A blade of two triangles notches the box from z = 0 up to z = 0.5 at x = 0.3, leaving
  // its caps on one another, where corefinement cannot cut: a second notch beside it, a
  // polygon or another surface blade at x = 0.7, left that piece whole. Now the box before
  // the first notch is cut by both blades at once: one closed piece of the box's volume,
  // both notches open, each its section's area on each side.
  const auto at = [](double x, double y, double z) { return Eigen::Vector3d(x, y, z); };
  CuttingPlane notch;
  notch.surface = std::make_shared<const SurfaceBlade>(
      blade_of_quadrilaterals({{at(0.3, -1, -1), at(0.3, 2, -1), at(0.3, 2, 0.5), at(0.3, -1, 0.5)}}));
  const SurfaceMesh box = test::box_surface(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  const SurfaceMesh notched = cut_surface(box, notch).surface;
  CuttingPlane beside_surface;
  beside_surface.surface = std::make_shared<const SurfaceBlade>(
      blade_of_quadrilaterals({{at(0.7, -1, -1), at(0.7, 2, -1), at(0.7, 2, 0.5), at(0.7, -1, 0.5)}}));
  const CuttingPlane beside_polygon =
      polygon_blade({at(0.7, -1, -1), at(0.7, 2, -1), at(0.7, 2, 0.5), at(0.7, -1, 0.5)});
  for (const CuttingPlane& second : {beside_surface, beside_polygon}) {
    const SurfaceCut cut = cut_surface(notched, second);
    EXPECT_EQ(cut.facts["pieces_left_whole"], 0) << !second.surface;
    EXPECT_EQ(cut.facts["blades_cut_again"], 1) << !second.surface;
    EXPECT_EQ(cut.surface.vertices.topRows(box.vertices.rows()), box.vertices) << !second.surface;
    const std::vector<double> volumes = test::closed_piece_volumes(cut.surface);
    ASSERT_EQ(volumes.size(), 1u) << !second.surface;
    EXPECT_NEAR(volumes[0], 1.0, 1e-15) << !second.surface;
    EXPECT_NEAR(test::area_in_plane(cut.surface, 0.3), 2 * 0.5, 1e-14) << !second.surface;
    EXPECT_NEAR(test::area_in_plane(cut.surface, 0.7), 2 * 0.5, 1e-14) << !second.surface;
  }
}

}  // namespace
}  // namespace altfem
