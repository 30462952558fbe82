// Hexahedral slicing of closed surfaces into polyhedral meshes: an aligned box gives the
// grid's hexahedra; a sphere, a torus and the bunny give cells whose volumes sum to the
// enclosed volume, each cell closed (every edge used once each way, Σ area·normal = 0),
// interior faces shared by exactly two cells; two boxes closer than a cell stay apart
// (also with a face in a grid plane);
// a U-shape keeps its arms apart; slivers are merged into their neighbours; a CSG shape
// goes through its Mesh_3 surface; a batch of degenerate surfaces slices into closed cells;
// a face pierced in a hole is bridged; octree grading is conforming and 2:1.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

#include "shared/common/error.hpp"
#include "shared/mesh/boundary_surface.hpp"
#include "shared/mesh/merge_slivers.hpp"
#include "shared/mesh/mesh_components.hpp"
#include "shared/mesh/slice_into_polyhedra.hpp"
#include "shared/mesh/tetrahedralize.hpp"
#include "tests/unit/surfaces.hpp"

namespace altfem {
namespace {

using test::box_surface;
using test::sphere;
using test::torus;
constexpr double pi = test::pi;

SurfaceMesh join(const SurfaceMesh& a, const SurfaceMesh& b) {
  SurfaceMesh both;
  both.vertices.resize(a.vertices.rows() + b.vertices.rows(), 3);
  both.vertices << a.vertices, b.vertices;
  both.triangles.resize(a.triangles.rows() + b.triangles.rows(), 3);
  both.triangles << a.triangles, (b.triangles.array() + static_cast<int>(a.vertices.rows())).matrix();
  return both;
}

double surface_area(const SurfaceMesh& surface) {
  double area = 0;
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t) {
    const Eigen::Vector3d a = surface.vertices.row(surface.triangles(t, 0)),
                          b = surface.vertices.row(surface.triangles(t, 1)),
                          c = surface.vertices.row(surface.triangles(t, 2));
    area += (b - a).cross(c - a).norm() / 2;
  }
  return area;
}

/// Every cell closed and positive, every edge of a cell used once in each direction (no
/// T-junctions), every interior face in the face lists of exactly its two cells; the
/// cells' volumes sum to `volume` and the boundary faces' area to `area` (relative `tolerance`).
void expect_valid_slicing(const PolyhedralMesh& mesh, double volume, double area, double tolerance) {
  const double scale = std::cbrt(mesh.cell_volumes.maxCoeff());
  std::vector<int> seen(mesh.face_count(), 0);
  for (int cell = 0; cell < mesh.cell_count(); ++cell) {
    EXPECT_GT(mesh.cell_volumes(cell), 0) << "cell " << cell;
    Eigen::Vector3d flux = Eigen::Vector3d::Zero();
    std::map<std::pair<int, int>, int> edges;
    for (int face : mesh.cell_faces[cell]) {
      ++seen[face];
      const bool owner = mesh.face_cells(face, 0) == cell;
      ASSERT_TRUE(owner || mesh.face_cells(face, 1) == cell);
      EXPECT_GT(mesh.face_areas(face), 0) << "face " << face;
      flux += (owner ? 1.0 : -1.0) * mesh.face_areas(face) * mesh.face_normals.row(face).transpose();
      const auto& loop = mesh.faces[face];
      for (std::size_t i = 0; i < loop.size(); ++i) {
        int a = loop[i], b = loop[(i + 1) % loop.size()];
        if (!owner) std::swap(a, b);
        ++edges[{a, b}];
      }
    }
    EXPECT_LT(flux.norm(), 1e-12 * scale * scale) << "cell " << cell;
    for (const auto& [edge, count] : edges) {
      EXPECT_EQ(count, 1) << "cell " << cell << " edge " << edge.first << "-" << edge.second;
      const auto reverse = edges.find({edge.second, edge.first});
      EXPECT_TRUE(reverse != edges.end() && reverse->second == 1)
          << "cell " << cell << " edge " << edge.first << "-" << edge.second << " not matched";
    }
  }
  double boundary_area = 0;
  Eigen::Vector3d boundary_flux = Eigen::Vector3d::Zero();
  for (int face = 0; face < mesh.face_count(); ++face) {
    const bool interior = !mesh.is_boundary_face(face);
    EXPECT_EQ(seen[face], interior ? 2 : 1) << "face " << face;
    if (interior) {
      EXPECT_NE(mesh.face_cells(face, 0), mesh.face_cells(face, 1));
    } else {
      boundary_area += mesh.face_areas(face);
      boundary_flux += mesh.face_areas(face) * mesh.face_normals.row(face).transpose();
    }
  }
  EXPECT_NEAR(mesh.cell_volumes.sum(), volume, tolerance * volume);
  EXPECT_NEAR(boundary_area, area, tolerance * area);
  EXPECT_LT(boundary_flux.norm(), tolerance * area);
}

TEST(SliceIntoPolyhedra, ABoxOnGridPlanesIsExactlyTheGridsHexahedra) {
  const SurfaceMesh box = box_surface(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1));
  SlicingOptions options;
  options.cell_size = 0.25;
  options.margin_cells = 1;
  const SlicedMesh sliced = slice_into_polyhedra(box, options);
  EXPECT_EQ(sliced.grid_cells, Eigen::Vector3i(6, 6, 6));
  ASSERT_EQ(sliced.mesh.cell_count(), 64);
  EXPECT_EQ(sliced.hexahedra, 64);
  EXPECT_EQ(sliced.cut_pieces, 0);
  for (int cell = 0; cell < 64; ++cell) {
    EXPECT_EQ(sliced.mesh.cell_kinds[cell], PolyhedralCellKind::hexahedron);
    EXPECT_EQ(sliced.mesh.cell_faces[cell].size(), 6u);
    EXPECT_DOUBLE_EQ(sliced.mesh.cell_volumes(cell), 0.25 * 0.25 * 0.25);
  }
  EXPECT_EQ(sliced.mesh.nodes.rows(), 125);
  EXPECT_EQ(sliced.mesh.face_count(), 3 * 5 * 16);
  expect_valid_slicing(sliced.mesh, 1.0, 6.0, 1e-14);
}

