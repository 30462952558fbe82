#pragma once
// The methods of this build. Adding a method is one line in method_registry.cpp:
// its MethodDescription (scene block + factory); nothing in shared/scene changes.
#include <string>
#include <vector>

#include "shared/scene/scene.hpp"
#include "shared/simulation/method_instance.hpp"

namespace altfem::cli {

/// The methods built into this executable, in the order `altfem info` lists them.
const std::vector<MethodDescription>& registered_methods();
/// Their names.
std::vector<std::string> available_methods();
/// One method; throws InputError naming `option` and the available ones otherwise.
const MethodDescription& find_method(const std::string& name, std::string_view option = "--method");
/// Checks that every block under /discretization names a method of this build, then
/// resolves the blocks of `methods` into scene.resolved (defaults filled), so the
/// run's resolved scene and summary show what the method used. Throws InputError.
void resolve_method_blocks(Scene& scene, const std::vector<std::string>& methods);

}  // namespace altfem::cli
