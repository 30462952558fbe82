// The lifted DG gradient of nonlinear materials (dg/lifted_gradients.hpp, Ten Eyck & Lew
// 2006): a continuous polynomial field of degree ≤ k lifts to zero (its DG gradient is its
// gradient); the energy's gradient and Hessian match finite differences for Neo-Hookean
// and Stable Neo-Hookean; and an affine finite deformation (10% stretch + 10% shear),
// held weakly on one face and loaded by its exact traction on the others, is reproduced
// by Newton to round-off on a hex grid and on a sliced (cut-cell) box — which the
// Babuška–Zlámal flux does not do (both errors printed); and so is the same deformation
// imposed weakly on every boundary face as moving data g(x, t) = t (F̄ − I) x, lifted into
// F at set_time.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <cmath>
#include <cstdio>

#include "dg/lifted_gradients.hpp"
#include "dg/polyhedral_mesh_faces.hpp"
#include "dg/tabulated_dg.hpp"
#include "shared/material/material.hpp"
#include "shared/mesh/slice_into_polyhedra.hpp"
#include "shared/quadrature/polyhedron_rule.hpp"
#include "tests/unit/dg/hex_grid_cells.hpp"
#include "tests/unit/random_vectors.hpp"
#include "tests/unit/surfaces.hpp"