TEST(SliceIntoPolyhedra, SphereCellsSumToTheEnclosedVolume) {
  const SurfaceMesh surface = sphere(0.8, 24, 48, Eigen::Vector3d(0.0123, -0.0311, 0.0071));
  // At resolution 3 grid planes pass through the centre: two meridians and the equator lie
  // in grid planes (after snapping) and the poles on grid lines.
  for (int resolution : {3, 8}) {
    SlicingOptions options;
    options.resolution = resolution;
    options.sliver_fraction = 0;
    const SlicedMesh sliced = slice_into_polyhedra(surface, options);
    EXPECT_GT(sliced.cut_pieces, 0);
    expect_valid_slicing(sliced.mesh, surface_volume(surface), surface_area(surface), 1e-10);
  }
}

TEST(SliceIntoPolyhedra, TorusCellsSumToTheEnclosedVolume) {
  const SurfaceMesh surface = torus(1.0, 0.35, 48, 24, Eigen::Vector3d(0.017, 0.0093, -0.021));
  SlicingOptions options;
  options.resolution = 10;
  options.sliver_fraction = 0;
  const SlicedMesh sliced = slice_into_polyhedra(surface, options);
  EXPECT_GT(sliced.hexahedra, 0);
  expect_valid_slicing(sliced.mesh, surface_volume(surface), surface_area(surface), 1e-10);
}

TEST(SliceIntoPolyhedra, TwoBoxesInOneGridCellGiveTwoPieces) {
  // A gap of 1e-2 at x ∈ [0.495, 0.505], inside the grid slab x ∈ [0.3825, 0.6175).
  const SurfaceMesh left = box_surface(Eigen::Vector3d(0.03, 0.03, 0.03), Eigen::Vector3d(0.495, 0.97, 0.97));
  const SurfaceMesh right = box_surface(Eigen::Vector3d(0.505, 0.03, 0.03), Eigen::Vector3d(0.97, 0.97, 0.97));
  const SurfaceMesh both = join(left, right);
  SlicingOptions options;
  options.resolution = 4;
  const SlicedMesh sliced = slice_into_polyhedra(both, options);
  EXPECT_EQ(sliced.split_grid_cells, 25);  // the 5 × 5 grid cells of that slab holding material
  expect_valid_slicing(sliced.mesh, surface_volume(both), surface_area(both), 1e-12);
  // No cell reaches across the gap.
  for (int cell = 0; cell < sliced.mesh.cell_count(); ++cell) {
    bool on_left = false, on_right = false;
    for (int face : sliced.mesh.cell_faces[cell])
      for (int node : sliced.mesh.faces[face]) {
        on_left |= sliced.mesh.nodes(node, 0) < 0.5;
        on_right |= sliced.mesh.nodes(node, 0) > 0.5;
      }
    EXPECT_FALSE(on_left && on_right) << "cell " << cell;
  }
}

