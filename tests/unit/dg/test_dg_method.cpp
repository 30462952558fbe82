// The dg method through the MethodInstance / Discretization interfaces: weakly imposed
// moving conditions (Kaufmann et al. 2009 §4.2) reproduce an exact affine solution,
// the automatic penalty doubling (§8) ends at the first definite K, the block-Jacobi
// preconditioner solves the system with PCG, the volume output is per element, a
// nonlinear material runs through the shared assembly (by default with the lifted interior
// penalty when its conditions are `fixed`, else Babuška–Zlámal), and material regions give
// each cell its own material.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <tuple>

#include "dg/dg_method.hpp"
#include "shared/common/eigen_decompositions.hpp"
#include "shared/common/error.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/solve/linear_solver.hpp"
#include "tests/support/static_solve.hpp"

namespace altfem::dg {
namespace {

// A 2 × 1 × 1 bar, x = 0 fixed and x = 2 pulled by `pull` along x over one second.
// `solver`: the scene's solver block, or empty for the defaults.
std::filesystem::path write_bar_scene(const std::string& name, const std::string& material, const std::string& dg,
                                      const std::string& solver = "") {
  const auto folder = std::filesystem::path(ALTFEM_BINARY_DIR) / "unit_dg";
  std::filesystem::create_directories(folder);
  const auto file = folder / (name + ".json");
  std::ofstream(file) << R"({ "geometry": { "shape": { "box": { "min": [0, 0, 0], "max": [2, 1, 1] } } },
    "material": )" << material
                      << R"(,
    "boundary_conditions": [
      { "type": "dirichlet", "region": { "box": { "min": [-1, -1, -1], "max": [0, 2, 2] } } },
      { "type": "dirichlet", "region": { "box": { "min": [2, -1, -1], "max": [3, 2, 2] } },
        "motion": { "kind": "translate", "displacement": [0.02, 0, 0], "duration": 1 } } ],
    "time": { "static": true },)"
                      << (solver.empty() ? "" : R"( "solver": )" + solver + ",") << R"(
    "discretization": { "dg": )"
                      << dg << R"( } })";
  return file;
}

const std::string linear_no_contraction = R"({ "model": "linear", "youngs_modulus": 1e6, "poisson_ratio": 0.0 })";

struct Built {
  Scene scene;
  SceneGeometry geometry;
  std::unique_ptr<MethodInstance> method;
};

Built build(const std::filesystem::path& file) {
  Built built;
  built.scene = load_scene(file);
  built.geometry = load_scene_geometry(built.scene);
  built.method = make_dg_method(built.scene, built.geometry);
  return built;
}

