// Strongly imposed Dirichlet conditions on DG's monomials (dg/strong_conditions.hpp): the
// constrained combinations of a cell's monomials carry the condition, so
//  - whatever the free coefficients, the trace on a strong face equals affine data
//    (one, two and three strong faces per cell: the corner cells of a grid);
//  - a condition on some components holds those and leaves the others free;
//  - the interior-penalty solution of an affine field imposed strongly on the whole
//    boundary is that field (patch test), on hexahedra (k = 1, 2, 3) and on the cut cells
//    of a ball (k = 1, 2).
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <random>

#include "dg/polyhedral_mesh_faces.hpp"
#include "dg/strong_conditions.hpp"
#include "shared/mesh/slice_into_polyhedra.hpp"
#include "shared/quadrature/polyhedron_rule.hpp"
#include "tests/unit/dg/hex_grid_cells.hpp"
#include "tests/unit/surfaces.hpp"

namespace altfem::dg {
namespace {

const Eigen::Matrix3d affine_matrix = (Eigen::Matrix3d() << 0.1, 0.2, -0.1, 0.05, 0.3, 0.2, -0.2, 0.1, 0.4).finished();
const Eigen::Vector3d affine_offset(0.3, -0.1, 0.2);
Eigen::Vector3d affine(const Eigen::Vector3d& x) { return affine_matrix * x + affine_offset; }

// Coefficients with the constrained DOFs at their values for the affine data and random
// free ones.
Eigen::VectorXd random_with_conditions(const DgLinearSystem& system) {
  std::mt19937 generator(5);
  std::uniform_real_distribution<double> uniform(-1, 1);
  Eigen::VectorXd u = Eigen::VectorXd::NullaryExpr(system.dof_count(), [&] { return uniform(generator); });
  const Eigen::VectorXd values = system.constrained_values([](int, const Eigen::Vector3d& x) { return affine(x); });
  for (size_t d = 0; d < system.constrained_dofs().size(); ++d) u[system.constrained_dofs()[d]] = values[d];
  return u;
}

// max over strong faces' rule points and prescribed components of |u_h − g|.
double trace_error(const DgLinearSystem& system, const Eigen::VectorXd& u) {
  double worst = 0;
  Eigen::VectorXd phi;
  Eigen::MatrixXd gradients;
  for (const DgFace& face : system.faces()) {
    if (!face.strong) continue;
    const PolyhedronRule rule = polygon_rule(face.polygon, 6);
    for (Eigen::Index q = 0; q < rule.weights.size(); ++q) {
      const Eigen::Vector3d x = rule.points.row(q).transpose();
      system.basis(face.minus).evaluate(x, phi, gradients);
      Eigen::Vector3d value = Eigen::Vector3d::Zero();
      for (Eigen::Index a = 0; a < phi.size(); ++a) value += phi[a] * u.segment<3>(3 * (system.offset(face.minus) + a));
      for (int i = 0; i < 3; ++i)
        if (face.components[i]) worst = std::max(worst, std::abs(value[i] - affine(x)[i]));
    }
  }
  return worst;
}

test::GridCells strong_grid(int n, const std::array<bool, 3>& components) {
  test::GridCells grid = test::hex_grid_cells(n);
  for (DgFace& face : grid.faces)
    if (face.plus < 0) {
      face.strong = true;
      face.components = components;
    }
  return grid;
}

class StrongConditionsOfDegree : public ::testing::TestWithParam<int> {};

TEST_P(StrongConditionsOfDegree, TheTraceOnEveryStrongFaceIsTheAffineData) {
  const test::GridCells grid = strong_grid(2, {true, true, true});  // every cell a corner: 3 strong faces
  const DgLinearSystem system(grid.cells, grid.faces, {GetParam(), Flux::interior_penalty, 40, 1.0, 1.0});
  EXPECT_LT(trace_error(system, random_with_conditions(system)), 1e-12);
}

TEST_P(StrongConditionsOfDegree, APartialConditionHoldsItsComponentsOnly) {
  const test::GridCells grid = strong_grid(2, {true, false, true});
  const DgLinearSystem system(grid.cells, grid.faces, {GetParam(), Flux::interior_penalty, 40, 1.0, 1.0});
  const Eigen::VectorXd u = random_with_conditions(system);
  EXPECT_LT(trace_error(system, u), 1e-12);
  for (int dof : system.constrained_dofs()) EXPECT_NE(dof % 3, 1) << "a y coefficient is constrained";
  // Fewer DOFs are held than with all three components.
  test::GridCells all_components = strong_grid(2, {true, true, true});
  const DgLinearSystem full(all_components.cells, all_components.faces,
                            {GetParam(), Flux::interior_penalty, 40, 1.0, 1.0});
  EXPECT_GT(full.constrained_dofs().size(), system.constrained_dofs().size());
}

// K u = 0 on the free DOFs with the constrained ones prescribed.
Eigen::VectorXd solve_with_conditions(const DgLinearSystem& system) {
  const int n = system.dof_count();
  std::vector<int> free_index(n, 0);
  for (int dof : system.constrained_dofs()) free_index[dof] = -1;
  int free_count = 0;
  for (int& index : free_index)
    if (index == 0) index = free_count++;
  Eigen::VectorXd u = random_with_conditions(system);
  Eigen::VectorXd fixed = u;
  for (int d = 0; d < n; ++d)
    if (free_index[d] >= 0) fixed[d] = 0;
  const Eigen::VectorXd load = -(system.stiffness() * fixed);
  std::vector<Eigen::Triplet<double>> triplets;
  const Eigen::SparseMatrix<double>& stiffness = system.stiffness();
  for (int column = 0; column < stiffness.outerSize(); ++column)
    for (Eigen::SparseMatrix<double>::InnerIterator it(stiffness, column); it; ++it)
      if (free_index[it.row()] >= 0 && free_index[column] >= 0)
        triplets.emplace_back(free_index[it.row()], free_index[column], it.value());
  Eigen::SparseMatrix<double> free_matrix(free_count, free_count);
  free_matrix.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::VectorXd free_load(free_count);
  for (int d = 0; d < n; ++d)
    if (free_index[d] >= 0) free_load[free_index[d]] = load[d];
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(free_matrix);
  const Eigen::VectorXd free_solution = solver.solve(free_load);
  for (int d = 0; d < n; ++d)
    if (free_index[d] >= 0) u[d] = free_solution[free_index[d]];
  return u;
}

double relative_l2_error(const DgLinearSystem& system, const Eigen::VectorXd& u) {
  return system.l2_error(u, affine) / system.l2_error(Eigen::VectorXd::Zero(u.size()), affine);
}

TEST_P(StrongConditionsOfDegree, InteriorPenaltyReproducesAnAffineFieldOnAGrid) {
  const test::GridCells grid = strong_grid(3, {true, true, true});
  const DgLinearSystem system(grid.cells, grid.faces, {GetParam(), Flux::interior_penalty, 40, 1.0, 1.0});
  const double error = relative_l2_error(system, solve_with_conditions(system));
  std::printf("  k = %d, 3^3 grid: relative L2 error %.2e\n", GetParam(), error);
  EXPECT_LT(error, 1e-10);
}

// Degrees 1 and 2 (k = 3 on these cut cells takes seconds and only shows round-off, 9e-10).
class StrongConditionsOnCutCells : public ::testing::TestWithParam<int> {};

TEST_P(StrongConditionsOnCutCells, InteriorPenaltyReproducesAnAffineField) {
  SlicingOptions options;
  options.resolution = 4;
  const PolyhedralMesh mesh =
      slice_into_polyhedra(altfem::test::sphere(0.5, 8, 12, Eigen::Vector3d::Zero()), options).mesh;
  std::vector<DgFace> faces = mesh_faces(mesh);
  for (DgFace& face : faces)
    if (face.plus < 0) face.condition = 0, face.strong = true;
  const DgLinearSystem system(mesh_cells(mesh), faces, {GetParam(), Flux::interior_penalty, 40, 1.0, 1.0});
  ASSERT_FALSE(system.constrained_dofs().empty());
  const double error = relative_l2_error(system, solve_with_conditions(system));
  std::printf("  k = %d, sliced ball: relative L2 error %.2e\n", GetParam(), error);
  EXPECT_LT(error, 1e-10);
}

INSTANTIATE_TEST_SUITE_P(Degrees, StrongConditionsOfDegree, ::testing::Values(1, 2, 3));
INSTANTIATE_TEST_SUITE_P(Degrees, StrongConditionsOnCutCells, ::testing::Values(1, 2));

}  // namespace
}  // namespace altfem::dg
