// Stiffness warping (Kaufmann et al. 2009 §6) on a hexahedral grid and on a sliced
// sphere (cut cells: general polyhedra): the warped terms at rest sum to the linear
// stiffness, a rigid rotation of 90° gives zero internal force (linear DG's is printed:
// large), and an affine deformation R(I + S) gives the forces of the stretch S rotated by
// R — the stresses of the patch test, exact in the corotated frame.
#include <gtest/gtest.h>
#include <omp.h>

#include <Eigen/Geometry>
#include <cstdio>

#include "dg/dg_method.hpp"
#include "dg/polyhedral_mesh_faces.hpp"
#include "dg/warped_dg_discretization.hpp"
#include "shared/common/error.hpp"
#include "shared/mesh/slice_into_polyhedra.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "tests/unit/dg/hex_grid_cells.hpp"
#include "tests/unit/dg/lame_parameters.hpp"
#include "tests/unit/dg/scene_file.hpp"
#include "tests/unit/surfaces.hpp"

namespace altfem::dg {
namespace {

struct Mesh {
  const char* name;
  std::vector<Polyhedron> cells;
  std::vector<DgFace> faces;
};

// A free body (no Dirichlet face) unless `held`, where every boundary face carries condition 0.
std::vector<Mesh> meshes(bool held) {
  std::vector<Mesh> result;
  test::GridCells grid = test::hex_grid_cells(3);
  result.push_back({"hex grid 3^3", grid.cells, grid.faces});
  SlicingOptions options;
  options.resolution = 3;
  const SlicedMesh sliced =
      slice_into_polyhedra(altfem::test::sphere(0.8, 12, 24, Eigen::Vector3d(0.03, -0.02, 0.01)), options);
  result.push_back({"sliced sphere", mesh_cells(sliced.mesh), mesh_faces(sliced.mesh)});
  for (Mesh& mesh : result)
    for (DgFace& face : mesh.faces)
      if (face.plus < 0) face.condition = held ? 0 : -1;
  return result;
}

WarpedDgDiscretization warped(const DgLinearSystem& system, const DgSettings& settings) {
  std::vector<std::vector<int>> element_dofs(system.cell_count());
  for (int cell = 0; cell < system.cell_count(); ++cell)
    for (int dof = 3 * system.offset(cell); dof < 3 * system.offset(cell + 1); ++dof) element_dofs[cell].push_back(dof);
  return WarpedDgDiscretization(system, settings, system.function_integrals(), std::move(element_dofs),
                                [&system](double) { return Eigen::VectorXd::Zero(system.dof_count()).eval(); });
}

const Eigen::Matrix3d quarter_turn =
    Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d(1, 1, 1).normalized()).toRotationMatrix();

TEST(DgWarping, WarpedTermsAtRestSumToTheLinearStiffness) {
  for (const Mesh& mesh : meshes(true))
    for (Flux flux : {Flux::interior_penalty, Flux::babuska_zlamal}) {
      const DgSettings settings{2, flux, 40.0, lambda, mu};
      const DgLinearSystem system(mesh.cells, mesh.faces, settings);
      const WarpedDgDiscretization discretization = warped(system, settings);
      Eigen::SparseMatrix<double> hessian = discretization.hessian_pattern();
      discretization.hessian(Eigen::VectorXd::Zero(system.dof_count()), hessian, false);
      const Eigen::MatrixXd difference = Eigen::MatrixXd(hessian) - Eigen::MatrixXd(system.stiffness());
      EXPECT_LE(difference.cwiseAbs().maxCoeff(), 1e-12 * system.stiffness().coeffs().cwiseAbs().maxCoeff())
          << mesh.name;
    }
}

TEST(DgWarping, ARigidQuarterTurnGivesNoInternalForce) {
  std::printf("  %-14s %6s %16s %16s\n", "mesh", "degree", "|f| linear", "|f| warped");
  for (const Mesh& mesh : meshes(false))
    for (int degree : {1, 2}) {
      const DgSettings settings{degree, Flux::interior_penalty, 40.0, lambda, mu};
      const DgLinearSystem system(mesh.cells, mesh.faces, settings);
      const WarpedDgDiscretization discretization = warped(system, settings);
      const Eigen::Vector3d centre(0.3, 0.5, -0.2), shift(1, -2, 0.5);
      const Eigen::VectorXd u = system.interpolate([&](const Eigen::Vector3d& x) {
        return ((quarter_turn - Eigen::Matrix3d::Identity()) * (x - centre) + shift).eval();
      });
      Eigen::VectorXd force;
      discretization.gradient(u, force);
      const double linear = (system.stiffness() * u).norm();
      std::printf("  %-14s %6d %16.3e %16.3e\n", mesh.name, degree, linear, force.norm());
      EXPECT_GT(linear, 1.0);
      EXPECT_LE(force.norm(), 1e-10 * linear) << mesh.name;
      EXPECT_LE(std::abs(discretization.energy(u)), 1e-12 * 0.5 * u.dot(system.stiffness() * u)) << mesh.name;
      for (const Eigen::Matrix3d& rotation : discretization.rotations(u))
        EXPECT_LE((rotation - quarter_turn).norm(), 1e-12);
    }
}

TEST(DgWarping, ARotatedAffineStretchGivesTheStretchForcesRotated) {
  Eigen::Matrix3d stretch;  // symmetric: the strain of the patch test
  stretch << 0.02, 0.005, -0.01, 0.005, -0.015, 0.003, -0.01, 0.003, 0.01;
  for (const Mesh& mesh : meshes(false)) {
    const DgSettings settings{2, Flux::interior_penalty, 40.0, lambda, mu};
    const DgLinearSystem system(mesh.cells, mesh.faces, settings);
    const WarpedDgDiscretization discretization = warped(system, settings);
    const Eigen::Matrix3d deformation = quarter_turn * (Eigen::Matrix3d::Identity() + stretch);
    const Eigen::VectorXd u = system.interpolate(
        [&](const Eigen::Vector3d& x) { return ((deformation - Eigen::Matrix3d::Identity()) * x).eval(); });
    const Eigen::VectorXd stretched =
        system.interpolate([&](const Eigen::Vector3d& x) { return (stretch * x).eval(); });
    Eigen::VectorXd force;
    discretization.gradient(u, force);
    Eigen::VectorXd expected = system.stiffness() * stretched;  // the linear patch test's forces
    for (Eigen::Index a = 0; a < expected.size(); a += 3)
      expected.segment<3>(a) = quarter_turn * expected.segment<3>(a);
    EXPECT_LE((force - expected).norm(), 1e-10 * expected.norm()) << mesh.name;
  }
}

// What warping does not cover in this build is refused with the key named: a moving
// Dirichlet condition (its data load would have to follow the rotation) and a nonlinear
// material (already rotation-invariant).
// The warped force and tangent are scattered colour by colour in parallel: 1 and 2
// threads give bit-identical results (an 8³ grid has enough blocks for parallel loops).
TEST(DgWarping, OneAndTwoThreadsBitIdentical) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(2);  // the discretization sizes its per-thread scratch for this
  test::GridCells grid = test::hex_grid_cells(8);
  for (DgFace& face : grid.faces)
    if (face.plus < 0) face.condition = 0;
  const DgSettings settings{1, Flux::interior_penalty, 40.0, lambda, mu};
  const DgLinearSystem system(grid.cells, grid.faces, settings);
  const WarpedDgDiscretization discretization = warped(system, settings);
  const Eigen::Matrix3d map = 1.1 * quarter_turn - Eigen::Matrix3d::Identity();
  const Eigen::VectorXd u = system.interpolate([&](const Eigen::Vector3d& x) {
    return (map * x + 0.01 * Eigen::Vector3d(std::sin(3 * x.y()), x.x() * x.z(), std::cos(2 * x.x()))).eval();
  });
  const auto evaluate = [&](int threads) {
    omp_set_num_threads(threads);
    Eigen::VectorXd gradient;
    discretization.gradient(u, gradient);
    Eigen::SparseMatrix<double> hessian = discretization.hessian_pattern();
    discretization.hessian(u, hessian, false);
    return std::tuple(discretization.energy(u), gradient, Eigen::VectorXd(hessian.coeffs()));
  };
  const auto [energy_two, gradient_two, hessian_two] = evaluate(2);
  const auto [energy_one, gradient_one, hessian_one] = evaluate(1);
  omp_set_num_threads(saved);
  EXPECT_EQ(energy_one, energy_two);
  EXPECT_TRUE(gradient_one == gradient_two);
  EXPECT_TRUE(hessian_one == hessian_two);
  EXPECT_GT(gradient_one.norm(), 0.0);
}

