#include "shared/cut_cells/cell_rules.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <iterator>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

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

// The options and the cell type hashed: the start of every key compute_cell_rules makes.
CacheKeyHasher options_key(const CellRuleOptions& options, ElementType type) {
  CacheKeyHasher hasher;
  hasher.scalar<std::int32_t>(options.order);
  hasher.scalar<std::int32_t>(options.simplify);
  hasher.scalar<std::int32_t>(static_cast<std::int32_t>(options.method));
  hasher.scalar<double>(options.tolerance);
  hasher.scalar<std::int32_t>(static_cast<std::int32_t>(options.fan));
  hasher.scalar<std::int32_t>(options.exact_degree);
  hasher.scalar<std::int32_t>(options.reduce);
  hasher.scalar<std::int32_t>(static_cast<std::int32_t>(type));
  return hasher;
}

// The key of a cell's rule in a CellRuleMemory: everything compute_cell_rules reads for it.
std::uint64_t cell_rule_key(const CacheKeyHasher& options, const Eigen::MatrixXd& corners,
                            const std::vector<TetrahedronCorners>& candidates) {
  CacheKeyHasher hasher = options;
  hasher.matrix(corners);
  for (const TetrahedronCorners& tetrahedron : candidates) hasher.matrix(tetrahedron);
  return hasher.value();
}

// Every rank's cells (each rank computed every count()-th, from its index) into every
// rank's `rules`, with their keys and reuse marks where `keys` is not empty (an affine
// cell's mass rule is its reduction alone, so mass rules' thousands of points a cell are
// not sent: half of fcm's divided set-up once went to sending them).
void gather_cell_rules(CellRules& rules, std::vector<std::uint64_t>& keys, std::vector<char>& reused) {
  const bool keyed = !keys.empty();
  const auto write = [&](BinaryWriter& out, std::size_t c) {
    const CellRule& cell = rules.cells[c];
    if (keyed) {
      out.put<std::uint64_t>(keys[c]);
      out.put<std::int32_t>(reused[c]);
    }
    write_cell_rule(out, cell);
  };
  const auto read = [&](BinaryReader& in, std::size_t c) {
    if (keyed) {
      const auto key = in.get<std::uint64_t>();
      const auto was_reused = in.get<std::int32_t>();
      if (!key || !was_reused) return false;
      keys[c] = *key;
      reused[c] = static_cast<char>(*was_reused);
    }
    return read_cell_rule(in, rules.cells[c]);
  };
  ranks::exchange_items(rules.cells.size(), "altfem cell rules of a rank 1", write, read);
}

}  // namespace

