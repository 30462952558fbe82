// The traction patch test (issue #21 item 3): a bar [0, L] × [0, 1] × [0, 1] on
// symmetric rollers (x = 0 holds u_x, y = 0 holds u_y, z = 0 holds u_z) under a
// uniform end traction σ e_x on x = L, or a pressure p there (σ = −p), is in uniform
// uniaxial stress: σ_xx = σ, every other component 0, and
//   u = (σ x / E, −ν σ y / E, −ν σ z / E)
// exactly, so the end moves by σ L / E. Every basis here reproduces affine fields, so
// the discrete solution is the exact one up to round-off — for every fem element type,
// fcm on a grid that cuts the end face's triangles (they are split along the cells),
// dg and harmonic.
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>

#include "tests/support/static_solve.hpp"

namespace altfem::test {
namespace {

constexpr double length = 2.0, youngs_modulus = 1000.0, poisson_ratio = 0.25;

struct PatchCase {
  std::string name;
  std::string method;
  std::string block;  // the method's discretization block
};
void PrintTo(const PatchCase& patch, std::ostream* out) { *out << patch.name; }

// The load entry: a traction σ e_x, or (pressure) p = −σ, on the end face x = L.
std::string bar_scene(const PatchCase& patch, double stress, bool as_pressure) {
  std::ostringstream load;
  load << R"({ "region": { "box": { "min": [2, -1, -1], "max": [3, 2, 2] } }, )";
  if (as_pressure) load << R"("pressure": )" << -stress << " }";
  else load << R"("traction": [)" << stress << ", 0, 0] }";
  std::ostringstream scene;
  scene << R"({
    "geometry": { "shape": { "box": { "min": [0, 0, 0], "max": [2, 1, 1] } } },
    "material": { "model": "linear", "youngs_modulus": 1000, "poisson_ratio": 0.25 },
    "boundary_conditions": [
      { "type": "dirichlet", "region": { "box": { "min": [-1, -1, -1], "max": [0, 2, 2] } }, "components": ["x"] },
      { "type": "dirichlet", "region": { "box": { "min": [-1, -1, -1], "max": [3, 0, 2] } }, "components": ["y"] },
      { "type": "dirichlet", "region": { "box": { "min": [-1, -1, -1], "max": [3, 2, 0] } }, "components": ["z"] }
    ],
    "loads": { "traction": [ )"
        << load.str() << R"( ] },
    "discretization": { ")"
        << patch.method << R"(": )" << patch.block << R"( }
  })";
  return scene.str();
}

class TractionPatch : public testing::TestWithParam<PatchCase> {
protected:
  void check(double stress, bool as_pressure) {
    const StaticRun solution = static_run_text(bar_scene(GetParam(), stress, as_pressure), GetParam().method);
    const double strain = stress / youngs_modulus;
    const auto exact = [&](const Eigen::Vector3d& x) -> Eigen::Vector3d {
      return {strain * x.x(), -poisson_ratio * strain * x.y(), -poisson_ratio * strain * x.z()};
    };
    const double end_exact = strain * length;  // the end displacement σ L / E
    const double scale = std::abs(end_exact);
    // The coefficients: the method's interpolant of the exact (affine) field.
    const Eigen::VectorXd expected = solution.method->interpolate(exact);
    EXPECT_LE((solution.displacement - expected).cwiseAbs().maxCoeff(), 1e-8 * scale);
    // The surface every method deforms, point by point.
    const SurfaceMesh& surface = solution.method->embedded_surface();
    const Eigen::MatrixXd moved = solution.method->embedded_displacement(solution.displacement);
    double worst = 0, end = 0;
    for (Eigen::Index v = 0; v < surface.vertices.rows(); ++v) {
      const Eigen::Vector3d x = surface.vertices.row(v).transpose();
      worst = std::max(worst, (moved.row(v).transpose() - exact(x)).norm());
      if (x.x() == length) end = moved(v, 0);
    }
    EXPECT_LE(worst, 1e-8 * scale);
    EXPECT_NEAR(end, end_exact, 1e-8 * scale) << "the end displacement σL/E";
    // The stress, where the method reports it (fem, fcm): the Cauchy stress
    // σ = P Fᵀ / det F (docs/conventions.md) of the linear material's P = σ e_x ⊗ e_x at
    // the exact F = diag(1 + ε, 1 − νε, 1 − νε): only σ_xx = σ (1 + ε) / det F ≠ 0.
    const Eigen::MatrixXd stresses = solution.method->discretization().element_cauchy_stress(solution.displacement);
    const Eigen::Vector3d stretches(1 + strain, 1 - poisson_ratio * strain, 1 - poisson_ratio * strain);
    Eigen::Matrix<double, 1, 9> uniaxial = Eigen::Matrix<double, 1, 9>::Zero();
    uniaxial[0] = stress * stretches.x() / stretches.prod();
    for (Eigen::Index e = 0; e < stresses.rows(); ++e)
      EXPECT_LE((stresses.row(e) - uniaxial).cwiseAbs().maxCoeff(), 1e-8 * std::abs(stress)) << "element " << e;
    std::printf("%-18s %s: end displacement %.15g (exact %.15g), %lld stress rows\n", GetParam().name.c_str(),
                as_pressure ? "pressure" : "traction", end, end_exact, static_cast<long long>(stresses.rows()));
  }
};

TEST_P(TractionPatch, UniformEndTractionGivesTheExactUniaxialState) { check(10.0, false); }

TEST_P(TractionPatch, EndPressureGivesMinusPressureAsStress) { check(-10.0, true); }

std::string grid(const std::string& key, const std::string& element, const std::string& resolution) {
  return R"({ ")" + key + R"(": ")" + element + R"(", "mesh": "grid", "resolution": )" + resolution + " }";
}

INSTANTIATE_TEST_SUITE_P(
    EveryMethod, TractionPatch,
    testing::Values(
        PatchCase{"fem_tet4", "fem", grid("element", "tet4", "[4, 2, 2]")},
        PatchCase{"fem_tet10", "fem", grid("element", "tet10", "[2, 1, 1]")},
        PatchCase{"fem_tet20", "fem", grid("element", "tet20", "[2, 1, 1]")},
        PatchCase{"fem_hex8", "fem", grid("element", "hex8", "[4, 2, 2]")},
        PatchCase{"fem_hex20", "fem", grid("element", "hex20", "[2, 1, 1]")},
        PatchCase{"fem_hex27", "fem", grid("element", "hex27", "[2, 1, 1]")},
        // 3 × 3 cells across the end face: its embedded triangles cross cells.
        PatchCase{"fcm_hex8", "fcm", R"({ "cell": "hex8", "resolution": [3, 3, 3] })"},
        PatchCase{"fcm_hex20", "fcm", R"({ "cell": "hex20", "resolution": [3, 3, 3] })"},
        PatchCase{"dg_k1", "dg", R"({ "degree": 1, "element": "hex8", "mesh": "grid", "resolution": [2, 2, 2] })"},
        PatchCase{"dg_k2_tet", "dg", R"({ "degree": 2, "element": "tet4", "mesh": "grid", "resolution": [2, 1, 1] })"},
        PatchCase{"harmonic_hex", "harmonic", R"({ "convert": )" + grid("element", "hex8", "[4, 2, 2]") + " }"},
        PatchCase{"harmonic_tet", "harmonic", R"({ "convert": )" + grid("element", "tet4", "[2, 1, 1]") + " }"}),
    [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace altfem::test
