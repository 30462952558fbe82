// The face ghost penalty (Burman 2010, deal.II step-85's g_F) on background grids of
// every FCM cell: which faces it acts on, and its energy for displacements whose
// normal-derivative jumps are known in closed form — a kink (x − 1)₊ across the grid
// plane x = 1 and a curvature jump (y − 1)₊² across y = 1, interpolated exactly — so the face
// rules, normals, the traces' gradients and Hessians and the h_F^{2k−1}/(k!)² weights are
// all checked at once. Also: forces and stiffness consistent with the energy, and
// polynomials of the cell's degree cost nothing (the penalty keeps the patch test).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "shared/assembly/ghost_penalty_kernel.hpp"
#include "shared/cut_cells/ghost_penalty_faces.hpp"
#include "shared/material/material.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "tests/unit/assembly/face_term.hpp"

namespace altfem::fcm {
namespace {

using Field = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;

double corner_centroid_x(const VolumeMesh& mesh, Eigen::Index cell) {
  const int corners = element_corner_count(mesh.element_type);
  double x = 0;
  for (int a = 0; a < corners; ++a) x += mesh.nodes(mesh.cells(cell, a), 0);
  return x / corners;
}

// [0, 2]³ in 2³ cubes (h = 1); every cell cut unless `inside_below_x` (cells with
// x < 1 then count as uncut).
struct Grid {
  VolumeMesh mesh;
  GhostPenaltyFaces ghost;
};
Grid grid(ElementType type, bool inside_below_x = false) {
  Grid result{
      structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(2)), {2, 2, 2}, type), {}};
  std::vector<double> fractions;
  for (Eigen::Index c = 0; c < result.mesh.cells.rows(); ++c)
    fractions.push_back(inside_below_x && corner_centroid_x(result.mesh, c) < 1 ? 1.0 : 0.5);
  result.ghost = ghost_penalty_faces(result.mesh, fractions);
  return result;
}

Eigen::VectorXd interpolate(const VolumeMesh& mesh, const Field& field) {
  Eigen::VectorXd u(3 * mesh.nodes.rows());
  for (Eigen::Index node = 0; node < mesh.nodes.rows(); ++node)
    u.segment<3>(3 * node) = field(mesh.nodes.row(node).transpose());
  return u;
}

// The penalty with γ_F = 1 on every face.
test::FaceTerm<GhostPenaltyKernel> unit_penalty(const Grid& grid) {
  const auto faces = static_cast<size_t>(grid.ghost.faces.size());
  return {grid.ghost.faces, GhostPenaltyKernel(grid.ghost.faces, std::vector<double>(faces, 1.0), grid.ghost.sizes,
                                               element_degree(grid.mesh.element_type))};
}

// h_F of the faces in the plane x = 1: a hex face's side 1; the triangles that split
// a cube face have the face diagonal √2 as their longest edge.
double plane_face_size(ElementType type) {
  return element_shape(type) == ElementShape::tetrahedron ? std::sqrt(2.0) : 1.0;
}

class GhostPenalty : public ::testing::TestWithParam<ElementType> {};

TEST_P(GhostPenalty, ActsOnTheInteriorFacesOfCutCellsOnly) {
  const ElementType type = GetParam();
  // 2³ cubes: 12 interior cube faces; the six-tetrahedra split adds 6 triangles inside
  // every cube and halves each cube face.
  const int all = element_shape(type) == ElementShape::tetrahedron ? 8 * 6 + 2 * 12 : 12;
  EXPECT_EQ(grid(type).ghost.faces.size(), all);
  // With the x < 1 half uncut, the faces among those cells drop out: 4 cube faces
  // (plus 4 × 6 triangles inside those cubes for tets, 8 halves of the 4 faces).
  const int among_uncut = element_shape(type) == ElementShape::tetrahedron ? 4 * 6 + 2 * 4 : 4;
  EXPECT_EQ(grid(type, true).ghost.faces.size(), all - among_uncut);
}

