// The conformance suite every method passes (issue #14): the properties any
// discretization of elasticity must have, checked through the MethodInstance and
// Discretization interfaces only, so the same tests run against every method —
// the shipped ones and the test-only two-hexahedra monomial method.
//   - a rigid translation, and a rigid rotation of a rotation-invariant material, give
//     zero internal force;
//   - the patch test: for an affine displacement u = (G − I)x the energy is V ψ(G) and
//     the virtual work against any affine v = Bx is V P(G) : B (constant stress);
//   - an affine field is embedded exactly on the scene surface;
//   - a run writes a summary.json with every required key, finite values, and output
//     files that meshio reads (tests/cli/check_run_output.py);
//   - events (docs/architecture.md, "Events"): a release frees only its condition's DOFs
//     and conserves the body exactly, and a rebuild that changes nothing leaves every DOF
//     bit-identical and the energy unchanged.
#include <gtest/gtest.h>

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "app/method_registry.hpp"
#include "shared/common/eigen_decompositions.hpp"
#include "shared/common/error.hpp"
#include "shared/material/material.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/simulation/body_force_load.hpp"
#include "shared/simulation/field_errors.hpp"
#include "shared/simulation/rigid_motion.hpp"
#include "shared/simulation/run_simulation.hpp"
#include "shared/simulation/simulation.hpp"
#include "tests/unit/conformance/conformance_measures.hpp"
#include "tests/unit/conformance/two_hex_monomial_method.hpp"

namespace altfem {
namespace {

using test::integrated_volume;
using test::internal_force;
using test::small_strain;

struct MethodCase {
  std::string name;
  MethodFactory factory;
  MethodRebuilder rebuild;  // empty for a method that cannot rebuild
};
void PrintTo(const MethodCase& method, std::ostream* out) { *out << method.name; }

// Every method registered in the executable, and the test-only one.
std::vector<MethodCase> methods_under_test() {
  std::vector<MethodCase> methods;
  for (const auto& method : cli::registered_methods())
    methods.push_back({std::string(method.scene_block.name), method.factory, method.rebuild});
  methods.push_back({"two_hex_monomial", test::make_two_hex_monomial_method, {}});
  return methods;
}

std::filesystem::path scene_path(const std::string& name) {
  return std::filesystem::path(ALTFEM_SOURCE_DIR) / "tests/unit/conformance/scenes" / name;
}

using Field = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;

Field affine(const Eigen::Matrix3d& A, const Eigen::Vector3d& b = Eigen::Vector3d::Zero()) {
  return [A, b](const Eigen::Vector3d& x) -> Eigen::Vector3d { return A * x + b; };
}

class Conformance : public ::testing::TestWithParam<MethodCase> {
protected:
  struct Built {
    Scene scene;
    SceneGeometry geometry;
    std::unique_ptr<MethodInstance> method;
    std::unique_ptr<Material> material;
  };
  static Built build(const std::string& scene_file) {
    Built built;
    built.scene = load_scene(scene_path(scene_file));
    built.geometry = load_scene_geometry(built.scene);
    built.method = GetParam().factory(built.scene, built.geometry);
    const MaterialSpec& spec = built.scene.material;
    built.material =
        make_material(*material_model_from_name(spec.model), spec.youngs_modulus, spec.poisson_ratio, spec.density);
    return built;
  }
  static double volume(const Built& built) { return integrated_volume(*built.method, built.scene.material.density); }
  static Eigen::VectorXd gradient(const Built& built, const Eigen::VectorXd& u) {
    return internal_force(*built.method, u);
  }
};

TEST_P(Conformance, VolumeIsTheGeometrysVolume) {
  const Built built = build("free_box.json");
  EXPECT_NEAR(volume(built), built.geometry.volume, 1e-12 * built.geometry.volume);
  // What events measure the volume by (MethodInstance::volume), when the method has it.
  if (const std::optional<double> integrated = built.method->volume()) {
    EXPECT_NEAR(*integrated, built.geometry.volume, 1e-12 * built.geometry.volume);
  }
}

TEST_P(Conformance, RigidTranslationGivesZeroForce) {
  const Built built = build("free_box.json");
  const Eigen::VectorXd translation = built.method->interpolate(affine(Eigen::Matrix3d::Zero(), {0.3, -0.2, 0.5}));
  const double scale = gradient(built, built.method->interpolate(affine(small_strain()))).cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0);
  EXPECT_LT(gradient(built, translation).cwiseAbs().maxCoeff(), 1e-12 * scale);
}

TEST_P(Conformance, RigidRotationGivesZeroForce) {
  const Built built = build("free_box.json");  // stable Neo-Hookean: P(R) = 0
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, -1).normalized()).toRotationMatrix();
  const Eigen::VectorXd rotation = built.method->interpolate(affine(R - Eigen::Matrix3d::Identity(), {0.1, 0, 0}));
  const double scale = gradient(built, built.method->interpolate(affine(small_strain()))).cwiseAbs().maxCoeff();
  EXPECT_LT(gradient(built, rotation).cwiseAbs().maxCoeff(), 1e-10 * scale);
}

