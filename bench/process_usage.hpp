#pragma once
// What the process has used so far. CPU time is reported next to wall time because the
// benchmark machines are shared: under load, wall time grows while CPU time does not,
// and their ratio says how far to trust a wall-clock figure.

namespace altfem::bench {

/// Peak resident set size so far [GiB] (getrusage(RUSAGE_SELF).ru_maxrss).
double peak_resident_gib();
/// CPU seconds used by all threads of the process so far (CLOCK_PROCESS_CPUTIME_ID).
double process_cpu_seconds();

}  // namespace altfem::bench
