#include "app/method_registry.hpp"

#include <map>

#include "shared/common/error.hpp"
#include "shared/fem/fem_method.hpp"

namespace altfem::cli {

namespace {
// fcm, dg and harmonic join here as their libraries land.
const std::map<std::string, MethodFactory>& registry() {
  static const std::map<std::string, MethodFactory> methods{{"fem", make_fem_method}};
  return methods;
}
}  // namespace

std::vector<std::string> available_methods() {
  std::vector<std::string> names;
  for (const auto& [name, factory] : registry()) names.push_back(name);
  return names;
}

MethodFactory method_factory(const std::string& name) {
  const auto found = registry().find(name);
  if (found != registry().end()) return found->second;
  std::string list;
  for (const auto& available : available_methods()) list += (list.empty() ? "" : ", ") + available;
  throw InputError(input_message("--method", "", "method '" + name + "' is not available in this build (available: " +
                                                     list + ")"));
}

}  // namespace altfem::cli
