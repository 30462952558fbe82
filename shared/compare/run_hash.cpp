#include "shared/compare/run_hash.hpp"

#include <cstdint>
#include <cstdio>

namespace altfem {

std::string run_hash(const std::string& method, const nlohmann::json& resolved_scene) {
  nlohmann::json options = resolved_scene;
  if (options.is_object()) {
    options.erase("name");
    options.erase("compare");
  }
  const std::string text = method + '\n' + options.dump();
  std::uint64_t hash = 14695981039346656037ull;  // FNV-1a offset basis and prime (64 bit)
  for (const unsigned char c : text) hash = (hash ^ c) * 1099511628211ull;
  char digits[17];
  std::snprintf(digits, sizeof digits, "%016llx", static_cast<unsigned long long>(hash));
  return digits;
}

}  // namespace altfem
