#include "fcm/rule_cache.hpp"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>

#include "shared/io/atomic_file.hpp"

namespace altfem::fcm {
namespace {

constexpr char magic[] = "altfem-cell-rules-v1";

struct Hasher {
  std::uint64_t value = 1469598103934665603ull;
  void bytes(const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) value = (value ^ p[i]) * 1099511628211ull;
  }
  template <typename T> void scalar(T x) { bytes(&x, sizeof x); }
  template <typename Matrix> void matrix(const Matrix& m) {
    scalar<std::int64_t>(m.rows());
    scalar<std::int64_t>(m.cols());
    bytes(m.data(), sizeof(typename Matrix::Scalar) * static_cast<std::size_t>(m.size()));
  }
};

template <typename T> void put(std::string& out, T x) { out.append(reinterpret_cast<const char*>(&x), sizeof x); }

/// Reads back what put wrote; nullopt past the end.
class Reader {
public:
  explicit Reader(const std::string& text) : text_(text) {}
  template <typename T> std::optional<T> get() {
    if (position_ + sizeof(T) > text_.size()) return std::nullopt;
    T x;
    std::memcpy(&x, text_.data() + position_, sizeof x);
    position_ += sizeof x;
    return x;
  }
  bool at_end() const { return position_ == text_.size(); }
  bool skip(std::size_t size) {
    if (position_ + size > text_.size()) return false;
    position_ += size;
    return true;
  }

private:
  const std::string& text_;
  std::size_t position_ = 0;
};

std::string serialise(const CellRules& rules) {
  std::string out(magic, sizeof magic);
  put<std::int64_t>(out, static_cast<std::int64_t>(rules.cells.size()));
  for (const CellRule& cell : rules.cells) {
    put<std::int32_t>(out, static_cast<std::int32_t>(cell.kind));
    put<std::int64_t>(out, cell.initial_points);
    put<double>(out, cell.clipped_volume);
    put<double>(out, cell.residual);
    put<std::int32_t>(out, cell.simplification_failed);
    put<std::int32_t>(out, cell.rule.strength);
    put<std::int64_t>(out, cell.rule.points.rows());
    for (Eigen::Index q = 0; q < cell.rule.points.rows(); ++q) {
      for (int d = 0; d < 3; ++d) put<double>(out, cell.rule.points(q, d));
      put<double>(out, cell.rule.weights(q));
    }
  }
  return out;
}

std::optional<CellRules> deserialise(const std::string& text, Eigen::Index cell_count) {
  Reader reader(text);
  if (text.size() < sizeof magic || std::memcmp(text.data(), magic, sizeof magic) != 0) return std::nullopt;
  reader.skip(sizeof magic);
  const auto count = reader.get<std::int64_t>();
  if (!count || *count != cell_count) return std::nullopt;
  CellRules rules;
  rules.cells.resize(cell_count);
  for (CellRule& cell : rules.cells) {
    const auto kind = reader.get<std::int32_t>();
    const auto initial = reader.get<std::int64_t>();
    const auto volume = reader.get<double>(), residual = reader.get<double>();
    const auto failed = reader.get<std::int32_t>(), strength = reader.get<std::int32_t>();
    const auto points = reader.get<std::int64_t>();
    if (!kind || !initial || !volume || !residual || !failed || !strength || !points || *points < 0 || *kind < 0 ||
        *kind > 2 || static_cast<std::size_t>(*points) > text.size() / 32) {
      return std::nullopt;
    }
    cell.kind = static_cast<CellKind>(*kind);
    cell.initial_points = *initial;
    cell.clipped_volume = *volume;
    cell.residual = *residual;
    cell.simplification_failed = *failed != 0;
    cell.rule.strength = *strength;
    cell.rule.points.resize(*points, 3);
    cell.rule.weights.resize(*points);
    for (Eigen::Index q = 0; q < *points; ++q) {
      for (int d = 0; d < 3; ++d) {
        const auto x = reader.get<double>();
        if (!x) return std::nullopt;
        cell.rule.points(q, d) = *x;
      }
      const auto w = reader.get<double>();
      if (!w) return std::nullopt;
      cell.rule.weights(q) = *w;
    }
  }
  if (!reader.at_end()) return std::nullopt;
  return rules;
}

}  // namespace

std::uint64_t cell_rules_key(const VolumeMesh& background, const VolumeMesh& embedded, const CellRuleOptions& options,
                             const std::vector<std::vector<int>>* cell_tetrahedra) {
  Hasher hasher;
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
  if (cell_tetrahedra)
    for (const std::vector<int>& tetrahedra : *cell_tetrahedra) {
      hasher.scalar<std::int64_t>(static_cast<std::int64_t>(tetrahedra.size()));
      hasher.bytes(tetrahedra.data(), sizeof(int) * tetrahedra.size());
    }
  return hasher.value;
}

CellRules cached_cell_rules(const VolumeMesh& background, const VolumeMesh& embedded, const CellRuleOptions& options,
                            const std::filesystem::path& directory, bool* reused,
                            const std::vector<std::vector<int>>* cell_tetrahedra) {
  char name[32];
  std::snprintf(name, sizeof name, "%016llx.rules",
                static_cast<unsigned long long>(cell_rules_key(background, embedded, options, cell_tetrahedra)));
  const std::filesystem::path path = directory / name;
  if (std::ifstream file{path, std::ios::binary}) {
    const std::string text{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
    if (auto rules = deserialise(text, background.cells.rows())) {
      sum_cell_rule_totals(*rules);
      if (reused) *reused = true;
      return *rules;
    }
  }
  CellRules rules = compute_cell_rules(background, embedded, options, cell_tetrahedra);
  std::filesystem::create_directories(directory);
  write_file_atomically(path, serialise(rules));
  if (reused) *reused = false;
  return rules;
}

}  // namespace altfem::fcm
