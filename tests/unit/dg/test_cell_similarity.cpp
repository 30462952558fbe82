// Issue #18, Table 1's integration phase: DgLinearSystem computes element and face
// matrices once per class of translated cells (dg/cell_similarity.hpp). The reused
// matrices must equal the recomputed ones (≤ 1e-12 relative) on a sliced mesh with cut
// cells, a cell moved by far less than its size must not be taken for a translate, and
// translates far from the origin must still be recognised.
#include <gtest/gtest.h>

#include "dg/cell_similarity.hpp"
#include "dg/polyhedral_mesh_faces.hpp"
#include "shared/mesh/slice_into_polyhedra.hpp"
#include "tests/unit/dg/hex_grid_cells.hpp"
#include "tests/unit/surfaces.hpp"

namespace altfem::dg {
namespace {

// max |A − B| / max |B|, over the union of the patterns.
double relative_difference(const Eigen::SparseMatrix<double>& a, const Eigen::SparseMatrix<double>& b) {
  const Eigen::SparseMatrix<double> difference = a - b;
  double largest = 0, scale = 0;
  for (int k = 0; k < difference.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(difference, k); it; ++it)
      largest = std::max(largest, std::abs(it.value()));
  for (int k = 0; k < b.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(b, k); it; ++it) scale = std::max(scale, std::abs(it.value()));
  return largest / scale;
}

DgSettings settings(int degree, Flux flux, bool reuse) {
  DgSettings result{degree, flux, 20, 2.0, 1.5};
  result.reuse_similar_cells = reuse;
  return result;
}

// The sphere sliced on a 6³ grid: cut cells, merged slivers and whole hexahedra; the
// lower half's boundary held in x and z, weakly, strongly below z = −0.5 (those cells'
// functions recombined, dg/strong_conditions.hpp); two materials split at z = 0, with
// split penalties.
struct SlicedSphere {
  std::vector<Polyhedron> cells;
  std::vector<DgFace> faces;
  DgCellMaterials materials;
};

SlicedSphere sliced_sphere() {
  SlicingOptions options;
  options.resolution = 6;
  const SlicedMesh sliced =
      slice_into_polyhedra(altfem::test::sphere(0.8, 12, 24, Eigen::Vector3d(0.03, -0.02, 0.01)), options);
  SlicedSphere sphere{mesh_cells(sliced.mesh), mesh_faces(sliced.mesh), {}};
  for (size_t f = 0; f < sphere.faces.size(); ++f)
    if (sphere.faces[f].plus < 0 && sliced.mesh.face_centroids(static_cast<Eigen::Index>(f), 2) < 0) {
      sphere.faces[f].condition = 0;
      sphere.faces[f].components = {true, false, true};
      sphere.faces[f].strong = sliced.mesh.face_centroids(static_cast<Eigen::Index>(f), 2) < -0.5;
    }
  sphere.materials.materials = {{2.0, 1.5, 1.0, 20, 0.6}, {20.0, 15.0, 3.0, 30, 1.0}};
  for (int c = 0; c < sliced.mesh.cell_count(); ++c)
    sphere.materials.ids.push_back(sliced.mesh.cell_centroids(c, 2) > 0 ? 1 : 0);
  return sphere;
}

TEST(CellSimilarity, ReusedMatricesEqualRecomputedOnesOnASlicedSphere) {
  const SlicedSphere sphere = sliced_sphere();
  for (const auto& [degree, flux] : {std::pair{1, Flux::babuska_zlamal}, std::pair{2, Flux::interior_penalty}}) {
    const DgLinearSystem reused(sphere.cells, sphere.faces, settings(degree, flux, true), sphere.materials);
    const DgLinearSystem recomputed(sphere.cells, sphere.faces, settings(degree, flux, false), sphere.materials);
    const SimilarityStatistics& statistics = reused.similarity();
    std::printf("  k=%d: %d cells in %d classes, %d faces in %d classes\n", degree, statistics.cells,
                statistics.cell_classes, statistics.faces, statistics.face_classes);
    // The whole hexahedra inside are translates: classes were shared...
    EXPECT_LT(statistics.cell_classes, statistics.cells);
    EXPECT_LT(statistics.face_classes, statistics.faces);
    EXPECT_EQ(recomputed.similarity().cell_classes, recomputed.similarity().cells);
    EXPECT_FALSE(reused.constrained_dofs().empty());  // strongly held cells are among them
    EXPECT_EQ(reused.constrained_dofs(), recomputed.constrained_dofs());
    // ...and give what recomputation gives.
    EXPECT_LE(relative_difference(reused.stiffness(), recomputed.stiffness()), 1e-12) << "k = " << degree;
    EXPECT_LE(relative_difference(reused.mass(), recomputed.mass()), 1e-12);
    EXPECT_LE((reused.function_integrals() - recomputed.function_integrals()).cwiseAbs().maxCoeff(),
              1e-12 * recomputed.function_integrals().cwiseAbs().maxCoeff());
  }
}

// Moves the grid point `point` by `offset` in every cell and face that holds it.
void move_point(test::GridCells& grid, const Eigen::Vector3d& point, const Eigen::Vector3d& offset) {
  const auto move_rows = [&](Eigen::MatrixXd& rows) {
    for (Eigen::Index r = 0; r < rows.rows(); ++r)
      if ((rows.row(r).transpose() - point).norm() < 1e-12) rows.row(r) += offset.transpose();
  };
  for (Polyhedron& cell : grid.cells) move_rows(cell.vertices);
  for (DgFace& face : grid.faces) move_rows(face.polygon);
}

TEST(CellSimilarity, AVertexMovedByOneMillionthIsNoFalseHit) {
  const test::GridCells cube = test::hex_grid_cells(4);
  test::GridCells perturbed = cube;
  move_point(perturbed, Eigen::Vector3d(0.5, 0.5, 0.5), Eigen::Vector3d(1e-6, 0, 0));
  const DgSettings reuse = settings(2, Flux::interior_penalty, true);
  const DgLinearSystem cube_system(cube.cells, cube.faces, reuse);
  const DgLinearSystem perturbed_system(perturbed.cells, perturbed.faces, reuse);
  const DgLinearSystem recomputed(perturbed.cells, perturbed.faces, settings(2, Flux::interior_penalty, false));
  // One class of cube cells; the 8 cells around the moved vertex each a class of its own.
  EXPECT_EQ(cube_system.similarity().cell_classes, 1);
  EXPECT_EQ(perturbed_system.similarity().cell_classes, 9);
  EXPECT_LE(relative_difference(perturbed_system.stiffness(), recomputed.stiffness()), 1e-12);
  // The move changes K by ~1e-6 relative, far above what reuse is allowed to differ by.
  EXPECT_GT(relative_difference(perturbed_system.stiffness(), cube_system.stiffness()), 1e-8);
}

TEST(CellSimilarity, TranslatesFarFromTheOriginShareTheirClasses) {
  const test::GridCells cube = test::hex_grid_cells(3);
  test::GridCells far = cube;
  const Eigen::RowVector3d shift(1e4, -2e4, 3e4);
  for (Polyhedron& cell : far.cells) cell.vertices.rowwise() += shift;
  for (DgFace& face : far.faces) face.polygon.rowwise() += shift;
  const DgLinearSystem near_system(cube.cells, cube.faces, settings(1, Flux::interior_penalty, true));
  const DgLinearSystem far_system(far.cells, far.faces, settings(1, Flux::interior_penalty, true));
  const DgLinearSystem recomputed(far.cells, far.faces, settings(1, Flux::interior_penalty, false));
  EXPECT_EQ(far_system.similarity().cell_classes, near_system.similarity().cell_classes);
  EXPECT_EQ(far_system.similarity().face_classes, near_system.similarity().face_classes);
  // Positions 1e5 cell sizes from the origin carry round-off that the exact integration
  // amplifies (~1e-8 relative between the near and the far grid): reuse stays within it.
  const double round_off = relative_difference(recomputed.stiffness(), near_system.stiffness());
  std::printf("  far from the origin: recomputed vs near %.2g, reused vs recomputed %.2g\n", round_off,
              relative_difference(far_system.stiffness(), recomputed.stiffness()));
  EXPECT_LE(relative_difference(far_system.stiffness(), recomputed.stiffness()), 2 * round_off);
}

TEST(CellSimilarity, ACellNumberedOtherwiseIsTheSameClass) {
  // An irregular hexahedron, then the same one with its vertices permuted, its faces in
  // reverse order and each loop starting at another vertex (orientation kept): the key
  // must not see the numbering, which differs between the cells of a mesh.
  Polyhedron cell = test::hex_grid_cells(1).cells.front();
  cell.vertices(7, 0) += 0.1;
  cell.vertices(6, 2) -= 0.05;
  const std::vector<int> permutation{5, 2, 7, 0, 3, 6, 1, 4};  // old vertex → new vertex
  Polyhedron renumbered;
  renumbered.vertices.resize(8, 3);
  for (int v = 0; v < 8; ++v) renumbered.vertices.row(permutation[v]) = cell.vertices.row(v);
  for (auto face = cell.faces.rbegin(); face != cell.faces.rend(); ++face) {
    std::vector<int> loop;
    for (size_t k = 0; k < face->size(); ++k) loop.push_back(permutation[(*face)[(k + 1) % face->size()]]);
    renumbered.faces.push_back(loop);
  }
  const Eigen::Vector3d centre(0.52, 0.49, 0.5);
  SimilarityClasses classes;
  EXPECT_TRUE(classes.classify(cell_similarity_key(cell, centre, 1.8, {0}, 1e-12)).created);
  EXPECT_EQ(classes.classify(cell_similarity_key(renumbered, centre, 1.8, {0}, 1e-12)).index, 0);
  // The same cell of another material is another class.
  EXPECT_TRUE(classes.classify(cell_similarity_key(renumbered, centre, 1.8, {1}, 1e-12)).created);
}

TEST(CellSimilarity, BadInputThrowsFromTheParallelComputation) {
  // Every face its own class: the face matrices are computed in an OpenMP loop, whose
  // exceptions must reach the caller.
  test::GridCells grid = test::hex_grid_cells(3);
  grid.faces[40].polygon.conservativeResize(2, 3);
  EXPECT_THROW(DgLinearSystem(grid.cells, grid.faces, settings(1, Flux::interior_penalty, false)),
               std::invalid_argument);
}

TEST(CellSimilarity, KeysDifferingBeyondTheToleranceOpenNewClasses) {
  SimilarityClasses classes;
  const auto key = [](double x, int material) {
    return SimilarityKey{{material}, {x, 0.25, -0.5}, 1.0, similarity_tolerance(1.0, 1.0, 1e-12)};
  };
  EXPECT_TRUE(classes.classify(key(0.125, 0)).created);
  EXPECT_EQ(classes.classify(key(0.125 + 1e-13, 0)).index, 0);   // within tolerance
  EXPECT_TRUE(classes.classify(key(0.125 + 1e-10, 0)).created);  // beyond it
  EXPECT_TRUE(classes.classify(key(0.125, 1)).created);          // another structure
  EXPECT_EQ(classes.class_count(), 3);
  EXPECT_EQ(classes.key_count(), 4);
}

}  // namespace
}  // namespace altfem::dg