// What the `petsc` solver hands its algebraic multigrid as the near-null space: six
// independent vectors that the stiffness of the unconstrained body (at rest, where its
// kernel is the infinitesimal rigid motions) maps to zero.
TEST_P(Conformance, RigidBodyModesSpanTheKernelOfTheStiffness) {
  const Built built = build("free_box.json");
  const Discretization& discretization = built.method->discretization();
  const Eigen::MatrixXd modes = rigid_body_modes(*built.method);
  ASSERT_EQ(modes.rows(), discretization.dof_count());
  ASSERT_EQ(modes.cols(), 6);
  EXPECT_EQ(Eigen::FullPivHouseholderQR<Eigen::MatrixXd>(modes).rank(), 6);
  Eigen::SparseMatrix<double> stiffness = discretization.hessian_pattern();
  discretization.hessian(Eigen::VectorXd::Zero(discretization.dof_count()), stiffness, false);
  const Eigen::VectorXd strain = built.method->interpolate(affine(small_strain()));
  const double scale = (stiffness * strain).norm() / strain.norm();
  ASSERT_GT(scale, 0);
  for (int mode = 0; mode < 6; ++mode)
    EXPECT_LT((stiffness * modes.col(mode)).norm(), 1e-10 * scale * modes.col(mode).norm()) << "mode " << mode;
}

TEST_P(Conformance, PatchTestGivesTheExactConstantStress) {
  const Built built = build("free_box.json");
  const Eigen::Matrix3d G = Eigen::Matrix3d::Identity() + small_strain();
  Eigen::Matrix3d B;
  B << 0.3, -0.1, 0.2, 0.05, 0.4, -0.3, 0.1, 0.2, -0.2;
  const Eigen::VectorXd u = built.method->interpolate(affine(G - Eigen::Matrix3d::Identity(), {0.01, 0.02, 0.03}));
  const Eigen::VectorXd v = built.method->interpolate(affine(B));
  const double V = volume(built);
  const double energy = V * built.material->energy(G);
  const double work = V * (built.material->pk1(G).array() * B.array()).sum();
  EXPECT_NEAR(built.method->discretization().energy(u), energy, 1e-10 * std::abs(energy));
  EXPECT_NEAR(gradient(built, u).dot(v), work, 1e-10 * std::abs(work));
}

TEST_P(Conformance, AffineFieldIsEmbeddedExactlyOnTheSurface) {
  const Built built = build("free_box.json");
  Eigen::Matrix3d A = small_strain();
  const Eigen::Vector3d b(0.1, -0.2, 0.3);
  const Eigen::MatrixXd moved = built.method->embedded_displacement(built.method->interpolate(affine(A, b)));
  const Eigen::MatrixXd& vertices = built.method->embedded_surface().vertices;
  ASSERT_EQ(moved.rows(), vertices.rows());
  const Eigen::MatrixXd expected = (vertices * A.transpose()).rowwise() + b.transpose();
  EXPECT_LT((moved - expected).cwiseAbs().maxCoeff(), 1e-12);
}