// u = ((x − 1)₊, 0, 0): [∂ₙu] = ±1 on the plane x = 1 (area 4), 0 elsewhere, so
// E = ½ h_F Σ_F ∫_F 1 = 2 h_F.
TEST_P(GhostPenalty, KinkAcrossAGridPlaneCostsHalfHTimesItsArea) {
  const ElementType type = GetParam();
  const Grid g = grid(type);
  const auto term = unit_penalty(g);
  const Eigen::VectorXd u =
      interpolate(g.mesh, [](const Eigen::Vector3d& x) { return Eigen::Vector3d(std::max(x[0] - 1, 0.0), 0, 0); });
  EXPECT_NEAR(term.assembler.energy(u), 2 * plane_face_size(type), 1e-12);
}

// The FCM's term: γ_F = γ × the mean λ + 2μ of the two cells. Two materials split at
// x = 1 (moduli M₁ left, M₂ right): the kink's faces lie between them, so
// E = ½ γ (M₁ + M₂)/2 · h_F · 4.
TEST_P(GhostPenalty, TermScalesTheKinkByTheMeanPWaveModulus) {
  const ElementType type = GetParam();
  const Grid g = grid(type);
  const auto soft = make_material(MaterialModel::linear, 1e5, 0.3, 1000);
  const auto stiff = make_material(MaterialModel::linear, 3e6, 0.45, 1000);
  std::vector<int> cell_materials;
  for (Eigen::Index c = 0; c < g.mesh.cells.rows(); ++c)
    cell_materials.push_back(corner_centroid_x(g.mesh, c) < 1 ? 0 : 1);
  const double gamma = 0.3;
  const std::unique_ptr<EnergyTerm> term =
      ghost_penalty_term(g.ghost, type, cell_materials, {soft.get(), stiff.get()}, gamma);
  const Eigen::VectorXd u =
      interpolate(g.mesh, [](const Eigen::Vector3d& x) { return Eigen::Vector3d(std::max(x[0] - 1, 0.0), 0, 0); });
  const auto modulus = [](const Material& material) { return material.lame().lambda + 2 * material.lame().mu; };
  const double expected = 0.5 * gamma * 0.5 * (modulus(*soft) + modulus(*stiff)) * plane_face_size(type) * 4;
  EXPECT_NEAR(term->energy(u), expected, 1e-12 * expected);
}

// u = (0, 0, (y − 1)₊²) on quadratic cells: [∂ₙu] = 0 and [∂ₙ²u] = ±2 on y = 1, so
// E = ½ (h_F³ / (2!)²) 4 · 4 = 2 h_F³.
TEST(GhostPenaltyQuadratic, CurvatureJumpCostsTheSecondDerivativeTerm) {
  for (ElementType type : {ElementType::hex20, ElementType::hex27, ElementType::tet10}) {
    const Grid g = grid(type);
    const auto term = unit_penalty(g);
    const Eigen::VectorXd u = interpolate(
        g.mesh, [](const Eigen::Vector3d& x) { return Eigen::Vector3d(0, 0, std::pow(std::max(x[1] - 1, 0.0), 2)); });
    EXPECT_NEAR(term.assembler.energy(u), 2 * std::pow(plane_face_size(type), 3), 1e-11) << element_name(type);
  }
}

// Any polynomial of the cells' complete degree has no jumps: the penalty leaves the
// patch test (affine u) and, on quadratic cells, every quadratic u untouched.
TEST_P(GhostPenalty, PolynomialsOfTheCellsDegreeCostNothing) {
  const ElementType type = GetParam();
  const Grid g = grid(type);
  const auto term = unit_penalty(g);
  const Eigen::VectorXd affine = interpolate(g.mesh, [](const Eigen::Vector3d& x) {
    return Eigen::Vector3d(0.3 * x[0] - 0.2 * x[1] + 0.1, 0.5 * x[2] + 0.4 * x[0], -0.7 * x[1] + 0.2 * x[2]);
  });
  EXPECT_NEAR(term.assembler.energy(affine), 0.0, 1e-24);
  EXPECT_LT(term.gradient(affine).cwiseAbs().maxCoeff(), 1e-12);
  if (element_degree(type) < 2) return;
  const Eigen::VectorXd quadratic = interpolate(g.mesh, [](const Eigen::Vector3d& x) {
    return Eigen::Vector3d(x[0] * x[1] - 0.5 * x[2] * x[2], x[1] * x[1] + x[0], 0.3 * x[0] * x[2] - x[1] * x[2]);
  });
  EXPECT_NEAR(term.assembler.energy(quadratic), 0.0, 1e-20);
}

