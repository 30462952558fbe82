#include "shared/cut_cells/cell_rule_bytes.hpp"

namespace altfem {

void write_cell_rule(BinaryWriter& out, const CellRule& cell) {
  out.put<std::int32_t>(static_cast<std::int32_t>(cell.kind));
  out.put<std::int64_t>(cell.initial_points);
  out.put<double>(cell.clipped_volume);
  out.put<double>(cell.residual);
  out.put<std::int32_t>(cell.simplification_failed);
  out.put<std::int32_t>(cell.rule.strength);
  out.matrix(cell.rule.points);
  out.matrix(cell.rule.weights);
  out.put<std::int32_t>(cell.reduced.has_value());
  if (!cell.reduced) return;
  out.matrix(cell.reduced->products);
  out.matrix(cell.reduced->integrals);
  out.put<double>(cell.reduced->weight_sum);
}

bool read_cell_rule(BinaryReader& in, CellRule& cell) {
  const auto kind = in.get<std::int32_t>();
  const auto initial = in.get<std::int64_t>();
  const auto volume = in.get<double>(), residual = in.get<double>();
  const auto failed = in.get<std::int32_t>(), strength = in.get<std::int32_t>();
  if (!kind || !initial || !volume || !residual || !failed || !strength || *kind < 0 || *kind > 2) return false;
  cell.kind = static_cast<CellKind>(*kind);
  cell.initial_points = *initial;
  cell.clipped_volume = *volume;
  cell.residual = *residual;
  cell.simplification_failed = *failed != 0;
  cell.rule.strength = *strength;
  // An empty rule may keep 0 × 0 points.
  if (!in.matrix(cell.rule.points) || !in.matrix(cell.rule.weights) ||
      (cell.rule.points.size() > 0 && cell.rule.points.cols() != 3) ||
      cell.rule.weights.size() != cell.rule.points.rows())
    return false;
  cell.reduced.reset();
  const auto reduced = in.get<std::int32_t>();
  if (!reduced) return false;
  if (*reduced == 0) return true;
  ReferenceProducts products;
  if (!in.matrix(products.products) || !in.matrix(products.integrals)) return false;
  const auto sum = in.get<double>();
  if (!sum) return false;
  products.weight_sum = *sum;
  cell.reduced = std::move(products);
  return true;
}

}  // namespace altfem