// The bars of tests/cli/scenes/two_boxes.json, 4 mm apart across y ∈ [0.1, 0.104], sliced
// on a grid with no margin, so grid planes lie at y = k · cell_size: with cell 0.1 the lower
// bar's top face lies in a grid plane, with cell 0.104 the upper bar's bottom face, with
// cell 0.102 a grid plane runs through the gap. Issue #35: no face may join the bars. The
// slicer cannot tell the two sides' faces apart in the flush cases and moves the grid.
class TwoBarsOnGridPlanes : public ::testing::TestWithParam<double> {};

TEST_P(TwoBarsOnGridPlanes, NeverShareAFace) {
  const SurfaceMesh lower = box_surface(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0.1, 0.1));
  const SurfaceMesh upper = box_surface(Eigen::Vector3d(0.3, 0.104, 0), Eigen::Vector3d(1, 0.204, 0.1));
  const SurfaceMesh both = join(lower, upper);
  SlicingOptions options;
  options.cell_size = GetParam();
  options.margin_cells = 0;
  const SlicedMesh sliced = slice_into_polyhedra(both, options);
  expect_valid_slicing(sliced.mesh, surface_volume(both), surface_area(both), 1e-12);
  EXPECT_EQ(polyhedral_mesh_components(sliced.mesh), 2);
  EXPECT_EQ(sliced.grid_shift_cells > 0, GetParam() != 0.102);
}

INSTANTIATE_TEST_SUITE_P(SliceIntoPolyhedra, TwoBarsOnGridPlanes, ::testing::Values(0.1, 0.102, 0.104));

/// A U-shaped prism, y ∈ [0, 1]: bottom [0, 3] × z [0, 1], arms x ∈ [0, 1.45] and
/// [1.55, 3] up to z = 3, so its gap (0.1 wide) is thinner than a cell; volume 8.8.
SurfaceMesh u_shape() {
  const std::vector<Eigen::Vector2d> outline{{0, 0},    {3, 0},    {3, 3},    {1.55, 3},
                                             {1.55, 1}, {1.45, 1}, {1.45, 3}, {0, 3}};
  // The outline's triangles without new vertices; counter-clockwise in (x, z), i.e. about −y.
  const std::vector<Eigen::Vector3i> cap{{0, 1, 4}, {0, 4, 5}, {1, 2, 3}, {1, 3, 4}, {0, 5, 6}, {0, 6, 7}};
  const int n = static_cast<int>(outline.size());
  SurfaceMesh u;
  u.vertices.resize(2 * n, 3);
  for (int k = 0; k < n; ++k) {
    u.vertices.row(k) << outline[k].x(), 0, outline[k].y();
    u.vertices.row(k + n) << outline[k].x(), 1, outline[k].y();
  }
  std::vector<Eigen::Vector3i> triangles;
  for (const auto& t : cap) {
    triangles.push_back(t);                                // y = 0, outward −y
    triangles.emplace_back(t(0) + n, t(2) + n, t(1) + n);  // y = 1, outward +y
  }
  for (int k = 0; k < n; ++k) {  // the sides, outward for a counter-clockwise outline about −y
    const int a = k, b = (k + 1) % n;
    triangles.emplace_back(a, b + n, b);
    triangles.emplace_back(a, a + n, b + n);
  }
  u.triangles.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (std::size_t t = 0; t < triangles.size(); ++t) u.triangles.row(t) = triangles[t].transpose();
  return u;
}

