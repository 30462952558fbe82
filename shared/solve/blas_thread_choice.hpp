#pragma once
// How many BLAS threads each phase of a sparse direct solve gets (issue #35).
//
// CHOLMOD's supernodal factorisation is a sequence of BLAS-3 calls, and OpenBLAS's
// workers meet at a barrier in every one: a worker that shares its core with another
// busy process holds all the others up at each call. Measured on 2 cores with one busy
// process beside `altfem run scenes/twisting_cylinder.json --method fcm` (issue #35):
// on 2 BLAS threads the factorisation went from 0.90 s to 2.99 s and the triangular
// solves from 0.044 s to 1.88 s; on 1 thread, 1.14 s and 0.044 s. Hence:
//  - the triangular solves (one right-hand side: BLAS-2, bound by memory bandwidth, not
//    by cores) always run on one thread;
//  - a factorisation too small for threads to pay for their barriers runs on one;
//  - a larger one gets the OpenMP thread limit less the cores other processes keep
//    busy at that moment, and never less than one.
#include <optional>
#include <string>

namespace altfem {

/// Factorisations below this many floating-point operations run on one BLAS thread:
/// ~20 ms of one core's dgemm, where two threads saved less than their start-up.
inline constexpr double minimum_flops_for_blas_threads = 1e8;

/// The BLAS threads for a factorisation of `flops` operations, given the thread
/// limit (OpenMP's, or the user's OPENBLAS_NUM_THREADS), the cores this process may
/// use and the runnable threads of other processes.
int factorisation_blas_threads(double flops, int thread_limit, int cores, int busy_elsewhere);

/// Threads of other processes that are runnable now: the system's runnable threads
/// (/proc/loadavg) less this process's own (/proc/self/task/*/stat, state R), the
/// fewest of up to three samples 0.5 ms apart so that a thread running for a moment is
/// not counted as a busy core. 0 when /proc cannot be read.
int runnable_threads_elsewhere();

/// The runnable threads in the text of /proc/loadavg ("1.99 1.90 2.27 4/89 12892": 4),
/// or nothing when it does not read as such.
std::optional<int> runnable_threads_in_loadavg(const std::string& text);

/// Whether the text of a /proc/<pid>/task/<tid>/stat file says the thread is runnable
/// (state R; the state follows the last ')', since the command may contain one).
bool thread_stat_is_runnable(const std::string& text);

/// Cores this process may run on (its affinity mask), at least 1.
int usable_cores();

/// The BLAS thread limit: OPENBLAS_NUM_THREADS when the user set it, else OpenMP's
/// thread limit (omp_get_max_threads, which OMP_NUM_THREADS and `compare --jobs` set).
int blas_thread_limit();

}  // namespace altfem