// The one-line InputError message of a scene the dg method must refuse (fails if accepted).
std::string bad_input_message(const std::filesystem::path& file) {
  try {
    (void)build(file);
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << file << " was accepted";
  return "";
}

Eigen::VectorXd solve(const Discretization& discretization, const Eigen::VectorXd& load) {
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver(discretization.hessian_pattern());
  return solver.solve(load);
}

// With ν = 0 the pulled bar's exact displacement is u = (0.01 x, 0, 0) at t = 1 (half at
// t = ½): affine, in every degree's space, so the consistent IP flux reproduces it.
TEST(DgMethod, WeakMovingConditionsReproduceTheAffineSolution) {
  for (int degree : {1, 2}) {
    const Built built =
        build(write_bar_scene("pulled_bar_" + std::to_string(degree), linear_no_contraction,
                              R"({ "degree": )" + std::to_string(degree) + R"(, "resolution": [2, 1, 1] })"));
    const Discretization& discretization = built.method->discretization();
    EXPECT_TRUE(discretization.imposes_conditions_weakly());
    EXPECT_TRUE(discretization.constrained_dofs().empty());
    for (double time : {0.5, 1.0}) {
      const Eigen::VectorXd u = solve(discretization, discretization.external_force(time));
      const Eigen::VectorXd exact = built.method->interpolate(
          [time](const Eigen::Vector3d& x) { return Eigen::Vector3d(0.01 * time * x.x(), 0, 0); });
      EXPECT_LT((u - exact).cwiseAbs().maxCoeff(), 1e-10) << "degree " << degree << ", t = " << time;
    }
  }
}

// The same bar with the conditions imposed strongly (dg/strong_conditions.hpp): the static
// solve of the shared integrator eliminates the constrained coefficients at their values
// for the translation at t = 1, and the solution is again the affine field — with the
// linear material (exact integration) and with a Neo-Hookean one (the tabulated path,
// lifted interior penalty), whose uniaxial stretch u = (0.01 x, 0, 0) at ν = 0 is exact
// too: P = μ(F − F⁻ᵀ) is constant and vanishes on the lateral faces. (Babuška–Zlámal's
// flux is not consistent: it misses the affine field across interior faces, strong
// conditions or weak.)
TEST(DgMethod, StrongMovingConditionsReproduceTheAffineSolution) {
  const std::string neo_hookean = R"({ "model": "neo_hookean", "youngs_modulus": 1e6, "poisson_ratio": 0.0 })";
  for (const auto& [name, material, tolerance] :
       {std::tuple{"linear", linear_no_contraction, 1e-10}, std::tuple{"neo_hookean", neo_hookean, 1e-8}})
    for (int degree : {1, 2}) {
      const test::StaticRun run = test::static_run(
          write_bar_scene(std::string("pulled_bar_strong_") + name + "_" + std::to_string(degree), material,
                          R"({ "degree": )" + std::to_string(degree) +
                              R"(, "resolution": [2, 1, 1], "conditions": "strong", "flux": "interior_penalty" })"),
          make_dg_method, {});
      const Discretization& discretization = run.method->discretization();
      EXPECT_FALSE(discretization.imposes_conditions_weakly());
      EXPECT_FALSE(discretization.constrained_dofs().empty());
      const Eigen::VectorXd exact =
          run.method->interpolate([](const Eigen::Vector3d& x) { return Eigen::Vector3d(0.01 * x.x(), 0, 0); });
      EXPECT_LT((run.displacement - exact).cwiseAbs().maxCoeff(), tolerance) << name << ", degree " << degree;
    }
}

TEST(DgMethod, StrongConditionsWithWarpingAreBadInputNamingTheKey) {
  const std::string message =
      bad_input_message(write_bar_scene("strong_warped_bar", linear_no_contraction,
                                        R"({ "resolution": [2, 1, 1], "conditions": "strong", "warping": true })"));
  EXPECT_NE(message.find("/discretization/dg/conditions"), std::string::npos) << message;
}

// Uniaxial tension with lateral contraction (ν = 0.3): rollers prescribe only u_x on the
// x faces, u_y on y = 0 and u_z on z = 0; the exact u = ε(x, −νy, −νz) is affine, and the
// projected Nitsche terms reproduce it.
TEST(DgMethod, ConditionsOnSomeComponentsReproduceUniaxialTension) {
  const auto folder = std::filesystem::path(ALTFEM_BINARY_DIR) / "unit_dg";
  std::filesystem::create_directories(folder);
  const auto file = folder / "rollers.json";
  std::ofstream(file) << R"({ "geometry": { "shape": { "box": { "min": [0, 0, 0], "max": [2, 1, 1] } } },
    "material": { "model": "linear", "youngs_modulus": 1e6, "poisson_ratio": 0.3 },
    "boundary_conditions": [
      { "type": "dirichlet", "region": { "box": { "min": [-1, -1, -1], "max": [0, 2, 2] } }, "components": ["x"] },
      { "type": "dirichlet", "region": { "box": { "min": [2, -1, -1], "max": [3, 2, 2] } }, "components": ["x"],
        "motion": { "kind": "translate", "displacement": [0.02, 0, 0], "duration": 1 } },
      { "type": "dirichlet", "region": { "box": { "min": [-1, -1, -1], "max": [3, 0, 2] } }, "components": ["y"] },
      { "type": "dirichlet", "region": { "box": { "min": [-1, -1, -1], "max": [3, 2, 0] } }, "components": ["z"] } ],
    "time": { "static": true },
    "discretization": { "dg": { "degree": 2, "element": "tet4", "resolution": [2, 1, 1] } } })";
  const Built built = build(file);
  const Discretization& discretization = built.method->discretization();
  const Eigen::VectorXd u = solve(discretization, discretization.external_force(1.0));
  const Eigen::VectorXd exact = built.method->interpolate(
      [](const Eigen::Vector3d& x) { return Eigen::Vector3d(0.01 * x.x(), -0.003 * x.y(), -0.003 * x.z()); });
  EXPECT_LT((u - exact).cwiseAbs().maxCoeff(), 1e-10);
  // Strongly, a corner cell would need one change of basis for an x and a y condition.
  std::ifstream input(file);
  std::string text((std::istreambuf_iterator<char>(input)), std::istreambuf_iterator<char>());
  text.replace(text.find(R"("degree": 2)"), 11, R"("degree": 2, "conditions": "strong")");
  std::ofstream(folder / "rollers_strong.json") << text;
  const std::string message = bad_input_message(folder / "rollers_strong.json");
  EXPECT_NE(message.find("/discretization/dg/conditions"), std::string::npos) << message;
  EXPECT_NE(message.find("/boundary_conditions/"), std::string::npos) << message;
}