TEST(SliceIntoPolyhedra, AUShapeKeepsItsArmsApartWhereTheGapCrossesAGridCell) {
  const SurfaceMesh u = u_shape();
  ASSERT_NEAR(surface_volume(u), 8.8, 1e-12);
  SlicingOptions options;
  options.cell_size = 0.5;  // grid planes at −0.25 + k/2: the gap lies in the slab x ∈ [1.25, 1.75]
  options.sliver_fraction = 0;
  const SlicedMesh sliced = slice_into_polyhedra(u, options);
  // Above the bottom (z > 1.25) the gap splits the 4 × 3 grid cells of that slab in two.
  EXPECT_EQ(sliced.split_grid_cells, 12);
  expect_valid_slicing(sliced.mesh, 8.8, surface_area(u), 1e-12);
  int pieces_across_the_gap = 0, pieces_beside_it = 0;
  for (int cell = 0; cell < sliced.mesh.cell_count(); ++cell) {
    const Eigen::Vector3d centroid = sliced.mesh.cell_centroids.row(cell);
    if (centroid.x() < 1.25 || centroid.x() > 1.75 || centroid.z() < 1.25) continue;
    bool on_left = false, on_right = false;
    for (int face : sliced.mesh.cell_faces[cell])
      for (int node : sliced.mesh.faces[face]) {
        on_left |= sliced.mesh.nodes(node, 0) < 1.5;
        on_right |= sliced.mesh.nodes(node, 0) > 1.5;
      }
    (on_left && on_right ? pieces_across_the_gap : pieces_beside_it)++;
  }
  EXPECT_EQ(pieces_across_the_gap, 0);
  EXPECT_EQ(pieces_beside_it, 24);
}

TEST(SliceIntoPolyhedra, SlicedBunnyHasTheSurfaceVolume) {
  const SurfaceMesh bunny = read_surface(std::string(ALTFEM_SOURCE_DIR) + "/data/surface/bunny_npm.off");
  // At 24³ with half a cell of margin the bunny pierces a grid face in a hole.
  for (int resolution : {8, 24}) {
    SlicingOptions options;
    options.resolution = resolution;
    options.sliver_fraction = 0;
    const SlicedMesh sliced = slice_into_polyhedra(bunny, options);
    expect_valid_slicing(sliced.mesh, surface_volume(bunny), surface_area(bunny), 1e-9);
  }
}

TEST(SliceIntoPolyhedra, SliversAreMergedIntoTheirLargestFaceNeighbour) {
  // The box reaches 1e-5 past the grid plane x = 1: sixteen pieces of 1e-5 / 0.25 = 4e-5 of a cell.
  const SurfaceMesh box = box_surface(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1.00001, 1, 1));
  SlicingOptions options;
  options.cell_size = 0.25;
  options.margin_cells = 1;
  options.sliver_fraction = 0;
  const SlicedMesh kept = slice_into_polyhedra(box, options);
  EXPECT_EQ(kept.mesh.cell_count(), 64 + 16);
  EXPECT_EQ(kept.merged_slivers, 0);

  options.sliver_fraction = 1e-3;
  const SlicedMesh merged = slice_into_polyhedra(box, options);
  EXPECT_EQ(merged.merged_slivers, 16);
  ASSERT_EQ(merged.mesh.cell_count(), 64);
  int merged_cells = 0;
  for (int cell = 0; cell < 64; ++cell) {
    merged_cells += merged.mesh.cell_kinds[cell] == PolyhedralCellKind::merged;
    EXPECT_GE(merged.mesh.cell_volumes(cell), 1e-3 * std::pow(0.25, 3));
  }
  EXPECT_EQ(merged_cells, 16);
  expect_valid_slicing(merged.mesh, 1.00001, surface_area(box), 1e-12);
  // The merged cells are the hexahedra next to x = 1, now reaching to x = 1.00001.
  for (int cell = 0; cell < 64; ++cell) {
    if (merged.mesh.cell_kinds[cell] == PolyhedralCellKind::merged) {
      EXPECT_NEAR(merged.mesh.cell_volumes(cell), 0.25 * 0.25 * 0.25001, 1e-15);
    }
  }
}

