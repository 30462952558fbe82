#pragma once
// Whole-file writes that never leave a truncated file behind (docs/conventions.md, principle 5:
// "Nothing half-written is left behind").
#include <filesystem>
#include <string_view>

namespace altfem {

/// Writes `content` to a temporary file in the folder of `path`, then renames it over
/// `path` (rename is atomic within one file system), so readers see the old file or
/// the new one, never a part. No fsync: this guards against interrupted runs, not
/// power loss. Throws std::runtime_error naming the path (e.g. a missing folder);
/// the temporary file is removed on failure.
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

}  // namespace altfem
