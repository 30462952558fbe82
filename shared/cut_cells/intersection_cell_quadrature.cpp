#include "shared/cut_cells/intersection_cell_quadrature.hpp"

#include <algorithm>
#include <chrono>
#include <exception>
#include <utility>

#include "shared/cut_cells/cut_cell_rule.hpp"
#include "shared/cut_cells/rule_cache.hpp"
#include "shared/element/polynomial_space.hpp"

namespace altfem {

CellQuadratureSource intersection_cell_quadrature(
    const VolumeMesh& background, const VolumeMesh& embedded, std::optional<SimplificationMethod> method,
    double tolerance, const std::filesystem::path& cache_directory, std::shared_ptr<IntersectionStatistics> statistics,
    std::vector<std::vector<int>> cell_tetrahedra, std::vector<char> filled_cells,
    std::shared_ptr<const CellRuleMemory> previous_rules, std::shared_ptr<CellRuleMemory> remembered_rules) {
  // Each cell's own volume, once: volume fractions are clipped volume over it. In
  // parallel (a cell's geometry tests its faces' planarity with exact predicates); the
  // first exception (a non-planar face) is rethrown after the loop.
  const int corner_count = element_corner_count(background.element_type);
  std::vector<double> volumes(background.cells.rows());
  std::exception_ptr failure;
#pragma omp parallel
  {
    Eigen::MatrixXd corners(corner_count, 3);
#pragma omp for schedule(static)
    for (Eigen::Index c = 0; c < background.cells.rows(); ++c) {
      try {
        for (int i = 0; i < corner_count; ++i) corners.row(i) = background.nodes.row(background.cells(c, i));
        volumes[c] = CellGeometry(background.element_type, corners).volume();
      } catch (...) {
#pragma omp critical(altfem_cell_volumes_failure)
        if (!failure) failure = std::current_exception();
      }
    }
  }
  if (failure) std::rethrow_exception(failure);
  // The total degree of a product of two basis functions.
  int product_degree = 0;
  for (const Eigen::Vector3i& exponent : polynomial_space_exponents(background.element_type))
    product_degree = std::max(product_degree, 2 * exponent.sum());
  return [background, embedded, method, tolerance, product_degree, cache_directory, volumes, statistics,
          cell_tetrahedra = std::move(cell_tetrahedra), filled_cells = std::move(filled_cells),
          previous_rules = std::move(previous_rules),
          remembered_rules = std::move(remembered_rules)](int strength, RulePurpose purpose) {
    const auto start = std::chrono::steady_clock::now();
    CellRuleOptions options;
    options.order = strength;
    // §6: mass rules are never simplified. Of at least twice the basis' degree, a piece's
    // rule integrates the products of an affine cell's basis functions exactly on any
    // tetrahedron, so they take the fan of fewer pieces (clip_tetrahedron) and no more than
    // that degree: the same masses to round-off from a quarter of the points (fcm Hex20's
    // default strength 10: half the pieces, 46 points a piece for 81; Hex8's 5 and Hex27's
    // 11 are below their products' degrees 6 and 12 and keep the centroid's fan). A
    // simplified rule (§4.4) keeps the moments of degree m of the rule it starts from, which
    // are exact on any tetrahedralisation: it starts from the vertex's fan too, so the
    // recombination picks from about half the points (fcm Hex20's refine event, issue #34:
    // the stiffness rules of 2,792 new cut cells).
    options.simplify = purpose == RulePurpose::stiffness && method.has_value();
    options.fan = options.simplify || (purpose == RulePurpose::mass && strength >= product_degree) ? PieceFan::vertex
                                                                                                   : PieceFan::centroid;
    options.exact_degree = purpose == RulePurpose::mass ? product_degree : 0;
    options.reduce = purpose == RulePurpose::mass;
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
      } else {
        statistics->reused_mass_tetrahedra = reuse.reused_tetrahedra;
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
          cells[c].reduced = std::move(cell.reduced);
          break;
      }
    }
    return cells;
  };
}

}  // namespace altfem