TEST(SliceIntoPolyhedra, CsgShapeIsSlicedThroughItsMesh3Surface) {
  // A box with a spherical bite, through the boundary of its Mesh_3 tetrahedralisation at
  // half the grid's cell size: the cells hold exactly that surface's volume.
  const ShapePointer shape = make_difference({make_box(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0.8, 0.6)),
                                              make_sphere(Eigen::Vector3d(1, 0.8, 0.6), 0.5)});
  SlicingOptions options;
  options.resolution = 6;
  options.sliver_fraction = 0;
  const SlicedMesh sliced = slice_into_polyhedra(*shape, options);
  const SurfaceMesh surface = boundary_surface(tetrahedralize_shape(*shape, sliced.cell_size / 2)).surface;
  expect_valid_slicing(sliced.mesh, surface_volume(surface), surface_area(surface), 1e-10);
  const double exact = 0.48 - pi * 0.5 * 0.5 * 0.5 / 6;
  EXPECT_NEAR(sliced.mesh.cell_volumes.sum(), exact, 0.02 * exact);  // Mesh_3's approximation
}

TEST(SliceIntoPolyhedra, RobustnessBatchOfDegenerateSurfacesKeepsTheVolume) {
  // Boxes with faces exactly on grid planes (lattice corners, cells of 1/8 or 1/4), jittered
  // and rotated boxes, spheres and tori centred on lattice points (meridians in grid planes,
  // grid lines through surface edges, poles on grid lines), several resolutions and margins:
  // every slicing closed cell by cell with the enclosed volume.
  std::mt19937 random(42);
  std::uniform_real_distribution<double> unit(0, 1);
  int sliced = 0;
  for (int trial = 0; trial < 40; ++trial) {
    SurfaceMesh surface;
    SlicingOptions options;
    options.margin_cells = trial % 3 == 0 ? 0.0 : 0.5;
    options.sliver_fraction = trial % 5 == 0 ? 1e-3 : 0.0;
    const bool lattice = trial % 2 == 0;
    if (trial < 20) {
      Eigen::Vector3d low, high;
      for (int axis = 0; axis < 3; ++axis) {
        double a = unit(random), b = unit(random);
        if (lattice) a = std::round(a * 8) / 8, b = std::round(b * 8) / 8;
        if (a == b) b = a + 0.125;
        low(axis) = std::min(a, b), high(axis) = std::max(a, b);
      }
      surface = box_surface(low, high);
      if (trial % 4 == 1) {
        const Eigen::Vector3d axis = Eigen::Vector3d(unit(random), unit(random), unit(random)).normalized();
        surface.vertices =
            (surface.vertices * Eigen::AngleAxisd(unit(random), axis).toRotationMatrix().transpose()).eval();
      }
      if (lattice) options.cell_size = 0.125 * (1 + trial % 4 / 2), options.margin_cells = 1;
    } else {
      Eigen::Vector3d centre(unit(random), unit(random), unit(random));
      if (lattice) centre = (centre * 4).array().round() / 4;
      surface = trial % 3 == 0
                    ? torus(0.7 + 0.3 * unit(random), 0.2 + 0.2 * unit(random), 16 + trial % 32, 8 + trial % 16, centre)
                    : sphere(0.5 + unit(random), 4 + trial % 20, 8 + trial % 30, centre);
      if (lattice && trial % 3 != 0) options.cell_size = 0.25, options.margin_cells = 1;
    }
    const double volume = surface_volume(surface);
    for (int resolution : {3, 7}) {
      options.resolution = resolution;
      const SlicedMesh mesh = slice_into_polyhedra(surface, options);
      SCOPED_TRACE("trial " + std::to_string(trial) + " resolution " + std::to_string(resolution));
      expect_valid_slicing(mesh.mesh, volume, surface_area(surface), 1e-11);
      ++sliced;
      if (options.cell_size > 0) break;  // the resolution does not change the grid
    }
  }
  std::printf("robustness batch: %d slicings\n", sliced);
}