// Babuška–Zlámal is inconsistent (§4.1): the same bar is only approximated.
TEST(DgMethod, BabuskaZlamalOnlyApproximatesTheAffineSolution) {
  const Built built = build(write_bar_scene("pulled_bar_bz", linear_no_contraction,
                                            R"({ "degree": 1, "flux": "babuska_zlamal", "resolution": [2, 1, 1] })"));
  const Discretization& discretization = built.method->discretization();
  const Eigen::VectorXd u = solve(discretization, discretization.external_force(1.0));
  const Eigen::VectorXd exact =
      built.method->interpolate([](const Eigen::Vector3d& x) { return Eigen::Vector3d(0.01 * x.x(), 0, 0); });
  const double error = (u - exact).cwiseAbs().maxCoeff();
  EXPECT_GT(error, 1e-6);
  EXPECT_LT(error, 0.01);  // of the 0.02 end displacement
}

bool cholesky_succeeds(const Eigen::SparseMatrix<double>& matrix) {
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> factor(matrix);
  return factor.info() == Eigen::Success;
}

// The implicit integrators take dg's mass as M v and as M added into the Hessian, from its
// element blocks: the same as the mass on K's pattern (which they no longer build, a copy
// of K's size), to round-off.
TEST(DgMethod, MassTimesAndAddMassAgreeWithTheMassMatrix) {
  const Built built =
      build(write_bar_scene("mass_bar", linear_no_contraction, R"({ "degree": 2, "resolution": [3, 2, 2] })"));
  const Discretization& discretization = built.method->discretization();
  const Eigen::SparseMatrix<double>& mass = discretization.mass_matrix();
  const Eigen::VectorXd v = Eigen::VectorXd::LinSpaced(discretization.dof_count(), -1.0, 2.0);
  const Eigen::VectorXd expected = mass * v;
  EXPECT_LE((discretization.mass_times(v) - expected).norm(), 1e-14 * expected.norm());
  // Into zeros on the Hessian's pattern, which the mass matrix shares.
  Eigen::SparseMatrix<double> added = discretization.hessian_pattern();
  Eigen::Map<Eigen::VectorXd> values(added.valuePtr(), added.nonZeros());
  values.setZero();
  discretization.add_mass(2.5, added);
  const Eigen::Map<const Eigen::VectorXd> mass_values(mass.valuePtr(), mass.nonZeros());
  ASSERT_EQ(added.nonZeros(), mass.nonZeros());
  EXPECT_LE((values - 2.5 * mass_values).lpNorm<Eigen::Infinity>(), 1e-14 * mass_values.lpNorm<Eigen::Infinity>());
  Eigen::SparseMatrix<double> other_pattern(discretization.dof_count(), discretization.dof_count());
  other_pattern.makeCompressed();
  EXPECT_THROW(discretization.add_mass(1.0, other_pattern), std::logic_error);
}

