#pragma once
// The environment a run needs that can only be set before the process starts (issue #35).
//
// - OMP_WAIT_POLICY=passive: libgomp's workers spin for a while after every parallel
//   region. CHOLMOD's factorisation runs on OpenBLAS's own threads right after the
//   assembly's regions, so the spinning workers and the BLAS threads fight for the
//   cores: on a 16-core Xeon a 16-thread Tet10 factorisation took 89.1 s, 9.0 s with
//   passive waiting (issue #35); under ctest a verify test went from 10 s to a 600 s
//   timeout (scripts/test).
// - OPENBLAS_CORETYPE, when OpenBLAS picked a generic core on a CPU with AVX2 or
//   AVX-512 (shared/solve/blas_core_type.hpp).
// libgomp and OpenBLAS read these once, when they are loaded, so the only way to change
// them for this process is to start it again.
namespace altfem::cli {

/// Sets what is missing of the above (never a variable the user set) and, if anything
/// was, replaces this process by a new run of the same executable with the same
/// arguments (execv of /proc/self/exe). Returns when nothing was missing or the restart
/// failed (the run then goes on as it is, and says so in `altfem info`/summary.json).
void restart_with_tuned_environment(char** argv);

/// What the restart chose, for `altfem info`: "" or e.g. "OPENBLAS_CORETYPE=Haswell
/// (OpenBLAS had picked Prescott)".
const char* openblas_core_choice();

}  // namespace altfem::cli
