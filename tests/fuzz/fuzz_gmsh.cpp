// libFuzzer target for the Gmsh MSH parser: any input either parses or throws
// InputError; every other exception, crash or sanitizer report is a bug.
// Run: fuzz_gmsh -max_total_time=60 tests/fuzz/corpus/gmsh
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "shared/common/error.hpp"
#include "shared/mesh/volume_mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const altfem::VolumeMesh mesh = altfem::parse_gmsh(text, "fuzz.msh");
    altfem::check_volume_mesh(mesh, "fuzz.msh");
  } catch (const altfem::InputError&) {
  }
  return 0;
}