// A penalty far too small for IP on tetrahedra: doubling stops at the first η whose K
// has a Cholesky factor, and half of it has none.
TEST(DgMethod, PenaltyIsDoubledUntilTheStiffnessIsDefinite) {
  const std::string material = R"({ "model": "linear", "youngs_modulus": 1e6, "poisson_ratio": 0.3 })";
  const auto block = [](double value, bool doubling) {
    return R"({ "degree": 2, "element": "tet4", "resolution": [2, 1, 1], "penalty": { "value": )" +
           std::to_string(value) + R"(, "double_until_definite": )" + (doubling ? "true" : "false") + " } }";
  };
  const Built doubled = build(write_bar_scene("doubled", material, block(0.01, true)));
  const nlohmann::json penalty = doubled.method->facts()["penalty"];
  const int doublings = penalty["doublings"].get<int>();
  ASSERT_GT(doublings, 0);
  EXPECT_TRUE(cholesky_succeeds(doubled.method->discretization().hessian_pattern()));
  const double half = penalty["value"].get<double>() / 2;
  const Built halved = build(write_bar_scene("halved", material, block(half, false)));
  EXPECT_FALSE(cholesky_succeeds(halved.method->discretization().hessian_pattern()));
  std::printf("  penalty 0.01 doubled %d times to %g\n", doublings, penalty["value"].get<double>());
}

// With an iterative solver the run needs no factor, and the test of definiteness takes
// none either (issue #35): block-Jacobi PCG on a random right-hand side breaks down on an
// indefinite K. It must double the penalty exactly as often as the Cholesky test.
TEST(DgMethod, PcgDecidesDefinitenessAsTheFactorisationDoes) {
  const std::string material = R"({ "model": "linear", "youngs_modulus": 1e6, "poisson_ratio": 0.3 })";
  for (const double value : {0.01, 0.3, 3.0}) {
    SCOPED_TRACE(value);
    const std::string block = R"({ "degree": 2, "element": "tet4", "resolution": [2, 1, 1], "penalty": { "value": )" +
                              std::to_string(value) + " } }";
    const Built direct = build(write_bar_scene("definite_direct", material, block));
    const Built iterative = build(write_bar_scene("definite_pcg", material, block, R"({ "linear": "pcg" })"));
    EXPECT_EQ(iterative.method->facts()["penalty"]["doublings"], direct.method->facts()["penalty"]["doublings"]);
  }
}

TEST(DgMethod, BlockJacobiPcgSolvesTheSystem) {
  const Built built =
      build(write_bar_scene("pcg_bar", R"({ "model": "linear", "youngs_modulus": 1e6, "poisson_ratio": 0.3 })",
                            R"({ "degree": 2, "resolution": [4, 2, 2] })"));
  const Discretization& discretization = built.method->discretization();
  const Eigen::VectorXd load = discretization.external_force(1.0) + discretization.body_force({0, 0, -9.81});
  LinearSolverOptions options;
  options.kind = LinearSolverKind::pcg;
  options.custom_preconditioner = discretization.preconditioner_factory();
  ASSERT_TRUE(options.custom_preconditioner);
  const auto solver = make_linear_solver(options);
  solver->factorize(discretization.hessian_pattern());
  Eigen::VectorXd u(load.size());
  solver->solve(load, u);
  const Eigen::VectorXd direct = solve(discretization, load);
  EXPECT_LT((u - direct).norm(), 1e-8 * direct.norm());
  std::printf("  block-Jacobi PCG: %ld iterations for %d DOFs\n", solver->statistics().iterations,
              discretization.dof_count());
}

TEST(DgMethod, VolumeOutputGivesEachElementItsOwnField) {
  const Built built =
      build(write_bar_scene("output_bar", linear_no_contraction, R"({ "degree": 1, "resolution": [2, 1, 1] })"));
  // Different affine fields on the two cubes: u = x on x < 1, u = 2x on x > 1.
  Eigen::VectorXd u = built.method->interpolate([](const Eigen::Vector3d& x) { return x; });
  const Eigen::VectorXd twice =
      built.method->interpolate([](const Eigen::Vector3d& x) { return Eigen::Vector3d(2 * x); });
  u.tail(u.size() / 2) = twice.tail(u.size() / 2);  // the second cell's 12 DOFs
  const UnstructuredGrid grid = built.method->volume_grid(u);
  ASSERT_EQ(grid.cell_count(), 2);
  ASSERT_EQ(grid.points.rows(), 16);  // 8 corners per cell, none shared
  const Eigen::MatrixXd& displacement = grid.point_data.front().second;
  for (Eigen::Index p = 0; p < 16; ++p) {
    const double factor = p < 8 ? 1.0 : 2.0;
    EXPECT_LT((displacement.row(p) - factor * grid.points.row(p)).norm(), 1e-12) << p;
  }
}

