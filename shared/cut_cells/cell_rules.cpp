#include "shared/cut_cells/cell_rules.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>

#include "shared/cut_cells/cell_rule_bytes.hpp"
#include "shared/cut_cells/cut_cell_rule.hpp"
#include "shared/cut_cells/tetrahedron_buckets.hpp"
#include "shared/element/geometry_map.hpp"
#include "shared/element/reference_element.hpp"
#include "shared/io/binary_cache.hpp"
#include "shared/quadrature/reference_rules.hpp"
#include "shared/solve/rank_exchange.hpp"

namespace altfem {
namespace {

// The key of a cell's rule in a CellRuleMemory: everything compute_cell_rules reads for it.
std::uint64_t cell_rule_key(const CellRuleOptions& options, ElementType type, const Eigen::MatrixXd& corners,
                            const std::vector<TetrahedronCorners>& candidates) {
  CacheKeyHasher hasher;
  hasher.scalar<std::int32_t>(options.order);
  hasher.scalar<std::int32_t>(options.simplify);
  hasher.scalar<std::int32_t>(static_cast<std::int32_t>(options.method));
  hasher.scalar<double>(options.tolerance);
  hasher.scalar<std::int32_t>(static_cast<std::int32_t>(options.fan));
  hasher.scalar<std::int32_t>(options.exact_degree);
  hasher.scalar<std::int32_t>(static_cast<std::int32_t>(type));
  hasher.matrix(corners);
  for (const TetrahedronCorners& tetrahedron : candidates) hasher.matrix(tetrahedron);
  return hasher.value();
}

// Every rank's cells (each rank computed every count()-th, from its index) into every
// rank's `rules`, with their keys and reuse marks where `keys` is not empty. A reduced rule
// of an affine cell goes without its points, on every rank: the masses read its reduction
// alone (fcm_discretization.cpp's kept_rules), and mass rules run to thousands of points a
// cell (half of fcm's divided set-up went to sending them).
void gather_cell_rules(const VolumeMesh& background, CellRules& rules, std::vector<std::uint64_t>& keys,
                       std::vector<char>& reused) {
  const bool keyed = !keys.empty();
  const ReferenceElement& element = reference_element(background.element_type);
  Eigen::MatrixXd nodes(background.cells.cols(), 3);
  const auto write = [&](BinaryWriter& out, std::size_t c) {
    CellRule& cell = rules.cells[c];
    if (cell.reduced) {
      for (Eigen::Index a = 0; a < nodes.rows(); ++a)
        nodes.row(a) = background.nodes.row(background.cells(static_cast<Eigen::Index>(c), a));
      if (affine_jacobian(element, nodes)) cell.rule.points.resize(0, 3), cell.rule.weights.resize(0);
    }
    if (keyed) {
      out.put<std::uint64_t>(keys[c]);
      out.put<std::int32_t>(reused[c]);
    }
    write_cell_rule(out, cell, true);
  };
  const auto read = [&](BinaryReader& in, std::size_t c) {
    if (keyed) {
      const auto key = in.get<std::uint64_t>();
      const auto was_reused = in.get<std::int32_t>();
      if (!key || !was_reused) return false;
      keys[c] = *key;
      reused[c] = static_cast<char>(*was_reused);
    }
    return read_cell_rule(in, rules.cells[c], true);
  };
  ranks::exchange_items(rules.cells.size(), "altfem cell rules of a rank 1", write, read);
}

}  // namespace

CellRules compute_cell_rules(const VolumeMesh& background, const VolumeMesh& embedded, const CellRuleOptions& options,
                             const std::vector<std::vector<int>>* cell_tetrahedra, CellRuleReuse* reuse) {
  const TetrahedronBuckets buckets(embedded);
  const ElementType type = background.element_type;
  const int corner_count = element_corner_count(type);
  const QuadratureRule standard = reference_rule(
      element_shape(type) == ElementShape::tetrahedron ? ReferenceDomain::tetrahedron : ReferenceDomain::hexahedron,
      options.order);
  const Eigen::Index cell_count = background.cells.rows();
  CellRules result;
  result.cells.resize(cell_count);
  // Per cell, its key (0: no tetrahedra, or no memory asked for) and whether it was reused.
  std::vector<std::uint64_t> keys(reuse ? cell_count : 0, 0);
  std::vector<char> reused(reuse ? cell_count : 0, 0);

  // A cell's work is independent of every other's; exceptions must not escape the
  // parallel region, so the first one is kept and rethrown after it.
  std::exception_ptr failure;
#pragma omp parallel
  {
    std::vector<TetrahedronCorners> candidates;
    Eigen::MatrixXd corners(corner_count, 3);
#pragma omp for schedule(dynamic, 4)
    for (Eigen::Index c = 0; c < cell_count; ++c) {
      if (!ranks::computes_item(static_cast<std::size_t>(c))) continue;  // another rank's (gathered below)
      try {
        for (int i = 0; i < corner_count; ++i) corners.row(i) = background.nodes.row(background.cells(c, i));
        const Eigen::AlignedBox3d box(corners.colwise().minCoeff().transpose(),
                                      corners.colwise().maxCoeff().transpose());
        if (cell_tetrahedra) {
          candidates.clear();
          for (const int t : (*cell_tetrahedra)[c]) candidates.push_back(buckets.corners(t));
        } else {
          buckets.candidates(box, candidates);
        }
        CellRule& cell = result.cells[c];
        if (candidates.empty()) continue;
        if (reuse) {
          keys[c] = cell_rule_key(options, type, corners, candidates);
          if (reuse->previous)
            if (const auto found = reuse->previous->find(keys[c]); found != reuse->previous->end()) {
              cell = found->second;
              reused[c] = 1;
              continue;
            }
        }
        const CellGeometry geometry(type, corners);
        const double volume = geometry.volume();
        const auto inside = [&](double clipped_volume) {
          cell.kind = CellKind::inside;
          cell.rule = standard;
          cell.initial_points = standard.points.rows();
          cell.clipped_volume = clipped_volume;
        };
        if (reuse && reuse->filled && (*reuse->filled)[c]) {
          inside(volume);
          continue;
        }
        const bool exact_pieces = geometry.affine() && options.exact_degree > 0;
        IntersectionRule intersection = intersection_rule(
            geometry, candidates, exact_pieces ? std::min(options.order, options.exact_degree) : options.order,
            geometry.affine() ? options.fan : PieceFan::centroid);
        cell.clipped_volume = intersection.clipped_volume;
        cell.initial_points = intersection.rule.points.rows();
        if (cell.initial_points == 0) continue;
        if (std::abs(intersection.clipped_volume - volume) <= filled_cell_tolerance * volume) {
          inside(intersection.clipped_volume);
          continue;
        }
        cell.kind = CellKind::cut;
        if (!options.simplify) {
          cell.rule = std::move(intersection.rule);
          continue;
        }
        SimplificationResult simplified =
            simplify_quadrature(intersection.rule, {options.order, options.method, options.tolerance});
        cell.rule = std::move(simplified.rule);
        cell.residual = simplified.residual;
        cell.simplification_failed = simplified.failed;
      } catch (...) {
#pragma omp critical(altfem_fcm_cell_rules_failure)
        if (!failure) failure = std::current_exception();
      }
    }
  }
  // Over several ranks every rank throws the first failing rank's exception.
  ranks::collectively([&] {
    if (failure) std::rethrow_exception(failure);
  });
  // After the rules (a remembered cell brings its reduction along): a cell at a time in
  // parallel, then each large rule by all threads (reference_products).
  if (options.reduce) {
    const auto unreduced = [&](Eigen::Index c) {
      return result.cells[c].kind == CellKind::cut && !result.cells[c].reduced;
    };
#pragma omp parallel for schedule(dynamic, 4)
    for (Eigen::Index c = 0; c < cell_count; ++c)
      if (unreduced(c) && result.cells[c].rule.weights.size() <= large_rule_points)
        result.cells[c].reduced = reference_products(type, result.cells[c].rule);
    for (Eigen::Index c = 0; c < cell_count; ++c)
      if (unreduced(c)) result.cells[c].reduced = reference_products(type, result.cells[c].rule);
  }

  // Over several ranks each computed (and reduced) every count()-th cell: most of the
  // set-up of fcm, and of fem's cut elements, divided, while every rank holds every rule,
  // as it holds the mesh (docs/scaling.md).
  if (ranks::distributed()) gather_cell_rules(background, result, keys, reused);

  if (reuse) {
    // The memory's copies in parallel, then moved into it. A reduced rule of an affine cell
    // is remembered without its points: its masses are its reduction times det J
    // (lagrange_element_masses, which asks the same of the cell's nodes), and mass rules run
    // to thousands of points a cell, which the memory would hold for the rest of the run.
    std::vector<CellRule> copies(reuse->computed ? cell_count : 0);
    const ReferenceElement& element = reference_element(type);
#pragma omp parallel
    {
      Eigen::MatrixXd nodes(background.cells.cols(), 3);
#pragma omp for schedule(dynamic, 16)
      for (Eigen::Index c = 0; c < static_cast<Eigen::Index>(copies.size()); ++c) {
        if (keys[c] == 0) continue;
        CellRule& cell = result.cells[c];
        for (Eigen::Index a = 0; a < nodes.rows(); ++a) nodes.row(a) = background.nodes.row(background.cells(c, a));
        if (!cell.reduced || !affine_jacobian(element, nodes)) {
          copies[c] = cell;
          continue;
        }
        QuadratureRule points = std::move(cell.rule);  // the copy takes everything else
        copies[c] = cell;
        cell.rule = std::move(points);
      }
    }
    for (Eigen::Index c = 0; c < cell_count; ++c) {
      reuse->reused += reused[c];
      reuse->integrated += keys[c] != 0 && !reused[c];
      if (reuse->computed && keys[c] != 0) reuse->computed->emplace(keys[c], std::move(copies[c]));
    }
  }
  sum_cell_rule_totals(result);
  return result;
}

void sum_cell_rule_totals(CellRules& rules) {
  rules.initial_points = rules.final_points = 0;
  rules.cut_cells = rules.inside_cells = rules.failed_simplifications = 0;
  rules.max_residual = 0.0;
  for (const CellRule& cell : rules.cells) {
    rules.initial_points += cell.initial_points;
    rules.final_points += cell.rule.points.rows();
    rules.cut_cells += cell.kind == CellKind::cut;
    rules.inside_cells += cell.kind == CellKind::inside;
    rules.failed_simplifications += cell.simplification_failed;
    rules.max_residual = std::max(rules.max_residual, cell.residual);
  }
}

}  // namespace altfem
