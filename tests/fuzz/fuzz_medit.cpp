// libFuzzer target for the Medit .mesh parser: any input either parses or throws
// InputError; every other exception, crash or sanitizer report is a bug.
// Run: fuzz_medit -max_total_time=60 tests/fuzz/corpus/medit
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "shared/common/error.hpp"
#include "shared/mesh/volume_mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const altfem::VolumeMesh mesh = altfem::parse_medit(text, "fuzz.mesh");
    altfem::check_volume_mesh(mesh, "fuzz.mesh");
  } catch (const altfem::InputError&) {
  }
  return 0;
}