// A body force f = A x + b integrated against the basis (field_quadrature(0)): tested
// with the field 1 it is ∫ f dV = V (A c + b), c the box's centre, exactly (a linear
// integrand). Field errors of an interpolated affine field against its own expression
// vanish, and against the expression shifted by s are |s| √V (L2) and 0 (H1).
TEST_P(Conformance, FieldQuadratureIntegratesLoadsAndMeasuresErrors) {
  const Built built = build("free_box.json");
  const std::optional<FieldQuadrature> loads = built.method->field_quadrature(0);
  if (!loads) GTEST_SKIP() << "the method gives no field quadrature (body forces and field errors unavailable)";
  const VectorExpression force({"x + 2*y", "3*z - 1", "0.5*x + 4"}, {}, "scene", "/loads/body_force");
  const int dofs = built.method->discretization().dof_count();
  const Eigen::VectorXd load = integrate_against_basis(*loads, evaluate_at_points(force, loads->points, 0.0), dofs);
  const Eigen::VectorXd ones =
      built.method->interpolate([](const Eigen::Vector3d&) { return Eigen::Vector3d::Ones().eval(); });
  const Eigen::Vector3d c = built.geometry.bounds.center();
  const double V = volume(built);
  const double expected = V * ((c.x() + 2 * c.y()) + (3 * c.z() - 1) + (0.5 * c.x() + 4));
  EXPECT_NEAR(ones.dot(load), expected, 1e-10 * std::abs(expected));

  const std::optional<FieldQuadrature> errors_rule = built.method->field_quadrature(2);
  ASSERT_TRUE(errors_rule);
  const Eigen::VectorXd u = built.method->interpolate(affine(small_strain(), Eigen::Vector3d(0.1, -0.2, 0.3)));
  const Eigen::Matrix3d A = small_strain();
  const auto expression = [&](double shift) {
    std::array<std::string, 3> components;
    for (int i = 0; i < 3; ++i)
      components[i] = std::to_string(A(i, 0)) + "*x + " + std::to_string(A(i, 1)) + "*y + " + std::to_string(A(i, 2)) +
                      "*z + " + std::to_string(Eigen::Vector3d(0.1, -0.2, 0.3)[i] + shift);
    return VectorExpression(components, {}, "scene", "/exact_displacement");
  };
  // std::to_string keeps 6 decimals: small_strain()'s entries must be exact in them.
  const FieldErrors same = field_errors(*errors_rule, expression(0.0), u, 0.0);
  EXPECT_LT(same.l2, 1e-10 * same.exact_l2);
  EXPECT_LT(same.h1_seminorm, 1e-8 * same.exact_h1_seminorm);
  const FieldErrors shifted = field_errors(*errors_rule, expression(0.25), u, 0.0);
  EXPECT_NEAR(shifted.l2, 0.25 * std::sqrt(3 * V), 1e-10);
  EXPECT_LT(shifted.h1_seminorm, 1e-8 * shifted.exact_h1_seminorm);
}

// Every number in a JSON document is finite.
bool all_finite(const nlohmann::json& value) {
  if (value.is_number_float()) return std::isfinite(value.get<double>());
  if (value.is_structured())
    for (const auto& item : value)
      if (!all_finite(item)) return false;
  return true;
}

TEST_P(Conformance, RunWritesACompleteSummaryAndReadableOutput) {
  const Scene scene = load_scene(scene_path("clamped_box.json"));
  const SceneGeometry geometry = load_scene_geometry(scene);
  const auto out = std::filesystem::path(ALTFEM_BINARY_DIR) / "conformance" / GetParam().name;
  std::filesystem::remove_all(out);
  const nlohmann::json summary = run_simulation(scene, geometry, GetParam().name, GetParam().factory, out, 0.0);
  for (const char* key : {"scene", "method", "options", "dofs", "elements", "quadrature_points", "timings_s", "counts",
                          "steps", "newton_iterations", "linear_iterations", "events", "status", "surface"})
    EXPECT_TRUE(summary.contains(key)) << key;
  for (const char* key : {"setup", "quadrature", "assembly", "analysis", "factorisation", "solve", "total"})
    EXPECT_TRUE(summary["timings_s"].contains(key)) << key;
  EXPECT_EQ(summary["status"], "ok");
  EXPECT_TRUE(all_finite(summary));
  const std::string check =
      "/usr/bin/python3 " + std::string(ALTFEM_SOURCE_DIR) + "/tests/cli/check_run_output.py " + out.string();
  EXPECT_EQ(std::system(check.c_str()), 0) << "meshio disagrees with summary.json (see output above)";
}

TEST_P(Conformance, BadDiscretizationBlockIsOneLineOfBadInput) {
  if (GetParam().name == "two_hex_monomial") GTEST_SKIP() << "the test-only method has no scene block";
  const auto folder = std::filesystem::path(ALTFEM_BINARY_DIR) / "conformance";
  std::filesystem::create_directories(folder);
  const auto file = folder / ("bad_block_" + GetParam().name + ".json");
  std::ofstream(file) << R"({ "geometry": { "shape": { "box": { "min": [0, 0, 0], "max": [1, 1, 1] } } },
    "material": { "youngs_modulus": 1e6, "poisson_ratio": 0.3 },
    "discretization": { ")"
                      << GetParam().name << R"(": { "no_such_key": 1 } } })";
  try {
    // The factory resolves its own block: a method built without the CLI checks it too.
    const Scene scene = load_scene(file);
    (void)GetParam().factory(scene, load_scene_geometry(scene));
    FAIL() << "accepted an unknown key";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_NE(message.find("/discretization/" + GetParam().name + "/no_such_key"), std::string::npos) << message;
  }
}