// On a curved (isoparametric) grid an affine field is still reproduced exactly, so its
// physical Hessian is zero: this holds only with the map's curvature term in the
// traces' Hessians (GhostPenaltyKernel's k = 2 would see a jump without it), and the
// face points must be located in the curved cell across the face.
TEST_P(GhostPenalty, AffineFieldsCostNothingOnACurvedGrid) {
  const ElementType type = GetParam();
  Grid g = grid(type);
  for (Eigen::Index node = 0; node < g.mesh.nodes.rows(); ++node) {
    const Eigen::Vector3d x = g.mesh.nodes.row(node).transpose();
    g.mesh.nodes.row(node) += 0.08 * Eigen::RowVector3d(std::sin(x[1] * x[2]), std::sin(x[0] + x[2]), x[0] * x[1] / 4);
  }
  g.ghost = ghost_penalty_faces(g.mesh, std::vector<double>(static_cast<size_t>(g.mesh.cells.rows()), 0.5));
  const auto term = unit_penalty(g);
  const Eigen::VectorXd affine = interpolate(g.mesh, [](const Eigen::Vector3d& x) {
    return Eigen::Vector3d(0.3 * x[0] - 0.2 * x[1] + 0.1, 0.5 * x[2] + 0.4 * x[0], -0.7 * x[1] + 0.2 * x[2]);
  });
  EXPECT_NEAR(term.assembler.energy(affine), 0.0, 1e-22);
  // A non-affine field does cost something (the test can fail).
  const Eigen::VectorXd kinked =
      interpolate(g.mesh, [](const Eigen::Vector3d& x) { return Eigen::Vector3d(std::max(x[0] - 1, 0.0), 0, 0); });
  EXPECT_GT(term.assembler.energy(kinked), 1e-3);
}

// Quadratic in u: E = ½ uᵀKu, ∇E = Ku, with K the assembled stiffness.
TEST_P(GhostPenalty, ForcesAndStiffnessAreTheEnergysDerivatives) {
  const Grid g = grid(GetParam());
  const auto term = unit_penalty(g);
  ASSERT_EQ(term.dof_count(), 3 * g.mesh.nodes.rows());
  const Eigen::VectorXd u = interpolate(g.mesh, [](const Eigen::Vector3d& x) {
    return Eigen::Vector3d(std::sin(2 * x[0] + x[1]), std::cos(x[2] - x[0]), x[0] * x[1] * x[2]);
  });
  const Eigen::VectorXd gradient = term.gradient(u);
  const SparseMatrix stiffness = term.hessian(u);
  const double energy = term.assembler.energy(u);
  EXPECT_GT(energy, 0);
  EXPECT_NEAR(0.5 * u.dot(stiffness * u), energy, 1e-12 * energy);
  EXPECT_LT((stiffness * u - gradient).norm(), 1e-12 * gradient.norm());
  EXPECT_LT((Eigen::MatrixXd(stiffness) - Eigen::MatrixXd(stiffness).transpose()).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(GhostPenaltyKernel, RefusesQuadraticCellsWithoutHessiansAndMismatchedSizes) {
  Grid g = grid(ElementType::hex8);  // linear cells: faces without Hessians
  const auto faces = static_cast<size_t>(g.ghost.faces.size());
  EXPECT_THROW(GhostPenaltyKernel(g.ghost.faces, std::vector<double>(faces, 1.0), g.ghost.sizes, 2),
               std::invalid_argument);
  EXPECT_THROW(GhostPenaltyKernel(g.ghost.faces, std::vector<double>(faces + 1, 1.0), g.ghost.sizes, 1),
               std::invalid_argument);
  EXPECT_THROW(GhostPenaltyKernel(g.ghost.faces, std::vector<double>(faces, 1.0), g.ghost.sizes, 3),
               std::invalid_argument);
  EXPECT_NO_THROW(GhostPenaltyKernel(g.ghost.faces, std::vector<double>(faces, 1.0), g.ghost.sizes, 1));
}

INSTANTIATE_TEST_SUITE_P(Cells, GhostPenalty,
                         ::testing::Values(ElementType::hex8, ElementType::hex20, ElementType::hex27, ElementType::tet4,
                                           ElementType::tet10),
                         [](const auto& info) { return std::string(element_name(info.param)); });

}  // namespace
}  // namespace altfem::fcm
