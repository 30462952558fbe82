#pragma once
// An on-disk cache of a mesh's cell rules, so a second run of a scene reuses them. The
// key is a hash of everything the rules depend on: the background mesh (type, nodes,
// cells), the embedded tetrahedra, the options and the file format version. Files are
// written whole to a temporary name and renamed (write_file_atomically), so an
// interrupted run leaves the old file or none; a file that does not read back completely
// (truncated, other version, hash collision on size) is ignored and recomputed.
#include <cstdint>
#include <filesystem>

#include "shared/cut_cells/cell_rules.hpp"

namespace altfem {

/// A 64-bit hash (CacheKeyHasher) of the inputs of compute_cell_rules (bit patterns of the doubles).
std::uint64_t cell_rules_key(const VolumeMesh& background, const VolumeMesh& embedded, const CellRuleOptions& options,
                             const std::vector<std::vector<int>>* cell_tetrahedra = nullptr);

/// compute_cell_rules, read from `directory`/<key>.rules when present and complete, else
/// computed and stored there (the folder is created). `reused` tells which happened.
/// Throws std::runtime_error naming the path if the file cannot be written.
CellRules cached_cell_rules(const VolumeMesh& background, const VolumeMesh& embedded, const CellRuleOptions& options,
                            const std::filesystem::path& directory, bool* reused = nullptr,
                            const std::vector<std::vector<int>>* cell_tetrahedra = nullptr);

}  // namespace altfem