// A moving condition on every boundary face, g(x, 1) = (Q(I + S) − I)(x − c) + t: a
// rigid quarter turn Q of a stretched body. At u = g the warped residual vanishes — the
// Nitsche data −∫ P R_Kᵀ g·σ(v)n rotated back with R_K matches the rotated strain terms —
// while the unrotated data load (what a moving condition would meet without rotating
// it) leaves a residual of the size of the forces (printed).
TEST(DgWarping, AMovingConditionsDataIsRotatedWithTheBoundaryElement) {
  const Eigen::Matrix3d stretch{{0.02, 0.01, 0.0}, {0.01, -0.01, 0.005}, {0.0, 0.005, 0.015}};
  const Eigen::Matrix3d map = quarter_turn * (Eigen::Matrix3d::Identity() + stretch) - Eigen::Matrix3d::Identity();
  const Eigen::Vector3d centre(0.3, 0.5, -0.2), shift(1, -2, 0.5);
  const ConditionTrajectory trajectory = [&](int, const Eigen::Vector3d& x, double time) {
    return (time * (map * (x - centre) + shift)).eval();
  };
  std::printf("  %-14s %6s %18s %18s\n", "mesh", "degree", "|r| rotated data", "|r| unrotated data");
  for (const Mesh& mesh : meshes(true))
    for (int degree : {1, 2}) {
      const DgSettings settings{degree, Flux::interior_penalty, 40.0, lambda, mu};
      const DgLinearSystem system(mesh.cells, mesh.faces, settings);
      const auto data = [&](int condition, const Eigen::Vector3d& x) { return trajectory(condition, x, 1.0); };
      std::vector<std::vector<int>> element_dofs(system.cell_count());
      for (int cell = 0; cell < system.cell_count(); ++cell)
        for (int dof = 3 * system.offset(cell); dof < 3 * system.offset(cell + 1); ++dof)
          element_dofs[cell].push_back(dof);
      const WarpedDgDiscretization moving(
          system, settings, system.function_integrals(), element_dofs,
          [&](double) { return system.dirichlet_load(data, true); }, trajectory);
      const WarpedDgDiscretization fixed = warped(system, settings);
      const Eigen::VectorXd u = system.interpolate([&](const Eigen::Vector3d& x) { return data(0, x); });
      moving.set_time(1.0);
      Eigen::VectorXd rotated, unrotated;
      moving.gradient(u, rotated);
      rotated -= moving.external_force(1.0);
      fixed.gradient(u, unrotated);
      unrotated -= system.dirichlet_load(data);
      const double scale = system.dirichlet_load(data, true).norm();
      std::printf("  %-14s %6d %18.3e %18.3e\n", mesh.name, degree, rotated.norm() / scale, unrotated.norm() / scale);
      EXPECT_LT(rotated.norm(), 1e-10 * scale) << mesh.name << " k = " << degree;
      EXPECT_GT(unrotated.norm(), 1e-2 * scale) << mesh.name << " k = " << degree;
    }
}

TEST(DgWarping, NonlinearMaterialsAreRefused) {
  const auto file = test::write_scene_file("warping_nonlinear", R"({
    "geometry": { "shape": { "box": { "min": [0, 0, 0], "max": [2, 1, 1] } } },
    "material": { "model": "neo_hookean", "youngs_modulus": 1e6, "poisson_ratio": 0.3 },
    "boundary_conditions": [ { "type": "dirichlet", "region": { "box": { "min": [-1, -1, -1], "max": [0, 2, 2] } },
      "motion": { "kind": "fixed" } } ],
    "time": { "static": true },
    "discretization": { "dg": { "warping": true, "flux": "babuska_zlamal", "resolution": [2, 1, 1] } } })");
  std::string message;
  try {
    const Scene scene = load_scene(file);
    make_dg_method(scene, load_scene_geometry(scene));
  } catch (const InputError& error) {
    message = error.what();
  }
  EXPECT_NE(message.find("/discretization/dg/warping"), std::string::npos) << message;
}

}  // namespace
}  // namespace altfem::dg
