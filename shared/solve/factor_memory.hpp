#pragma once
// Whether a sparse direct factor fits in memory, decided before it is computed (issue
// #35: a 897k-DOF Tet10 run failed deep inside CHOLMOD instead of saying what to do).
// CHOLMOD's analysis knows the factor's size (its entries, and for supernodal LLᵀ the
// exact number of stored values) before any of it is allocated.
#include <string>

namespace altfem {

/// The memory this process can still allocate without swapping: MemAvailable of
/// /proc/meminfo in bytes, 0 when unknown.
double available_memory_bytes();

/// Throws NumericalError naming the factor's size, the memory available and the
/// scene key to change (solver.linear) when `factor_bytes` exceeds `available_bytes`;
/// does nothing when `available_bytes` is 0 (unknown).
void require_factor_fits(double factor_entries, double factor_bytes, double available_bytes);

}  // namespace altfem
