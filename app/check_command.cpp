#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "app/commands.hpp"
#include "app/method_registry.hpp"
#include "shared/common/error.hpp"
#include "shared/scene/method_scene_block.hpp"
#include "shared/scene/scene.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/simulation/simulation.hpp"

namespace altfem::cli {

namespace {

nlohmann::json geometry_facts(const SceneGeometry& geometry) {
  nlohmann::json facts;
  if (geometry.surface) {
    facts["kind"] = "surface";
    facts["vertices"] = geometry.surface->vertices.rows();
    facts["faces"] = geometry.surface->triangles.rows();
  } else if (geometry.mesh) {
    facts["kind"] = "mesh";
    facts["element"] = std::string(element_name(geometry.mesh->element_type));
    facts["vertices"] = geometry.mesh->nodes.rows();
    facts["cells"] = geometry.mesh->cells.rows();
  } else {
    facts["kind"] = "shape";
  }
  const auto& box = geometry.bounds;
  facts["bounding_box"] = {{"min", {box.min().x(), box.min().y(), box.min().z()}},
                           {"max", {box.max().x(), box.max().y(), box.max().z()}}};
  facts["volume"] = geometry.volume;
  facts["closed"] = geometry.closed;
  facts["manifold"] = geometry.manifold;
  facts["warnings"] = geometry.warnings;
  return facts;
}

// What the method integrates, built as `run` builds it: its DOFs, and the volume
// ∫ 1 dV = (interpolant of e_x)ᵀ · body_force(e_x) / ρ through its own quadrature
// (the isoparametric volume of a curved mesh, the cut cells' volume of an embedded one).
nlohmann::json method_facts(const Scene& scene, const SceneGeometry& geometry, const MethodDescription& method) {
  // Built as `run` builds it, so what `run` refuses is refused here too: a load region
  // that holds no triangle of the loaded surface, an event the method cannot carry out.
  const Simulation simulation(scene, geometry, std::string(method.scene_block.name), method.factory, method.rebuild);
  const MethodInstance* instance = &simulation.method();
  const Eigen::Vector3d unit_x = Eigen::Vector3d::UnitX();
  const Eigen::VectorXd ones = instance->interpolate([&](const Eigen::Vector3d&) { return unit_x; });
  const double mass = ones.dot(instance->discretization().body_force(unit_x));
  // With several materials the volume is Σ mass_m / ρ_m, which needs the masses per
  // material: with one density, mass / ρ.
  double density = scene.materials.front().density;
  for (const MaterialSpec& material : scene.materials)
    if (material.density != density) density = std::numeric_limits<double>::quiet_NaN();
  if (std::isnan(density))
    return {{"dofs", instance->discretization().dof_count()},
            {"elements", instance->element_counts()},
            {"integrated_mass", mass}};
  const double volume = mass / density;
  return {{"dofs", instance->discretization().dof_count()},
          {"elements", instance->element_counts()},
          {"integrated_mass", mass},
          {"integrated_volume", volume},
          {"volume_difference", volume / geometry.volume - 1.0}};
}

// One method's outcome: its facts, or why it cannot run the scene (the message and
// exit code `run --method` would give).
struct MethodCheck {
  nlohmann::json facts;
  std::string error;  // "altfem: error: …" or "altfem: numerical failure: …"; empty when it can
  int exit_code = 0;
};

MethodCheck check_method(Scene& scene, const SceneGeometry& geometry, const std::string& name) {
  try {
    scene.resolved["discretization"][name] = resolve_method_block(scene, find_method(name).scene_block);
    return {method_facts(scene, geometry, find_method(name)), "", 0};
  } catch (const InputError& error) {
    return {{}, std::string("altfem: error: ") + error.what(), exit_bad_input};
  } catch (const NumericalError& error) {
    return {{}, std::string("altfem: numerical failure: ") + error.what(), exit_numerical};
  }
}

}  // namespace

int check_command(const std::filesystem::path& scene_file, const std::string& method, bool json) {
  Scene scene = load_scene(scene_file);
  const std::vector<std::string> methods = method.empty() ? available_methods() : std::vector<std::string>{method};
  for (const auto& name : methods) (void)find_method(name);
  resolve_method_blocks(scene, {});  // the scene-wide checks: no block of an unknown method
  const SceneGeometry geometry = load_scene_geometry(scene);
  for (const auto& warning : geometry.warnings) std::fprintf(stderr, "altfem: warning: %s\n", warning.c_str());
  // Each method on its own (issue #35): one that cannot run the scene does not hide what
  // the others can. A scene no method can run is one failure, as `run` reports it.
  std::vector<std::pair<std::string, MethodCheck>> checks;
  for (const auto& name : methods) checks.emplace_back(name, check_method(scene, geometry, name));
  int exit_code = 0, failures = 0;
  for (const auto& [name, check] : checks)
    if (check.exit_code != 0) {
      exit_code = std::max(exit_code, check.exit_code);
      ++failures;
    }
  if (failures == static_cast<int>(checks.size())) {
    std::fprintf(stderr, "%s\n", checks.front().second.error.c_str());
    return checks.front().second.exit_code;
  }
  const nlohmann::json facts = geometry_facts(geometry);
  nlohmann::json built;
  for (const auto& [name, check] : checks)
    built[name] = check.exit_code == 0 ? check.facts : nlohmann::json{{"error", check.error}};
  if (json) {
    std::printf("%s\n",
                nlohmann::json{{"scene", scene.resolved}, {"geometry", facts}, {"methods", built}}.dump(2).c_str());
  } else {
    std::printf("%s: %s scene '%s'\n", scene_file.c_str(), failures == 0 ? "valid" : "partly valid",
                scene.name.c_str());
    std::printf("%s\n", scene.resolved.dump(2).c_str());
    std::printf("geometry: %s", facts["kind"].get<std::string>().c_str());
    if (facts.contains("faces"))
      std::printf(", %lld vertices, %lld faces", facts["vertices"].get<long long>(), facts["faces"].get<long long>());
    if (facts.contains("cells"))
      std::printf(", %s, %lld vertices, %lld cells", facts["element"].get<std::string>().c_str(),
                  facts["vertices"].get<long long>(), facts["cells"].get<long long>());
    const auto& box = geometry.bounds;
    std::printf("\nbounding box: [%g, %g, %g] – [%g, %g, %g]\nvolume: %.6g\nclosed: %s, manifold: %s\n", box.min().x(),
                box.min().y(), box.min().z(), box.max().x(), box.max().y(), box.max().z(), geometry.volume,
                geometry.closed ? "yes" : "no", geometry.manifold ? "yes" : "no");
    for (const auto& [name, method_facts] : built.items()) {
      if (method_facts.contains("error")) {
        std::printf("%s: cannot run this scene (see stderr)\n", name.c_str());
        continue;
      }
      std::printf("%s: %lld DOFs, integrated mass %.6g kg", name.c_str(), method_facts["dofs"].get<long long>(),
                  method_facts["integrated_mass"].get<double>());
      if (method_facts.contains("integrated_volume"))
        std::printf(", volume %.6g (%+.2e relative to the geometry's)", method_facts["integrated_volume"].get<double>(),
                    method_facts["volume_difference"].get<double>());
      std::printf("\n");
    }
  }
  std::fflush(stdout);
  for (const auto& [name, check] : checks)
    if (check.exit_code != 0) std::fprintf(stderr, "%s\n", check.error.c_str());
  return exit_code;
}

}  // namespace altfem::cli
