#include "shared/cut_cells/rule_cache.hpp"

#include <optional>
#include <string>

#include "shared/cut_cells/cell_rule_bytes.hpp"
#include "shared/io/binary_cache.hpp"

namespace altfem {
namespace {

// v2: points and weights as BinaryWriter matrices; v3: with reductions (an affine cell's
// mass rule is its reduction alone).
constexpr char magic[] = "altfem-cell-rules-v3";

std::string serialise(const CellRules& rules) {
  BinaryWriter out(magic);
  out.put<std::int64_t>(static_cast<std::int64_t>(rules.cells.size()));
  for (const CellRule& cell : rules.cells) write_cell_rule(out, cell);
  return out.bytes();
}

std::optional<CellRules> deserialise(const std::string& text, Eigen::Index cell_count) {
  BinaryReader reader(text, magic);
  const auto count = reader.get<std::int64_t>();
  if (!count || *count != cell_count) return std::nullopt;
  CellRules rules;
  rules.cells.resize(cell_count);
  for (CellRule& cell : rules.cells)
    if (!read_cell_rule(reader, cell)) return std::nullopt;
  if (!reader.at_end()) return std::nullopt;
  return rules;
}

}  // namespace

std::uint64_t cell_rules_key(const VolumeMesh& background, const VolumeMesh& embedded, const CellRuleOptions& options,
                             const std::vector<std::vector<int>>* cell_tetrahedra) {
  CacheKeyHasher hasher;
  hasher.bytes(magic, sizeof magic);
  for (const VolumeMesh* mesh : {&background, &embedded}) {
    hasher.scalar<std::int32_t>(static_cast<std::int32_t>(mesh->element_type));
    hasher.matrix(mesh->nodes);
    hasher.matrix(mesh->cells);
  }
  hasher.scalar<std::int32_t>(options.order);
  hasher.scalar<std::int32_t>(options.simplify);
  hasher.scalar<std::int32_t>(static_cast<std::int32_t>(options.method));
  hasher.scalar<double>(options.tolerance);
  hasher.scalar<std::int32_t>(static_cast<std::int32_t>(options.fan));
  hasher.scalar<std::int32_t>(options.exact_degree);
  hasher.scalar<std::int32_t>(options.reduce);
  if (cell_tetrahedra)
    for (const std::vector<int>& tetrahedra : *cell_tetrahedra) {
      hasher.scalar<std::int64_t>(static_cast<std::int64_t>(tetrahedra.size()));
      hasher.bytes(tetrahedra.data(), sizeof(int) * tetrahedra.size());
    }
  return hasher.value();
}

CellRules cached_cell_rules(const VolumeMesh& background, const VolumeMesh& embedded, const CellRuleOptions& options,
                            const std::filesystem::path& directory, bool* reused,
                            const std::vector<std::vector<int>>* cell_tetrahedra) {
  const std::filesystem::path path =
      cache_file_path(directory, cell_rules_key(background, embedded, options, cell_tetrahedra), ".rules");
  if (const auto text = read_cache_file(path)) {
    if (auto rules = deserialise(*text, background.cells.rows())) {
      sum_cell_rule_totals(*rules);
      if (reused) *reused = true;
      return *rules;
    }
  }
  CellRules rules = compute_cell_rules(background, embedded, options, cell_tetrahedra);
  write_cache_file(path, serialise(rules));
  if (reused) *reused = false;
  return rules;
}

}  // namespace altfem