CellRules compute_cell_rules(const VolumeMesh& background, const VolumeMesh& embedded, const CellRuleOptions& options,
                             const std::vector<std::vector<int>>* cell_tetrahedra, CellRuleReuse* reuse) {
  // Listed tetrahedra need no search for them (a rebuild lists them for every piece).
  const std::optional<TetrahedronBuckets> buckets =
      cell_tetrahedra ? std::nullopt : std::optional<TetrahedronBuckets>(std::in_place, embedded);
  const ElementType type = background.element_type;
  const int corner_count = element_corner_count(type);
  const QuadratureRule standard = reference_rule(
      element_shape(type) == ElementShape::tetrahedron ? ReferenceDomain::tetrahedron : ReferenceDomain::hexahedron,
      options.order);
  const Eigen::Index cell_count = background.cells.rows();
  const CacheKeyHasher keyed_options = options_key(options, type);
  CellRules result;
  result.cells.resize(cell_count);
  // Per cell, its key (0: no tetrahedra, or no memory asked for) and whether it was reused.
  std::vector<std::uint64_t> keys(reuse ? cell_count : 0, 0);
  std::vector<char> reused(reuse ? cell_count : 0, 0);
  std::vector<int> taken_tetrahedra(cell_count, 0);  // per cell, shares taken from the memory
  // A rebuild remembers the shares of the tetrahedra of the large cells' reductions it
  // computes, per cell (moved into the memory in cell order after the parallel loops): a
  // cut cell of more tetrahedra than a block (the tip of a sharpened pencil, cut again at
  // every cut) is what re-integrating costs, while the thousands of small cut cells a
  // refinement makes would hold a reduction's worth of memory per tetrahedron for nothing.
  const bool remember_tetrahedra = reuse && reuse->previous && reuse->computed;
  std::vector<RememberedShares> shares(remember_tetrahedra ? cell_count : 0);
  const TetrahedronReductionMemory* previous_shares = reuse && reuse->previous ? &reuse->previous->tetrahedra : nullptr;
  // Affine cells whose reduction sums more than one block of tetrahedra: summed after the
  // cells, block by block by all threads.
  std::vector<Eigen::Index> large_cells;

  const auto gather_candidates = [&](Eigen::Index c, Eigen::MatrixXd& corners,
                                     std::vector<TetrahedronCorners>& candidates) {
    for (int i = 0; i < corner_count; ++i) corners.row(i) = background.nodes.row(background.cells(c, i));
    candidates.clear();
    if (cell_tetrahedra) {
      for (const int t : (*cell_tetrahedra)[c]) {
        TetrahedronCorners& tetrahedron = candidates.emplace_back();
        for (int k = 0; k < 4; ++k) tetrahedron.row(k) = embedded.nodes.row(embedded.cells(t, k));
      }
    } else {
      buckets->candidates(
          Eigen::AlignedBox3d(corners.colwise().minCoeff().transpose(), corners.colwise().maxCoeff().transpose()),
          candidates);
    }
  };
  // The cell's map affine by all its nodes (a fem cell's curved edges are not), where a
  // mass rule is needed only as its reduction.
  const ReferenceElement& element = reference_element(type);
  const auto affine = [&](Eigen::Index c, const CellGeometry& geometry) {
    if (!geometry.affine()) return false;
    Eigen::MatrixXd nodes(background.cells.cols(), 3);
    for (Eigen::Index a = 0; a < nodes.rows(); ++a) nodes.row(a) = background.nodes.row(background.cells(c, a));
    return affine_jacobian(element, nodes).has_value();
  };
  const auto inside = [&](CellRule& cell, double clipped_volume) {
    cell.kind = CellKind::inside;
    cell.rule = standard;
    cell.initial_points = standard.points.rows();
    cell.clipped_volume = clipped_volume;
  };
  // A piece's rule of the integrand's degree is exact on an affine cell, whatever the fan.
  const auto piece_order = [&](const CellGeometry& geometry) {
    return geometry.affine() && options.exact_degree > 0 ? std::min(options.order, options.exact_degree)
                                                         : options.order;
  };
  const auto reduction_rule = [&](const CellGeometry& geometry, const Eigen::MatrixXd& corners) {
    TetrahedronReductionRule rule{geometry, piece_order(geometry), options.fan, keyed_options};
    rule.cell_key.matrix(corners);
    return rule;
  };
  // An affine cell's reduction, summed over its tetrahedra, classifies it as a rule does.
  const auto reduced = [&](Eigen::Index c, TetrahedronReduction sum, double volume) {
    CellRule& cell = result.cells[c];
    cell.clipped_volume = sum.clipped_volume;
    cell.initial_points = sum.points;
    taken_tetrahedra[c] = sum.taken;
    if (sum.points == 0) return;
    if (std::abs(sum.clipped_volume - volume) <= filled_cell_tolerance * volume)
      return inside(cell, sum.clipped_volume);
    cell.kind = CellKind::cut;
    cell.reduced = std::move(sum.products);
  };

  // A cell's work is independent of every other's; exceptions must not escape the
  // parallel region, so the first one is kept and rethrown after it.
  std::exception_ptr failure;
  const auto keep_failure = [&] {
#pragma omp critical(altfem_fcm_cell_rules_failure)
    if (!failure) failure = std::current_exception();
  };
#pragma omp parallel
  {
    std::vector<TetrahedronCorners> candidates;
    Eigen::MatrixXd corners(corner_count, 3);
#pragma omp for schedule(dynamic, 4)
    for (Eigen::Index c = 0; c < cell_count; ++c) {
      if (!ranks::computes_item(static_cast<std::size_t>(c))) continue;  // another rank's (gathered below)
      try {
        gather_candidates(c, corners, candidates);
        CellRule& cell = result.cells[c];
        if (candidates.empty()) continue;
        if (reuse) {
          keys[c] = cell_rule_key(keyed_options, corners, candidates);
          if (reuse->previous)
            if (const auto found = reuse->previous->cells.find(keys[c]); found != reuse->previous->cells.end()) {
              cell = found->second;
              reused[c] = 1;
              continue;
            }
        }
        const CellGeometry geometry(type, corners);
        const double volume = geometry.volume();
        if (reuse && reuse->filled && (*reuse->filled)[c]) {
          inside(cell, volume);
          continue;
        }
        if (options.reduce && affine(c, geometry)) {
          if (candidates.size() > reduction_block) {
#pragma omp critical(altfem_fcm_large_cells)
            large_cells.push_back(c);
            continue;
          }
          reduced(c, reduce_tetrahedra(reduction_rule(geometry, corners), candidates, previous_shares, nullptr),
                  volume);
          continue;
        }
        IntersectionRule intersection = intersection_rule(geometry, candidates, piece_order(geometry),
                                                          geometry.affine() ? options.fan : PieceFan::centroid);
        cell.clipped_volume = intersection.clipped_volume;
        cell.initial_points = intersection.rule.points.rows();
        if (cell.initial_points == 0) continue;
        if (std::abs(intersection.clipped_volume - volume) <= filled_cell_tolerance * volume) {
          inside(cell, intersection.clipped_volume);
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
        keep_failure();
      }
    }
  }
  // The large cells' blocks of tetrahedra by all threads, each cell's block sums added in order.
  std::sort(large_cells.begin(), large_cells.end());
  for (const Eigen::Index c : large_cells) {
    if (failure) break;
    std::vector<TetrahedronCorners> candidates;
    Eigen::MatrixXd corners(corner_count, 3);
    gather_candidates(c, corners, candidates);
    const CellGeometry geometry(type, corners);
    const TetrahedronReductionRule rule = reduction_rule(geometry, corners);
    const std::size_t blocks = (candidates.size() + reduction_block - 1) / reduction_block;
    std::vector<TetrahedronReduction> block_sums(blocks);
    std::vector<RememberedShares> block_shares(remember_tetrahedra ? blocks : 0);
#pragma omp parallel for schedule(dynamic, 1)
    for (std::size_t b = 0; b < blocks; ++b) {
      try {
        const std::size_t first = b * reduction_block;
        block_sums[b] = reduce_tetrahedra(rule,
                                          std::span<const TetrahedronCorners>(candidates)
                                              .subspan(first, std::min(reduction_block, candidates.size() - first)),
                                          previous_shares, remember_tetrahedra ? &block_shares[b] : nullptr);
      } catch (...) {
        keep_failure();
      }
    }
    TetrahedronReduction sum;
    for (const TetrahedronReduction& block_sum : block_sums) add_reduction(sum, block_sum);
    for (auto& block : block_shares) std::move(block.begin(), block.end(), std::back_inserter(shares[c]));
    reduced(c, std::move(sum), geometry.volume());
  }
  // Over several ranks every rank throws the first failing rank's exception.
  ranks::collectively([&] {
    if (failure) std::rethrow_exception(failure);
  });
  // The rules of cells that are not affine reduced (a remembered cell brings its
  // reduction along): a cell at a time in parallel, then each large rule by all threads
  // (reference_products).
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
  if (ranks::distributed()) gather_cell_rules(result, keys, reused);

  if (reuse) {
    // An affine cell's reduction comes without points, so a copy holds no mass rule's.
    std::vector<CellRule> copies(reuse->computed ? cell_count : 0);
#pragma omp parallel for schedule(dynamic, 16)
    for (Eigen::Index c = 0; c < static_cast<Eigen::Index>(copies.size()); ++c)
      if (keys[c] != 0) copies[c] = result.cells[c];
    for (Eigen::Index c = 0; c < cell_count; ++c) {
      reuse->reused += reused[c];
      reuse->integrated += keys[c] != 0 && !reused[c];
      reuse->reused_tetrahedra += taken_tetrahedra[c];
      if (reuse->computed && keys[c] != 0) reuse->computed->cells.emplace(keys[c], std::move(copies[c]));
      if (remember_tetrahedra)
        for (auto& [key, share] : shares[c]) reuse->computed->tetrahedra.emplace(key, std::move(share));
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