// The released box: a clamp at x = 0 and a pull at x = 2 moving up, released at 0.02 s.
TEST_P(Conformance, ReleaseFreesItsDofsAndConservesTheBody) {
  const Scene scene = load_scene(scene_path("released_box.json"));
  const SceneGeometry geometry = load_scene_geometry(scene);
  if (GetParam().name == "two_hex_monomial") {
    // It records no condition per constrained DOF: the release is refused as bad input.
    try {
      Simulation simulation(scene, geometry, GetParam().name, GetParam().factory);
      FAIL() << "accepted a release it cannot carry out";
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find("/events/0/release"), std::string::npos) << error.what();
    }
    return;
  }
  Simulation simulation(scene, geometry, GetParam().name, GetParam().factory);
  Simulation held_on(scene, geometry, GetParam().name, GetParam().factory);  // never released
  const std::vector<int> held = simulation.discretization().constrained_dofs();
  for (int step = 0; step < 2; ++step) {
    simulation.integrator().step(simulation.state());
    held_on.integrator().step(held_on.state());
  }
  const State before = simulation.state();
  const MethodInstance* method = &simulation.method();
  const EventRecord record = simulation.apply(scene.events.front());
  // Only the pull's DOFs are freed. The method is not rebuilt (nothing re-integrated, the
  // identity transfer), and the energy through the new layers — the integrator rebound to
  // them — is the energy before: the layers change the constraints and nothing else.
  EXPECT_EQ(&simulation.method(), method);
  EXPECT_EQ(static_cast<std::size_t>(record.constrained_before), held.size());
  EXPECT_GT(record.constrained_before, record.constrained_after);
  EXPECT_GT(record.constrained_after, 0);  // the clamp still holds
  EXPECT_EQ(record.dofs_before, record.dofs_after);
  EXPECT_GT(record.conserved["energy_before_j"].get<double>(), 0.0);
  EXPECT_EQ(record.conserved["energy_jump_j"].get<double>(), 0.0);
  EXPECT_TRUE(simulation.state().displacement == before.displacement);
  // The freed DOFs now move by the dynamics, not by the pull's motion.
  std::vector<int> freed;
  const std::vector<int>& still_held = simulation.discretization().constrained_dofs();
  std::set_difference(held.begin(), held.end(), still_held.begin(), still_held.end(), std::back_inserter(freed));
  ASSERT_FALSE(freed.empty());
  simulation.integrator().step(simulation.state());
  held_on.integrator().step(held_on.state());
  double largest_difference = 0;
  for (int dof : freed)
    largest_difference = std::max(largest_difference,
                                  std::abs(simulation.state().displacement[dof] - held_on.state().displacement[dof]));
  EXPECT_GT(largest_difference, 1e-6);
}

// A rebuild on the method's own mesh changes nothing: every DOF bit for bit, the energy,
// and the steps after it (the same run without the rebuild).
TEST_P(Conformance, NoOpRebuildLeavesEveryDofBitIdentical) {
  if (!GetParam().rebuild) GTEST_SKIP() << "the method has no rebuild";
  Scene scene = load_scene(scene_path("released_box.json"));
  scene.events.clear();
  const SceneGeometry geometry = load_scene_geometry(scene);
  Simulation rebuilt(scene, geometry, GetParam().name, GetParam().factory, GetParam().rebuild);
  Simulation plain(scene, geometry, GetParam().name, GetParam().factory);
  for (int step = 0; step < 2; ++step) {
    rebuilt.integrator().step(rebuilt.state());
    plain.integrator().step(plain.state());
  }
  const State before = rebuilt.state();
  const EventRecord record = rebuilt.rebuild();
  EXPECT_TRUE(rebuilt.state().displacement == before.displacement);
  EXPECT_TRUE(rebuilt.state().velocity == before.velocity);
  EXPECT_EQ(record.dofs_before, record.dofs_after);
  EXPECT_EQ(record.constrained_before, record.constrained_after);
  EXPECT_EQ(record.quadrature_points_before, record.quadrature_points_after);
  EXPECT_EQ(record.quadrature_points_after, rebuilt.method().quadrature_points());
  EXPECT_EQ(record.conserved["energy_jump_j"].get<double>(), 0.0);
  EXPECT_EQ(record.conserved["mass_change"].get<double>(), 0.0);
  EXPECT_EQ(record.conserved["momentum_change"].get<double>(), 0.0);
  for (int step = 0; step < 2; ++step) {
    rebuilt.integrator().step(rebuilt.state());
    plain.integrator().step(plain.state());
  }
  EXPECT_LT((rebuilt.state().displacement - plain.state().displacement).cwiseAbs().maxCoeff(),
            1e-13 * plain.state().displacement.cwiseAbs().maxCoeff());
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, Conformance, ::testing::ValuesIn(methods_under_test()),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace altfem
