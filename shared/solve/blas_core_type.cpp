#include "shared/solve/blas_core_type.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <array>
#include <cctype>

namespace altfem {

std::string better_openblas_core(std::string_view chosen_core, bool has_avx2, bool has_avx512) {
  if (chosen_core.empty() || !has_avx2) return "";
  // OpenBLAS 0.3.21's cores with AVX2 (or wider) kernels, as openblas_get_corename names them.
  constexpr std::array<std::string_view, 6> avx2_cores{"haswell",        "skylakex", "cooperlake",
                                                       "sapphirerapids", "zen",      "excavator"};
  std::string lower(chosen_core);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  if (std::find(avx2_cores.begin(), avx2_cores.end(), lower) != avx2_cores.end()) return "";
  return has_avx512 ? "SkylakeX" : "Haswell";
}

std::string loaded_openblas_core() {
  using CorenameFunction = char* (*)();
  const auto corename = reinterpret_cast<CorenameFunction>(dlsym(RTLD_DEFAULT, "openblas_get_corename"));
  const char* name = corename != nullptr ? corename() : nullptr;
  return name != nullptr ? name : "";
}

std::string better_openblas_core_here() {
  __builtin_cpu_init();
  const bool avx512 = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
                      __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl");
  return better_openblas_core(loaded_openblas_core(), __builtin_cpu_supports("avx2"), avx512);
}

}  // namespace altfem
