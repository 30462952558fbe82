#include "shared/cut_cells/intersection_cell_quadrature.hpp"

#include <algorithm>
#include <chrono>
#include <utility>

#include "shared/cut_cells/cut_cell_rule.hpp"
#include "shared/cut_cells/rule_cache.hpp"

namespace altfem {

CellQuadratureSource intersection_cell_quadrature(
    const VolumeMesh& background, const VolumeMesh& embedded, std::optional<SimplificationMethod> method,
    double tolerance, const std::filesystem::path& cache_directory, std::shared_ptr<IntersectionStatistics> statistics,
    std::vector<std::vector<int>> cell_tetrahedra, std::vector<char> filled_cells,
    std::shared_ptr<const CellRuleMemory> previous_rules, std::shared_ptr<CellRuleMemory> remembered_rules) {
  // Each cell's own volume, once: volume fractions are clipped volume over it.
  const int corner_count = element_corner_count(background.element_type);
  std::vector<double> volumes(background.cells.rows());
  Eigen::MatrixXd corners(corner_count, 3);
  for (Eigen::Index c = 0; c < background.cells.rows(); ++c) {
    for (int i = 0; i < corner_count; ++i) corners.row(i) = background.nodes.row(background.cells(c, i));
    volumes[c] = CellGeometry(background.element_type, corners).volume();
  }
  return [background, embedded, method, tolerance, cache_directory, volumes, statistics,
          cell_tetrahedra = std::move(cell_tetrahedra), filled_cells = std::move(filled_cells),
          previous_rules = std::move(previous_rules),
          remembered_rules = std::move(remembered_rules)](int strength, RulePurpose purpose) {
    const auto start = std::chrono::steady_clock::now();
    CellRuleOptions options;
    options.order = strength;
    // §6: mass rules are never simplified.
    options.simplify = purpose == RulePurpose::stiffness && method.has_value();
    if (method) options.method = *method;
    options.tolerance = tolerance;
    const std::vector<std::vector<int>>* tetrahedra = cell_tetrahedra.empty() ? nullptr : &cell_tetrahedra;
    CellRuleReuse reuse{previous_rules.get(), remembered_rules.get(), filled_cells.empty() ? nullptr : &filled_cells};
    const bool reusing = previous_rules || remembered_rules || !filled_cells.empty();
    CellRules rules = cache_directory.empty()
                          ? compute_cell_rules(background, embedded, options, tetrahedra, reusing ? &reuse : nullptr)
                          : cached_cell_rules(background, embedded, options, cache_directory, nullptr, tetrahedra);
    if (statistics) {
      statistics->seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (purpose == RulePurpose::stiffness) {
        statistics->initial_points = rules.initial_points;
        statistics->final_points = rules.final_points;
        statistics->max_residual = rules.max_residual;
        statistics->failed_simplifications = rules.failed_simplifications;
        statistics->reused_cells = reuse.reused;
        statistics->integrated_cells = reuse.integrated;
      }
    }
    std::vector<CellQuadrature> cells(rules.cells.size());
    for (std::size_t c = 0; c < cells.size(); ++c) {
      CellRule& cell = rules.cells[c];
      switch (cell.kind) {
        case CellKind::outside: cells[c].volume_fraction = 0.0; break;
        case CellKind::inside: cells[c].volume_fraction = 1.0; break;
        case CellKind::cut:
          cells[c].volume_fraction = std::clamp(cell.clipped_volume / volumes[c], 0.0, 1.0);
          cells[c].rule = std::move(cell.rule);
          break;
      }
    }
    return cells;
  };
}

}  // namespace altfem
