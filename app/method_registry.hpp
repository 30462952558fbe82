#pragma once
#include <string>
#include <vector>

#include "shared/simulation/method_instance.hpp"

namespace altfem::cli {

/// The methods built into this executable, in the order `altfem run` lists them.
std::vector<std::string> available_methods();
/// The factory of a method; throws InputError naming the available ones otherwise.
MethodFactory method_factory(const std::string& name);

}  // namespace altfem::cli
