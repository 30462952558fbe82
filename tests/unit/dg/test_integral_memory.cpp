// Issue #33: a rebuild after a cut integrates again only the cells and faces the cut
// touched (Kaufmann et al. 2009 §9.4); every other class of cells and faces takes its
// matrices from the build before (dg/dg_integral_memory.hpp). The rebuilt K must be the
// one a fresh build gives (≤ 1e-12 relative, the tolerance within which translates share
// matrices), the counts must name only what the cut changed, and a build with another
// penalty, or after the matrices were taken, must take nothing. The penalty's certificate
// is computed only for the combinations of classes the rebuild integrated.
#include <gtest/gtest.h>

#include <set>

#include "dg/definiteness_certificate.hpp"
#include "dg/dg_integral_memory.hpp"
#include "dg/polyhedral_mesh_faces.hpp"
#include "shared/mesh/cut_polyhedral_mesh.hpp"
#include "tests/unit/mesh/unit_cube_mesh.hpp"

namespace altfem::dg {
namespace {

double largest_difference(const Eigen::SparseMatrix<double>& a, const Eigen::SparseMatrix<double>& b) {
  const Eigen::SparseMatrix<double> difference = a - b;
  double largest = 0;
  for (int k = 0; k < difference.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(difference, k); it; ++it)
      largest = std::max(largest, std::abs(it.value()));
  return largest;
}

// The DG system of `mesh` with every boundary face held weakly (so boundary faces have
// terms too), reusing `previous`, remembering its own.
DgLinearSystem system_of(const PolyhedralMesh& mesh, double penalty,
                         std::shared_ptr<DgIntegralMemory> previous = nullptr) {
  std::vector<DgFace> faces = mesh_faces(mesh);
  for (DgFace& face : faces)
    if (face.plus < 0) face.condition = 0;
  DgSettings settings{2, Flux::interior_penalty, penalty, 2.0, 1.5};
  return {mesh_cells(mesh), std::move(faces), settings, {}, {std::move(previous), true}};
}

TEST(IntegralMemory, ARebuildAfterACutIntegratesOnlyThePiecesAndTheirFaces) {
  const PolyhedralMesh grid = unit_cube_mesh(ElementType::hex8, 4);
  // x = 0.6 crosses the 16 cells of the slab [0.5, 0.75] into pieces 0.1 and 0.15 wide.
  const PolyhedralCut cut =
      cut_polyhedral_mesh(grid, CuttingPlane(Eigen::Vector3d(0.6, 0, 0), Eigen::Vector3d::UnitX()));
  ASSERT_EQ(cut.crossed_cells, 16);

  const DgLinearSystem before = system_of(grid, 20);
  const DgLinearSystem rebuilt = system_of(cut.mesh, 20, before.integral_memory());
  const DgLinearSystem fresh = system_of(cut.mesh, 20);

  EXPECT_LE(largest_difference(rebuilt.stiffness(), fresh.stiffness()),
            1e-12 * fresh.stiffness().coeffs().cwiseAbs().maxCoeff());
  EXPECT_LE(largest_difference(rebuilt.mass(), fresh.mass()), 1e-12 * fresh.mass().coeffs().cwiseAbs().maxCoeff());

  // The cells the cut made: those of the crossed parents, the only cells with a parent
  // that holds two of them. Every class without one of them is taken from the build before.
  std::vector<int> children(grid.cell_count(), 0);
  for (int parent : cut.parent_cell) ++children[parent];
  std::set<int> piece_classes, other_classes;
  const SimilarityStatistics& counts = rebuilt.similarity();
  const SimilarityStatistics& fresh_counts = fresh.similarity();
  EXPECT_EQ(counts.cell_classes, fresh_counts.cell_classes);
  EXPECT_EQ(counts.face_classes, fresh_counts.face_classes);
  EXPECT_EQ(before.similarity().remembered_cell_classes, 0);
  // The grid's cells are translates of one cube, whose class the rebuild takes; the
  // pieces are two widths (0.1 and 0.15), two classes integrated anew.
  EXPECT_EQ(counts.cell_classes, 3);
  EXPECT_EQ(counts.remembered_cell_classes, 1);
  // Faces: every class whose faces all lie between whole cubes (or on their boundary) is
  // taken; those touching a piece are new. Count the latter from the geometry: faces
  // with a piece on one side, classified as the system does, are at least one class and at
  // most as many classes as there are such faces.
  int faces_at_pieces = 0;
  for (const DgFace& face : mesh_faces(cut.mesh))
    if (children[cut.parent_cell[face.minus]] == 2 || (face.plus >= 0 && children[cut.parent_cell[face.plus]] == 2))
      ++faces_at_pieces;
  const int new_face_classes = counts.face_classes - counts.remembered_face_classes;
  EXPECT_GE(new_face_classes, 1);
  EXPECT_LE(new_face_classes, faces_at_pieces);
  // And none of those the uncut grid had: its faces' classes are all still present
  // (interior and boundary faces between cubes away from the slab) and all taken.
  EXPECT_EQ(counts.remembered_face_classes, before.similarity().face_classes);
}

TEST(IntegralMemory, ARebuildCertifiesOnlyTheCombinationsOfClassesItIntegrated) {
  // The penalty's certificate per combination of a cell's class and its faces' is that of
  // the build before wherever those classes were taken from it; the others are computed.
  // Every combination's ratio is a fresh build's (the same classes, in the same order).
  const PolyhedralMesh grid = unit_cube_mesh(ElementType::hex8, 4);
  const PolyhedralMesh cut =
      cut_polyhedral_mesh(grid, CuttingPlane(Eigen::Vector3d(0.6, 0, 0), Eigen::Vector3d::UnitX())).mesh;
  const DgLinearSystem before = system_of(grid, 20);
  const DefinitenessCertificate first = certify_definiteness(before);
  const DgLinearSystem rebuilt = system_of(cut, 20, before.integral_memory());
  const DgLinearSystem fresh = system_of(cut, 20);
  const DefinitenessCertificate kept = certify_definiteness(rebuilt), computed = certify_definiteness(fresh);
  const auto& ratios = rebuilt.integral_memory()->certificate_ratios;
  const auto& fresh_ratios = fresh.integral_memory()->certificate_ratios;
  ASSERT_EQ(ratios.size(), fresh_ratios.size());
  for (auto it = ratios.begin(), other = fresh_ratios.begin(); it != ratios.end(); ++it, ++other) {
    ASSERT_EQ(it->first, other->first);
    EXPECT_NEAR(it->second, other->second, 1e-10 * other->second);
  }
  EXPECT_EQ(kept.certified, computed.certified);
  EXPECT_NEAR(kept.largest_ratio, computed.largest_ratio, 1e-10 * computed.largest_ratio);
  EXPECT_EQ(computed.cells_checked, static_cast<int>(fresh_ratios.size()));
  EXPECT_GT(first.cells_checked, 0);
  // The combinations away from the slab's pieces keep theirs.
  EXPECT_GE(kept.cells_checked, 1);
  EXPECT_LT(kept.cells_checked, computed.cells_checked);
}

TEST(IntegralMemory, ABuildWithAnotherPenaltyTakesNothing) {
  const PolyhedralMesh grid = unit_cube_mesh(ElementType::hex8, 3);
  const DgLinearSystem before = system_of(grid, 20);
  const DgLinearSystem same = system_of(grid, 20, before.integral_memory());
  const DgLinearSystem doubled = system_of(grid, 40, before.integral_memory());
  EXPECT_EQ(same.similarity().remembered_cell_classes, same.similarity().cell_classes);
  EXPECT_EQ(same.similarity().remembered_face_classes, same.similarity().face_classes);
  // A class taken is the matrix the build before integrated, bit for bit.
  EXPECT_EQ(largest_difference(same.stiffness(), before.stiffness()), 0.0);
  EXPECT_EQ(doubled.similarity().remembered_cell_classes, 0);
  EXPECT_EQ(doubled.similarity().remembered_face_classes, 0);
  EXPECT_GT(largest_difference(doubled.stiffness(), before.stiffness()), 0.0);
  // `same` moved the matrices out: a second rebuild from `before` integrates every class
  // again, to the same K.
  const DgLinearSystem again = system_of(grid, 20, before.integral_memory());
  EXPECT_EQ(again.similarity().remembered_cell_classes, 0);
  EXPECT_EQ(again.similarity().remembered_face_classes, 0);
  EXPECT_LE(largest_difference(again.stiffness(), before.stiffness()),
            1e-12 * before.stiffness().coeffs().cwiseAbs().maxCoeff());
}

}  // namespace
}  // namespace altfem::dg
