#pragma once
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "shared/scene/scene.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/simulation/method_instance.hpp"
#include "shared/simulation/run_frame.hpp"
#include "shared/simulation/simulation.hpp"

namespace altfem {

/// Runs a scene with one method and writes into `output_directory` (docs/conventions.md,
/// "Command line and outputs"): summary.json, log.txt, volume.pvd + volume_NNNNNN.vtu
/// and surface.pvd + surface_NNNNNN.vtu every `output.every` steps. The scene's events act
/// between steps (Simulation::apply), each a line of log.txt and an entry of summary.json's
/// `events`.
///
/// Everything that can reject the input (building the method, its mesh, its
/// constraints) happens before the folder is created, so bad input leaves no output.
/// A numerical failure writes summary.json with status "error: …" and is rethrown.
/// `setup_seconds` is the time already spent loading the scene and its geometry;
/// `on_frame`, when set, receives every frame as it is written.
/// Returns the summary.
nlohmann::json run_simulation(const Scene& scene, const SceneGeometry& geometry, const std::string& method_name,
                              const MethodDescription& description, const std::filesystem::path& output_directory,
                              double setup_seconds = 0, const FrameObserver& on_frame = {});
/// The same for a method known by its factory alone (no event that rebuilds it).
nlohmann::json run_simulation(const Scene& scene, const SceneGeometry& geometry, const std::string& method_name,
                              const MethodFactory& factory, const std::filesystem::path& output_directory,
                              double setup_seconds = 0);

}  // namespace altfem