namespace altfem::dg {
namespace {

constexpr double youngs_modulus = 1e3, poisson_ratio = 0.3;

DgSettings settings_of(const Material& material, int degree, Flux flux) {
  return {degree, flux, 20 * youngs_modulus, material.lame().lambda, material.lame().mu, material.density(), 1.0};
}

TabulatedDg tabulated(const DgLinearSystem& system, const Material& material) {
  return make_tabulated_dg(system, {&material},
                           [&](double) { return Eigen::VectorXd::Zero(system.dof_count()).eval(); }, {});
}

class LiftedGradientsOfDegree : public ::testing::TestWithParam<int> {};

TEST_P(LiftedGradientsOfDegree, AContinuousPolynomialFieldLiftsToZero) {
  const int k = GetParam();
  const auto material = make_material(MaterialModel::neo_hookean, youngs_modulus, poisson_ratio, 1.0);
  test::GridCells grid = test::hex_grid_cells(2);
  for (DgFace& face : grid.faces) face.condition = -1;  // free: only interior jumps are lifted
  const DgLinearSystem system(grid.cells, grid.faces, settings_of(*material, k, Flux::interior_penalty));
  // A global polynomial of degree k and its gradient.
  const auto field = [k](const Eigen::Vector3d& x) {
    Eigen::Vector3d u(0.3 * x.x() - 0.2 * x.y() + 0.1, 0.5 * x.z() + 0.25 * x.x(), -0.4 * x.y() + 0.7 * x.z());
    if (k >= 2) u += Eigen::Vector3d(x.x() * x.y(), x.z() * x.z() - x.x() * x.z(), 2 * x.y() * x.y());
    return u;
  };
  const auto gradient = [k](const Eigen::Vector3d& x) {
    Eigen::Matrix3d g;
    g << 0.3, -0.2, 0, 0.25, 0, 0.5, 0, -0.4, 0.7;
    if (k >= 2) {
      g(0, 0) += x.y(), g(0, 1) += x.x();
      g(1, 0) -= x.z(), g(1, 2) += 2 * x.z() - x.x();
      g(2, 1) += 4 * x.y();
    }
    return g;
  };
  const Eigen::VectorXd u = system.interpolate(field);
  const int strength = 2 * k;
  const TabulatedElements lifted = tabulate_lifted_dg_cells(system, strength).elements;
  Eigen::MatrixXd points;
  const TabulatedElements plain = tabulate_dg_cells(system, strength, &points);
  ASSERT_EQ(lifted.point_count(), plain.point_count());
  double worst = 0;
  long long row = 0;
  for (int e = 0; e < lifted.size(); ++e) {
    const ElementView element = lifted[e];
    for (int q = 0; q < element.point_count(); ++q, ++row) {
      Eigen::Matrix3d dg_gradient = Eigen::Matrix3d::Zero();
      for (int a = 0; a < element.basis_count(); ++a)
        dg_gradient += u.segment<3>(3 * element.basis[a]) * element.gradients_at(q).row(a);
      worst = std::max(worst, (dg_gradient - gradient(points.row(row).transpose())).cwiseAbs().maxCoeff());
    }
  }
  EXPECT_LT(worst, 1e-12);
}

// Directional finite differences of the energy (central, step h) against the gradient,
// and of the gradient against the Hessian, at a random displacement of moderate strain.
TEST_P(LiftedGradientsOfDegree, GradientAndHessianMatchFiniteDifferences) {
  const int k = GetParam();
  const test::GridCells grid = test::hex_grid_cells(2);  // every boundary face held (condition 0)
  for (MaterialModel model : {MaterialModel::neo_hookean, MaterialModel::stable_neo_hookean}) {
    const auto material = make_material(model, youngs_modulus, poisson_ratio, 1.0);
    const DgLinearSystem system(grid.cells, grid.faces, settings_of(*material, k, Flux::interior_penalty));
    const TabulatedDg dg = tabulated(system, *material);
    const Discretization& discretization = *dg.discretization;
    const Eigen::VectorXd u = 0.02 * altfem::test::random_vector(system.dof_count(), 7);
    Eigen::VectorXd gradient, plus, minus;
    discretization.gradient(u, gradient);
    Eigen::SparseMatrix<double> hessian = discretization.hessian_pattern();
    discretization.hessian(u, hessian, false);
    for (unsigned seed : {1u, 2u, 3u}) {
      const Eigen::VectorXd direction = altfem::test::random_vector(system.dof_count(), seed);
      const double h = 1e-6;
      const double energy_difference =
          (discretization.energy(u + h * direction) - discretization.energy(u - h * direction)) / (2 * h);
      EXPECT_NEAR(energy_difference, gradient.dot(direction), 1e-6 * gradient.norm() * direction.norm())
          << material_model_name(model) << " k = " << k;
      discretization.gradient(u + h * direction, plus);
      discretization.gradient(u - h * direction, minus);
      const Eigen::VectorXd hessian_times_direction = hessian * direction;
      EXPECT_LT(((plus - minus) / (2 * h) - hessian_times_direction).norm(), 1e-6 * hessian_times_direction.norm())
          << material_model_name(model) << " k = " << k;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Degrees, LiftedGradientsOfDegree, ::testing::Values(1, 2));

struct Mesh {
  const char* name;
  std::vector<Polyhedron> cells;
  std::vector<DgFace> faces;
};

// The boundary faces on z = 0 hold the body (condition 0, g = 0); the others are free.
std::vector<Mesh> patch_meshes() {
  std::vector<Mesh> meshes;
  test::GridCells grid = test::hex_grid_cells(2);
  meshes.push_back({"hex grid 2^3", grid.cells, grid.faces});
  SlicingOptions options;
  options.resolution = 3;
  const SlicedMesh sliced = slice_into_polyhedra(
      altfem::test::box_surface(Eigen::Vector3d::Zero(), Eigen::Vector3d(1.0, 0.7, 0.55)), options);
  meshes.push_back({"sliced box", mesh_cells(sliced.mesh), mesh_faces(sliced.mesh)});
  for (Mesh& mesh : meshes)
    for (DgFace& face : mesh.faces)
      if (face.plus < 0)
        face.condition = face.normal.z() < -0.5 && std::abs(face.polygon.col(2).maxCoeff()) < 1e-12 ? 0 : -1;
  return meshes;
}

// ∫_f t·φ_a dA over the free boundary faces for the nominal traction t = P N.
Eigen::VectorXd traction_load(const DgLinearSystem& system, const Eigen::Matrix3d& stress) {
  Eigen::VectorXd load = Eigen::VectorXd::Zero(system.dof_count());
  Eigen::VectorXd phi;
  Eigen::MatrixXd gradients;
  for (const DgFace& face : system.faces()) {
    if (face.plus >= 0 || face.condition >= 0) continue;
    const Eigen::Vector3d traction = stress * face.normal;
    const PolyhedronRule rule = polygon_rule(face.polygon, 2 * system.basis(face.minus).degree());
    for (Eigen::Index p = 0; p < rule.weights.size(); ++p) {
      system.basis(face.minus).evaluate(rule.points.row(p).transpose(), phi, gradients);
      for (Eigen::Index a = 0; a < phi.size(); ++a)
        load.segment<3>(3 * (system.offset(face.minus) + a)) += rule.weights[p] * phi[a] * traction;
    }
  }
  return load;
}

// Newton on gradient(u) = load from u = 0 (full steps: the strain is moderate).
Eigen::VectorXd solve(const Discretization& discretization, const Eigen::VectorXd& load) {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(discretization.dof_count()), residual;
  Eigen::SparseMatrix<double> hessian = discretization.hessian_pattern();
  for (int iteration = 0; iteration < 30; ++iteration) {
    discretization.gradient(u, residual);
    residual -= load;
    if (residual.norm() <= 1e-11 * load.norm()) break;
    discretization.hessian(u, hessian, false);
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor(hessian);
    u -= factor.solve(residual);
  }
  return u;
}

TEST(LiftedGradients, AnAffineFiniteDeformationPassesThePatchTest) {
  // u* = (F̄ − I) X vanishes on z = 0: 10% stretch along z and 10% shear of x along z.
  Eigen::Matrix3d deformation = Eigen::Matrix3d::Identity();
  deformation(0, 2) = 0.1;
  deformation(2, 2) = 1.1;
  const auto exact = [&](const Eigen::Vector3d& x) {
    return Eigen::Vector3d((deformation - Eigen::Matrix3d::Identity()) * x);
  };
  for (MaterialModel model : {MaterialModel::neo_hookean, MaterialModel::stable_neo_hookean})
    for (const Mesh& mesh : patch_meshes())
      for (int k : {1, 2}) {
        const auto material = make_material(model, youngs_modulus, poisson_ratio, 1.0);
        double errors[2];
        for (Flux flux : {Flux::interior_penalty, Flux::babuska_zlamal}) {
          const DgLinearSystem system(mesh.cells, mesh.faces, settings_of(*material, k, flux));
          const TabulatedDg dg = tabulated(system, *material);
          const Eigen::VectorXd u = solve(*dg.discretization, traction_load(system, material->pk1(deformation)));
          errors[static_cast<int>(flux)] = (u - system.interpolate(exact)).cwiseAbs().maxCoeff();
        }
        std::printf("patch test %-18s %-13s k = %d: max coefficient error IP %.2e, BZ %.2e\n",
                    std::string(material_model_name(model)).c_str(), mesh.name, k, errors[0], errors[1]);
        EXPECT_LT(errors[static_cast<int>(Flux::interior_penalty)], 1e-9);
        EXPECT_GT(errors[static_cast<int>(Flux::babuska_zlamal)], 1e-5);
      }
}

TEST(LiftedGradients, AnAffineDeformationImposedWeaklyAsMovingDataPassesThePatchTest) {
  Eigen::Matrix3d displacement_gradient;
  displacement_gradient << 0.1, 0.05, 0, -0.03, 0, 0.1, 0.02, 0, -0.08;  // F̄ − I: stretch, shear, compression
  const auto data = [&](int, const Eigen::Vector3d& x, double time) {
    return Eigen::Vector3d(time * displacement_gradient * x);
  };
  const auto material = make_material(MaterialModel::stable_neo_hookean, youngs_modulus, poisson_ratio, 1.0);
  for (Mesh mesh : patch_meshes())
    for (int k : {1, 2}) {
      for (DgFace& face : mesh.faces)
        if (face.plus < 0) face.condition = 0;  // every boundary face held by the data
      const DgLinearSystem system(mesh.cells, mesh.faces, settings_of(*material, k, Flux::interior_penalty));
      const auto penalty_load = [&](double time) {
        return system.dirichlet_load([&](int c, const Eigen::Vector3d& x) { return data(c, x, time); }, true);
      };
      const TabulatedDg dg = make_tabulated_dg(system, {material.get()}, penalty_load, {}, data);
      for (double time : {0.5, 1.0}) {
        dg.discretization->set_time(time);
        const Eigen::VectorXd u = solve(*dg.discretization, dg.discretization->external_force(time));
        const double error =
            (u - system.interpolate([&](const Eigen::Vector3d& x) { return data(0, x, time); })).cwiseAbs().maxCoeff();
        std::printf("weak affine data %-13s k = %d, t = %.1f: max coefficient error %.2e\n", mesh.name, k, time, error);
        EXPECT_LT(error, 1e-9) << mesh.name << " k = " << k << " t = " << time;
      }
    }
}

}  // namespace
}  // namespace altfem::dg
