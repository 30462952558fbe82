#pragma once
// Which of OpenBLAS's kernels this CPU should run (issue #35).
//
// A DYNAMIC_ARCH OpenBLAS picks its kernels from the CPU model when it is loaded, and a
// model it does not know gets a generic core: OpenBLAS 0.3.21 picked "Prescott" (SSE3)
// on an AVX-512 Xeon, where its factorisation was 1.8x slower than with
// OPENBLAS_CORETYPE=Haswell (issue #35). The core can only be chosen before the library
// is loaded, i.e. by the environment of a new process (app/process_environment.hpp).
#include <string>
#include <string_view>

namespace altfem {

/// The OPENBLAS_CORETYPE to run instead of `chosen_core` on a CPU with these
/// instruction sets: "SkylakeX" (AVX-512 F, BW, DQ and VL) or "Haswell" (AVX2) when the
/// chosen core has no kernels for them; "" when the choice is already right or the CPU
/// has no AVX2.
std::string better_openblas_core(std::string_view chosen_core, bool has_avx2, bool has_avx512);

/// The core the loaded OpenBLAS runs (openblas_get_corename, looked up at run time),
/// "" for another BLAS.
std::string loaded_openblas_core();

/// better_openblas_core for the loaded OpenBLAS on this CPU (__builtin_cpu_supports).
std::string better_openblas_core_here();

}  // namespace altfem
