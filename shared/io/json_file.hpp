#pragma once
// JSON output files (summary.json and friends).
#include <filesystem>
#include <nlohmann/json.hpp>

namespace altfem {

/// Writes `value` pretty-printed (2-space indent, trailing newline) with
/// write_file_atomically. nlohmann::json would silently print NaN and ±inf as
/// `null`; output must never hold NaN (docs/conventions.md), so any non-finite number throws
/// NumericalError naming its JSON pointer, e.g. "summary.json: /timings_s/solve: ...",
/// and nothing is written.
void write_json_file(const std::filesystem::path& path, const nlohmann::json& value);

}  // namespace altfem
