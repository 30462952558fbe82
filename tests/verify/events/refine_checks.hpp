#pragma once
// What the refine tests check alike: the patch test's affine field on the 1 × 0.1 × 0.1 m
// cantilever (E = 1e8 Pa, ν = 0.3) and its exact energy, the refine event limited to the
// clamped half, a refine event refused before the run, and the static L-shaped beam's
// energy after refinement cycles.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "app/method_registry.hpp"
#include "shared/common/error.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/scene/scene_override.hpp"
#include "shared/simulation/run_simulation.hpp"
#include "shared/simulation/simulation.hpp"

namespace altfem {

/// The cantilever the refine tests run, clamped at x = 0.
inline const std::filesystem::path cantilever_refine_scene =
    std::filesystem::path(ALTFEM_SOURCE_DIR) / "tests/verify/events/scenes/cantilever_refine.json";

/// Its refine event limited to the half next to the clamp, x ≤ 0.5 m, so that split cells
/// meet unsplit ones across faces holding hanging nodes.
inline const SceneOverride clamp_half =
    parse_scene_override("events/0/refine/region={\"box\": {\"min\": [0, -1, -1], \"max\": [0.5, 1, 1]}}");

/// The affine displacement the patch tests carry across a refinement: u = G x.
inline Eigen::Matrix3d patch_gradient() {
  Eigen::Matrix3d gradient;
  gradient << 1e-3, 0, 2e-4, 3e-4, -1e-4, 0, -2e-4, 0, 5e-4;
  return gradient;
}
inline Eigen::Vector3d patch_field(const Eigen::Vector3d& x) { return patch_gradient() * x; }

/// Its strain energy on the cantilever: ½ ε:C:ε × 0.01 m³, ε the symmetric part of G.
inline double patch_energy() {
  const Eigen::Matrix3d strain = 0.5 * (patch_gradient() + patch_gradient().transpose());
  const double E = 1e8, nu = 0.3, lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  return (0.5 * lambda * strain.trace() * strain.trace() + mu * strain.squaredNorm()) * 0.01;
}

/// A refine event the method refuses before the run (MethodInstance::refine_refusal):
/// building its Simulation throws an InputError naming the event and saying `why`.
inline void expect_refine_refused(const Scene& scene, const std::string& method_name, const std::string& why) {
  const SceneGeometry geometry = load_scene_geometry(scene);
  const MethodDescription& method = cli::find_method(method_name);
  try {
    Simulation simulation(scene, geometry, method_name, method.factory, method.rebuild);
    ADD_FAILURE() << method_name << " refined: " << why;
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("/events/0/refine: cannot refine with " + method_name + ": " + why),
              std::string::npos)
        << error.what();
  }
}

/// The DOFs and the total energy of the last solve of the static L-shaped beam
/// (tests/verify/events/scenes/l_beam.json) with `overrides`, run by `method`: the last line
/// of log.txt (step, time, dofs, iterations, linear iterations, residual, total energy, …).
inline std::pair<double, double> l_beam_solution(const std::string& method, const std::vector<SceneOverride>& overrides,
                                                 const std::string& name) {
  const Scene scene =
      load_scene(std::filesystem::path(ALTFEM_SOURCE_DIR) / "tests/verify/events/scenes/l_beam.json", overrides);
  const std::filesystem::path output =
      std::filesystem::path(ALTFEM_BINARY_DIR) / ("verify_refine_" + method + "_" + name);
  std::filesystem::remove_all(output);
  const nlohmann::json summary =
      run_simulation(scene, load_scene_geometry(scene), method, cli::find_method(method), output, 0.0);
  EXPECT_EQ(summary["status"], "ok") << name;
  std::ifstream log(output / "log.txt");
  std::string line, last;
  while (std::getline(log, line))
    if (!line.empty() && line[0] != '#') last = line;
  std::istringstream fields(last);
  double step, time, dofs, iterations, linear_iterations, residual, energy;
  fields >> step >> time >> dofs >> iterations >> linear_iterations >> residual >> energy;
  std::filesystem::remove_all(output);
  return {dofs, energy};
}

/// A refine event at t = 0 by the error indicator with `marking` ("\"fraction\": 0.5" or a
/// threshold), re-solving `cycles` times.
inline SceneOverride refine_cycles(const std::string& marking, int max_level, int cycles) {
  return parse_scene_override("events=[{\"time\": 0, \"refine\": {\"criterion\": \"error_indicator\", " + marking +
                              ", \"max_level\": " + std::to_string(max_level) +
                              ", \"cycles\": " + std::to_string(cycles) + "}}]");
}

/// Issue #34's claim on the L-shaped beam, for `method` with `base` overrides: `cycles`
/// of bulk marking (half the estimated error) from the base grid reach the energy of the
/// uniform grid `uniform` sets with at most a third of its DOFs. For a conforming method
/// integrated exactly, Π(u_h) − Π(u) = ½ |u − u_h|²_E: a lower energy is a smaller error.
inline void expect_adaptive_reaches_uniform_with_a_third_of_the_dofs(const std::string& method,
                                                                     const SceneOverride& base,
                                                                     const SceneOverride& uniform, int cycles) {
  const auto [uniform_dofs, uniform_energy] = l_beam_solution(method, {base, uniform}, "uniform");
  const auto [adaptive_dofs, adaptive_energy] =
      l_beam_solution(method, {base, refine_cycles("\"fraction\": 0.5", 10, cycles)}, "adaptive");
  EXPECT_LE(adaptive_energy, uniform_energy);
  EXPECT_LE(adaptive_dofs, uniform_dofs / 3);
}

}  // namespace altfem
