// The tabulated DG of nonlinear materials (dg/tabulated_dg.hpp) against the exact
// matrices: with the linear material and the Babuška–Zlámal flux, its rules of strength
// 2k integrate every product exactly, so its Hessian, mass and body force equal the
// exact ones (Kaufmann et al. 2009 §5) to round-off, for k = 1, 2, 3 — with Dirichlet
// faces on all components and on some, and with the penalty isotropic or split into
// normal and tangential parts (Hansbo & Larson 2002).
#include <gtest/gtest.h>

#include <cmath>

#include "dg/tabulated_dg.hpp"
#include "shared/material/material.hpp"
#include "tests/unit/dg/hex_grid_cells.hpp"

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
    const DgSettings settings{GetParam(), Flux::babuska_zlamal, 20 * 1e3,
                              material->lame().lambda, material->lame().mu, material->density(),
                              1.0, PenaltyScaling::cell_surface, tangential_fraction};
    const DgLinearSystem system(grid.cells, grid.faces, settings);
    const TabulatedDg tabulated =
        make_tabulated_dg(system, {material.get()}, [&](double) { return Eigen::VectorXd::Zero(system.dof_count()).eval(); }, {});
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
    EXPECT_LT((discretization.body_force(gravity) - exact_load).cwiseAbs().maxCoeff(), 1e-12 * exact_load.cwiseAbs().maxCoeff());
  }
}

INSTANTIATE_TEST_SUITE_P(Degrees, TabulatedDgOfDegree, ::testing::Values(1, 2, 3));

}  // namespace
}  // namespace altfem::dg