// A static Neo-Hookean 2 × 1 × 1 bar held at x = 0, with `more_conditions` (JSON to append
// to the conditions, from ",") and the dg block `dg`.
std::filesystem::path write_static_neo_hookean_bar(const std::string& name, const std::string& more_conditions,
                                                   const std::string& dg) {
  const auto file = std::filesystem::path(ALTFEM_BINARY_DIR) / "unit_dg" / (name + ".json");
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file) << R"({ "geometry": { "shape": { "box": { "min": [0, 0, 0], "max": [2, 1, 1] } } },
    "material": { "model": "neo_hookean", "youngs_modulus": 1e6, "poisson_ratio": 0.3 },
    "boundary_conditions": [
      { "type": "dirichlet", "region": { "box": { "min": [-1, -1, -1], "max": [0, 2, 2] } } })"
                      << more_conditions << R"( ],
    "time": { "static": true },
    "discretization": { "dg": )"
                      << dg << R"( } })";
  return file;
}

TEST(DgMethod, InteriorPenaltyWithANonlinearMaterialAndAPartialConditionIsBadInputNamingBoth) {
  const auto file = write_static_neo_hookean_bar("neo_hookean_roller_bar",
                                                 R"(,
      { "type": "dirichlet", "region": { "box": { "min": [2, -1, -1], "max": [3, 2, 2] } }, "components": ["x"] })",
                                                 R"({ "flux": "interior_penalty", "resolution": [2, 1, 1] })");
  const std::string message = bad_input_message(file);
  EXPECT_NE(message.find("/discretization/dg/flux"), std::string::npos) << message;
  EXPECT_NE(message.find("/boundary_conditions/1/components"), std::string::npos) << message;
}

TEST(DgMethod, ASplitPenaltyUnderKaufmannsConventionIsBadInputNamingTheKey) {
  const auto file = write_static_neo_hookean_bar(
      "kaufmann_split_bar", "",
      R"({ "resolution": [2, 1, 1], "penalty": { "convention": "kaufmann", "lame_split": true } })");
  const std::string message = bad_input_message(file);
  EXPECT_NE(message.find("/discretization/dg/penalty/lame_split"), std::string::npos) << message;
}

// A moving condition: Babuška–Zlámal by default, interior penalty (its data lifted into F
// at every set_time) on request.
TEST(DgMethod, ANonlinearMaterialWithAMovingConditionTakesEitherFlux) {
  const std::string neo_hookean = R"({ "model": "neo_hookean", "youngs_modulus": 1e6, "poisson_ratio": 0.3 })";
  const Built by_default = build(write_bar_scene("neo_hookean_bar", neo_hookean, R"({ "resolution": [2, 1, 1] })"));
  EXPECT_EQ(by_default.method->facts()["flux"], "babuska_zlamal");
  EXPECT_GT(by_default.method->quadrature_points(), 0);
  const Built lifted = build(
      write_bar_scene("neo_hookean_ip_bar", neo_hookean, R"({ "flux": "interior_penalty", "resolution": [2, 1, 1] })"));
  EXPECT_EQ(lifted.method->facts()["flux"], "interior_penalty");
}

// With `fixed` conditions only, a nonlinear material defaults to the consistent interior
// penalty of the lifted DG gradient (dg/lifted_gradients.hpp): each cell's element lists
// its face neighbours' functions too, so its Hessian couples them.
TEST(DgMethod, ANonlinearMaterialWithFixedConditionsDefaultsToTheLiftedInteriorPenalty) {
  const auto file =
      write_static_neo_hookean_bar("neo_hookean_hanging_bar", "", R"({ "degree": 1, "resolution": [2, 1, 1] })");
  const Built built = build(file);
  EXPECT_EQ(built.method->facts()["flux"], "interior_penalty");
  const Discretization& discretization = built.method->discretization();
  // The two cells' 4 + 4 functions couple through the lifting: a dense 24 × 24 pattern.
  EXPECT_EQ(discretization.hessian_pattern().nonZeros(), 24 * 24);
  EXPECT_TRUE(discretization.forces_have_potential());
}

