#pragma once
// A refine event the method refuses before the run (MethodInstance::refine_refusal): building
// its Simulation throws an InputError naming the event and saying why.
#include <gtest/gtest.h>

#include <string>

#include "app/method_registry.hpp"
#include "shared/common/error.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/simulation/simulation.hpp"

namespace altfem {

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

}  // namespace altfem
