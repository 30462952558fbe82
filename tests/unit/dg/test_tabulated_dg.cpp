// The tabulated DG of nonlinear materials (dg/tabulated_dg.hpp) against the exact
// matrices: with the linear material and the Babuška–Zlámal flux, its rules of strength
// 2k integrate every product exactly, so its Hessian, mass and body force equal the
// exact ones (Kaufmann et al. 2009 §5) to round-off, for k = 1, 2, 3 — with Dirichlet
// faces on all components and on some, and with the penalty isotropic or split into
// normal and tangential parts (Hansbo & Larson 2002); and so do its simplified rules
// on the cut cells of a sliced sphere, with at most C(2k + 3, 3) points per cell.
#include <gtest/gtest.h>

#include <cmath>

#include "dg/polyhedral_mesh_faces.hpp"
#include "dg/tabulated_dg.hpp"
#include "shared/geometry/monomial_index.hpp"
#include "shared/material/material.hpp"
#include "shared/mesh/slice_into_polyhedra.hpp"
#include "tests/unit/dg/hex_grid_cells.hpp"
#include "tests/unit/surfaces.hpp"

namespace altfem::dg {
namespace {

class TabulatedDgOfDegree : public ::testing::TestWithParam<int> {};

TEST_P(TabulatedDgOfDegree, LinearBabuskaZlamalEqualsTheExactMatrices) {
  const auto material = make_material(MaterialModel::linear, 1e3, 0.3, 7.0);
  test::GridCells grid = test::hex_grid_cells(2);
  // Rollers on the x faces: only x is prescribed there (the masked penalty).
  for (DgFace& face : grid.faces)
    if (face.plus < 0 && std::abs(face.normal.x()) > 0.5) face.components = {true, false, false};
  for (const double tangential_fraction : {1.0, 0.3}) {
    const DgSettings settings{GetParam(),          Flux::babuska_zlamal, 20 * 1e3, material->lame().lambda,
                              material->lame().mu, material->density(),  1.0,      PenaltyScaling::cell_surface,
                              tangential_fraction};
    const DgLinearSystem system(grid.cells, grid.faces, settings);
    const TabulatedDg tabulated = make_tabulated_dg(
        system, {material.get()}, [&](double) { return Eigen::VectorXd::Zero(system.dof_count()).eval(); }, {});
    const Discretization& discretization = *tabulated.discretization;
    ASSERT_EQ(discretization.dof_count(), system.dof_count());
    Eigen::SparseMatrix<double> hessian = discretization.hessian_pattern();
    discretization.hessian(Eigen::VectorXd::Zero(system.dof_count()), hessian, false);
    const double scale = Eigen::MatrixXd(system.stiffness()).cwiseAbs().maxCoeff();
    EXPECT_LT(Eigen::MatrixXd(hessian - system.stiffness()).cwiseAbs().maxCoeff(), 1e-10 * scale);
    const Eigen::SparseMatrix<double> mass = system.mass();
    EXPECT_LT(Eigen::MatrixXd(discretization.mass_matrix() - mass).cwiseAbs().maxCoeff(),
              1e-12 * Eigen::MatrixXd(mass).cwiseAbs().maxCoeff());
    const Eigen::Vector3d gravity(0, 0, -9.81);
    Eigen::VectorXd exact_load(system.dof_count());
    for (Eigen::Index a = 0; a < system.function_integrals().size(); ++a)
      exact_load.segment<3>(3 * a) = material->density() * system.function_integrals()[a] * gravity;
    EXPECT_LT((discretization.body_force(gravity) - exact_load).cwiseAbs().maxCoeff(),
              1e-12 * exact_load.cwiseAbs().maxCoeff());
  }
}

INSTANTIATE_TEST_SUITE_P(Degrees, TabulatedDgOfDegree, ::testing::Values(1, 2, 3));

TEST(TabulatedDg, SimplifiedRulesOfCutCellsGiveTheExactMatrices) {
  const auto material = make_material(MaterialModel::linear, 1e3, 0.3, 7.0);
  SlicingOptions options;
  options.resolution = 3;
  const SlicedMesh sliced =
      slice_into_polyhedra(altfem::test::sphere(0.8, 24, 48, Eigen::Vector3d(0.03, -0.02, 0.01)), options);
  std::vector<DgFace> faces = mesh_faces(sliced.mesh);
  for (DgFace& face : faces)
    if (face.plus < 0 && face.normal.z() < -0.5) face.condition = 0;
  const int degree = 2;
  DgSettings settings{
      degree, Flux::babuska_zlamal, 20 * 1e3, material->lame().lambda, material->lame().mu, material->density()};
  settings.rule_simplification = SimplificationMethod::caratheodory;
  const DgLinearSystem system(mesh_cells(sliced.mesh), faces, settings);
  const TabulatedDg tabulated = make_tabulated_dg(
      system, {material.get()}, [&](double) { return Eigen::VectorXd::Zero(system.dof_count()).eval(); }, {});
  Eigen::SparseMatrix<double> hessian = tabulated.discretization->hessian_pattern();
  tabulated.discretization->hessian(Eigen::VectorXd::Zero(system.dof_count()), hessian, false);
  const double scale = Eigen::MatrixXd(system.stiffness()).cwiseAbs().maxCoeff();
  EXPECT_LT(Eigen::MatrixXd(hessian - system.stiffness()).cwiseAbs().maxCoeff(), 1e-9 * scale);
  const Eigen::SparseMatrix<double> mass = system.mass();
  EXPECT_LT(Eigen::MatrixXd(tabulated.discretization->mass_matrix() - mass).cwiseAbs().maxCoeff(),
            1e-10 * Eigen::MatrixXd(mass).cwiseAbs().maxCoeff());
  // The cone rules of the cut cells hold many more points than the simplified ones.
  const long simplified = tabulate_dg_cells(system, 2 * degree).point_count();
  settings.rule_simplification.reset();
  const long cone =
      tabulate_dg_cells(DgLinearSystem(mesh_cells(sliced.mesh), faces, settings), 2 * degree).point_count();
  EXPECT_LE(simplified, system.cell_count() * monomial_count(2 * degree));
  EXPECT_GT(cone, 5 * simplified);
}

}  // namespace
}  // namespace altfem::dg
