#include "app/method_registry.hpp"

#include "dg/dg_method.hpp"
#include "fcm/fcm_method.hpp"
#include "polyhedral/harmonic_method.hpp"
#include "shared/common/error.hpp"
#include "shared/fem/method/fem_method.hpp"

namespace altfem::cli {

const std::vector<MethodDescription>& registered_methods() {
  static const std::vector<MethodDescription> methods{fem_method(), fcm::fcm_method(), dg::dg_method(),
                                                      harmonic::harmonic_method()};
  return methods;
}

std::vector<std::string> available_methods() {
  std::vector<std::string> names;
  for (const auto& method : registered_methods()) names.emplace_back(method.scene_block.name);
  return names;
}

const MethodDescription& find_method(const std::string& name, std::string_view option) {
  for (const auto& method : registered_methods())
    if (method.scene_block.name == name) return method;
  std::string list;
  for (const auto& available : available_methods()) list += (list.empty() ? "" : ", ") + available;
  throw InputError(input_message(std::string(option), "",
                                 "method '" + name + "' is not available in this build (available: " + list + ")"));
}

void resolve_method_blocks(Scene& scene, const std::vector<std::string>& methods) {
  std::vector<MethodSceneBlock> blocks;
  for (const auto& method : registered_methods()) blocks.push_back(method.scene_block);
  check_method_block_names(scene, blocks);
  for (const auto& name : methods)
    scene.resolved["discretization"][name] = resolve_method_block(scene, find_method(name).scene_block);
}

}  // namespace altfem::cli
