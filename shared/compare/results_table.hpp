#pragma once
// results.csv: one row per run (RFC 4180 quoting), the only input of
// scripts/plot_report.py, so report.md regenerates from it alone.
#include <filesystem>
#include <string>
#include <vector>

#include "shared/compare/run_record.hpp"

namespace altfem {

/// Writes the table atomically. Numbers are written with 17 significant digits
/// (a round trip is exact); an unknown error (NaN) is an empty field.
void write_results_csv(const std::filesystem::path& file, const std::vector<RunRecord>& records);
/// Reads a table written by write_results_csv. Throws InputError naming the file and
/// line for a missing column or a malformed number.
std::vector<RunRecord> read_results_csv(const std::filesystem::path& file);

}  // namespace altfem