// `materials` with regions: the pulled bar of E = 1e6 for x < 1 and 3e6 for x > 1 (ν = 0)
// stretches piecewise affinely with equal stress on both sides, a₁ = 3a₂, a₁ + a₂ = 0.02:
// IP of degree 1 reproduces it only if each cell has its region's material.
TEST(DgMethod, MaterialRegionsGiveEachCellItsMaterial) {
  const auto file = std::filesystem::path(ALTFEM_BINARY_DIR) / "unit_dg" / "two_material_bar.json";
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file) << R"({ "geometry": { "shape": { "box": { "min": [0, 0, 0], "max": [2, 1, 1] } } },
    "materials": [
      { "model": "linear", "youngs_modulus": 1e6, "poisson_ratio": 0.0 },
      { "model": "linear", "youngs_modulus": 3e6, "poisson_ratio": 0.0,
        "region": { "box": { "min": [1, -1, -1], "max": [3, 2, 2] } } } ],
    "boundary_conditions": [
      { "type": "dirichlet", "region": { "box": { "min": [-1, -1, -1], "max": [0, 2, 2] } } },
      { "type": "dirichlet", "region": { "box": { "min": [2, -1, -1], "max": [3, 2, 2] } },
        "motion": { "kind": "translate", "displacement": [0.02, 0, 0], "duration": 1 } } ],
    "time": { "static": true },
    "discretization": { "dg": { "degree": 1, "resolution": [4, 1, 1], "embedding": "element" } } })";
  const Built built = build(file);
  const Discretization& discretization = built.method->discretization();
  const Eigen::VectorXd u = solve(discretization, discretization.external_force(1.0));
  // Each vertex by its own cell's field (MLS, the default embedding, would round the
  // kink: it reproduces affine fields only). At the surface's vertices (interpolate's collocation points may leave a
  // cell and cross the kink): u_x = 0.015 x for x ≤ 1, 0.015 + 0.005 (x − 1) beyond.
  const Eigen::MatrixXd& vertices = built.method->embedded_surface().vertices;
  const Eigen::MatrixXd displacement = built.method->embedded_displacement(u);
  for (Eigen::Index v = 0; v < vertices.rows(); ++v) {
    const double x = vertices(v, 0);
    const Eigen::Vector3d exact(x <= 1 ? 0.015 * x : 0.015 + 0.005 * (x - 1), 0, 0);
    EXPECT_LT((displacement.row(v).transpose() - exact).norm(), 1e-12) << "vertex " << v;
  }
}

// PETSc's coarse level (multigrid_coarse_space.hpp, tested there) is offered under linear
// solver petsc with p_multigrid, the one solver that uses it: one function per vertex of
// the 2 × 1 × 1 bar for degree 2 (36 coarse unknowns against 60), with the linear material
// and a nonlinear one (the tabulated path); none for degree 1 (36 against 24) or under
// strong conditions, nor for the direct solver.
TEST(DgMethod, OffersPetscsCoarseLevelOnlyToPetsc) {
  const std::string petsc = R"({ "linear": "petsc" })";
  const auto coarse_functions = [&](const std::string& name, const std::string& dg, const std::string& solver,
                                    const std::string& material = linear_no_contraction) {
    const Built built = build(write_bar_scene(name, material, dg, solver));
    return built.method->discretization().coarse_space().fine_function.size();
  };
  EXPECT_EQ(coarse_functions("coarse_space_2", R"({ "degree": 2, "resolution": [2, 1, 1] })", petsc), 12u);
  EXPECT_EQ(coarse_functions("coarse_space_nonlinear", R"({ "degree": 2, "resolution": [2, 1, 1] })", petsc,
                             R"({ "model": "neo_hookean", "youngs_modulus": 1e6, "poisson_ratio": 0.3 })"),
            12u);
  EXPECT_EQ(coarse_functions("coarse_space_direct", R"({ "degree": 2, "resolution": [2, 1, 1] })", ""), 0u);
  EXPECT_EQ(coarse_functions("coarse_space_whole", R"({ "degree": 2, "resolution": [2, 1, 1] })",
                             R"({ "linear": "petsc", "p_multigrid": false })"),
            0u);
  EXPECT_EQ(coarse_functions("coarse_space_1", R"({ "degree": 1, "resolution": [2, 1, 1] })", petsc), 0u);
  EXPECT_EQ(coarse_functions("coarse_space_strong",
                             R"({ "degree": 2, "resolution": [2, 1, 1], "conditions": "strong" })", petsc),
            0u);
}

}  // namespace
}  // namespace altfem::dg
