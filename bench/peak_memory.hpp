#pragma once

namespace altfem::bench {

/// The process's peak resident set size so far [GiB] (getrusage(RUSAGE_SELF).ru_maxrss).
double peak_resident_gib();

}  // namespace altfem::bench
