#pragma once
// The static solution of an event scene, what the cut tests compare with the pieces
// meshed alone: its elastic energy and ∫ρ u_z dV, each event applied after the load step
// it names, and every event checked to conserve the volume and to open the surface.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "app/method_registry.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/scene/scene_override.hpp"
#include "shared/simulation/simulation.hpp"

namespace altfem {

struct StaticAnswer {
  double energy = 0;         ///< the method's elastic energy of the solution [J]
  double vertical_mass = 0;  ///< ∫ρ u_z dV [kg m]
};

// The static solution of a scene at its last load step, each event applied after the
// load step it names.
inline StaticAnswer solve_static(const std::filesystem::path& file, const std::string& method_name,
                                 const std::vector<SceneOverride>& overrides = {}) {
  const Scene scene = load_scene(file, overrides);
  const SceneGeometry geometry = load_scene_geometry(scene);
  const MethodDescription& method = cli::find_method(method_name);
  Simulation simulation(scene, geometry, method_name, method.factory, method.rebuild);
  std::size_t next = 0;  // events act after the load steps they name
  for (int step = 0; step < scene.time.load_steps; ++step) {
    for (; next < scene.events.size() && scene.events[next].time <= step; ++next) {
      const EventRecord record = simulation.apply(scene.events[next]);
      EXPECT_LE(std::abs(record.conserved["volume_change"].get<double>()), 1e-12);
      // Every cut opens the surface the methods deform (a sweep's cuts too: each cuts the
      // surface from before the sweep, not the notch its last cut left).
      if (record.facts.contains("surface")) {
        EXPECT_EQ(record.facts["surface"]["pieces_left_whole"], 0) << next;
      }
    }
    simulation.integrator().step(simulation.state());
  }
  const Discretization& discretization = simulation.method().discretization();
  const Eigen::VectorXd& u = simulation.state().displacement;
  return {discretization.energy(u), discretization.body_force(Eigen::Vector3d::UnitZ()).dot(u)};
}

}  // namespace altfem
