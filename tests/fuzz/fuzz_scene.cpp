// libFuzzer target: parse_scene on arbitrary text. Bad input must end in
// InputError; any other exception, crash or sanitizer report is a bug.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "shared/common/error.hpp"
#include "shared/scene/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    altfem::parse_scene(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.json");
  } catch (const altfem::InputError&) {
  }
  return 0;
}
