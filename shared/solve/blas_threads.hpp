#pragma once
// Keeping the BLAS library's threads from competing with OpenMP assembly.
//
// OpenBLAS's pthread workers do not sleep when a BLAS call ends: they busy-wait
// (sched_yield in a loop) for about 2^28 cycles, ~0.1 s, in case another call
// follows. A Newton iteration assembles right after it factorises, so for that
// time one of our two cores runs a spinning BLAS thread instead of an assembly
// thread. Measured once, with a temporary switch, on the 30,675-DOF twisting beam
// (bench_scene --case twisting_beam 0.035 1, 2 threads):
// assembly took 0.076-0.087 s per Newton iteration, 0.046-0.048 s with the BLAS
// threads parked after every factorisation and solve; the factorisation itself
// was unchanged within noise (0.32-0.39 s either way), since re-creating one
// worker thread costs microseconds.
namespace altfem {

/// Stops the BLAS worker threads now (they are re-created by the next call that
/// needs them), through OpenBLAS's exported blas_thread_shutdown_, the function its
/// own fork handler uses. Does nothing for a BLAS without worker threads. Call it
/// only from the thread that calls BLAS, between BLAS calls.
void park_blas_threads();

/// Limits the BLAS library to `count` threads (OpenBLAS's openblas_set_num_threads, looked
/// up at run time like the above); does nothing for another BLAS. What a single-core
/// benchmark needs besides omp_set_num_threads(1): OpenBLAS's pthread workers are its own.
void set_blas_threads(int count);

}  // namespace altfem