TEST(SliceIntoPolyhedra, AFacePiercedAwayFromItsEdgesIsSplitIntoSimplePolygons) {
  // The torus hole crosses the grid plane z = 0.1 inside one face: that face's region is a
  // square with a hole, bridged into two simple polygons.
  const SurfaceMesh surface = torus(1.0, 0.5, 48, 24, Eigen::Vector3d::Zero());
  SlicingOptions options;
  options.cell_size = 1.5;
  options.margin_cells = 0.6;
  options.sliver_fraction = 0;
  const SlicedMesh sliced = slice_into_polyhedra(surface, options);
  int faces_in_plane = 0;
  for (int face = 0; face < sliced.mesh.face_count(); ++face) {
    const auto& loop = sliced.mesh.faces[face];
    faces_in_plane += std::all_of(loop.begin(), loop.end(), [&](int node) {
      return std::abs(sliced.mesh.nodes(node, 2) - 0.1) < 1e-15 && std::abs(sliced.mesh.nodes(node, 0)) < 0.9 &&
             std::abs(sliced.mesh.nodes(node, 1)) < 0.9;
    });
  }
  EXPECT_EQ(faces_in_plane, 2);  // the holed face as two polygons
  expect_valid_slicing(sliced.mesh, surface_volume(surface), surface_area(surface), 1e-10);
}

TEST(SliceIntoPolyhedra, OctreeGradingIsConformingAndTwoToOneBalanced) {
  // Martin et al. 2008, Fig. 4: coarse cells inside, their faces carry the finer nodes.
  const SurfaceMesh surface = sphere(0.8, 24, 48, Eigen::Vector3d(0.0123, -0.0311, 0.0071));
  SlicingOptions options;
  options.resolution = 40;  // level-2 cells need 4 + 2 × 8 cells of inside across
  options.sliver_fraction = 0;
  const SlicedMesh uniform = slice_into_polyhedra(surface, options);
  options.octree_levels = 3;
  const SlicedMesh graded = slice_into_polyhedra(surface, options);
  EXPECT_GT(graded.coarse_cells, 0);
  EXPECT_LT(graded.mesh.cell_count(), uniform.mesh.cell_count() - 7 * graded.coarse_cells + 1);
  // Every edge of every cell used once each way: no hanging node on any cell's boundary.
  expect_valid_slicing(graded.mesh, surface_volume(surface), surface_area(surface), 1e-10);
  // Levels from the volumes ((2^L h)^3 for coarse cells); face neighbours within one level.
  const double cell_volume = std::pow(graded.cell_size, 3);
  auto level = [&](int cell) {
    return graded.mesh.cell_kinds[cell] == PolyhedralCellKind::coarse
               ? static_cast<int>(std::lround(std::log2(graded.mesh.cell_volumes(cell) / cell_volume) / 3))
               : 0;
  };
  int largest_level = 0;
  for (int cell = 0; cell < graded.mesh.cell_count(); ++cell) {
    largest_level = std::max(largest_level, level(cell));
    if (graded.mesh.cell_kinds[cell] == PolyhedralCellKind::coarse) {
      EXPECT_NEAR(graded.mesh.cell_volumes(cell), std::pow(2.0, 3 * level(cell)) * cell_volume, 1e-12 * cell_volume);
    }
  }
  EXPECT_GE(largest_level, 2);
  for (int face = 0; face < graded.mesh.face_count(); ++face) {
    if (graded.mesh.is_boundary_face(face)) continue;
    EXPECT_LE(std::abs(level(graded.mesh.face_cells(face, 0)) - level(graded.mesh.face_cells(face, 1))), 1)
        << "face " << face;
  }
  // Every node is used by some face.
  std::vector<bool> used(graded.mesh.nodes.rows(), false);
  for (const auto& loop : graded.mesh.faces)
    for (int node : loop) used[node] = true;
  EXPECT_TRUE(std::all_of(used.begin(), used.end(), [](bool value) { return value; }));
}

TEST(SliceIntoPolyhedra, BadOptionsAreInputErrors) {
  const SurfaceMesh box = box_surface(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1));
  SlicingOptions options;
  options.resolution = 0;
  EXPECT_THROW(slice_into_polyhedra(box, options), InputError);
  options.resolution = 4;
  options.margin_cells = -1;
  EXPECT_THROW(slice_into_polyhedra(box, options), InputError);
}

}  // namespace
}  // namespace altfem
