#include "polyhedral/harmonic_element_bases.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <string>
#include <unordered_map>

#include "polyhedral/earlier_tabulation.hpp"
#include "polyhedral/harmonic_tabulation.hpp"
#include "polyhedral/mesh_face_coordinates.hpp"
#include "shared/assembly/tabulated_here.hpp"
#include "shared/common/error.hpp"
#include "shared/element/geometry_map.hpp"
#include "shared/fem/tabulate_lagrange.hpp"
#include "shared/io/binary_cache.hpp"
#include "shared/quadrature/reference_rules.hpp"
#include "shared/solve/rank_exchange.hpp"

namespace altfem::harmonic {

namespace {

// Keeps the smallest cell index any thread records: an exception must not leave an
// OpenMP region, so failures are reported after it, the first in cell order.
void record_first(std::atomic<int>& first, int cell) {
  for (int current = first.load(); cell < current && !first.compare_exchange_weak(current, cell);) {
  }
}

}  // namespace

HarmonicElementBases::HarmonicElementBases(const PolyhedralMesh& mesh, HarmonicBasisKind kind,
                                           const MfsOptions& options, const HarmonicBasisMemory* previous,
                                           HarmonicBasisMemory* remember)
    : mesh_(mesh), cells_(static_cast<size_t>(mesh.cell_count())) {
  const int cells = mesh.cell_count();
  std::vector<int> mfs_cells;  // to fit, or to move a fit to
  std::vector<CellShapeKey> shapes(cells);
  for (int cell = 0; cell < cells; ++cell) {
    Cell& entry = cells_[cell];
    if (kind == HarmonicBasisKind::automatic) {
      if (auto plain = plain_cell(mesh, cell)) {
        entry.plain = plain->type;
        entry.nodes = std::move(plain->nodes);
        continue;
      }
    }
    entry.nodes = cell_nodes(mesh, cell);
    shapes[cell] = cell_shape_key(mesh, cell);
    if (std::optional<ElementHarmonicBasis> earlier = previous ? previous->find(shapes[cell], options) : std::nullopt) {
      entry.mfs = std::move(earlier);
      ++remembered_bases_;
      continue;
    }
    mfs_cells.push_back(cell);
  }
  // Cells alike but for their place and size share one fit: a blade through a grid cuts
  // every crossed cell alike (the 2,048 pieces of docs/performance.md's cut take a few
  // fits), and so does a refinement, whose levels also repeat its cells halved. The first
  // of them in cell order is fitted.
  std::vector<int> fitted_for(cells, -1);  // the cell whose fit a cell takes
  std::vector<int> to_fit;
  std::unordered_multimap<std::uint64_t, int> fitted_shapes;
  for (int cell : mfs_cells) {
    const auto [first, last] = fitted_shapes.equal_range(shapes[cell].hash);
    for (auto candidate = first; candidate != last && fitted_for[cell] < 0; ++candidate)
      if (shapes[candidate->second] == shapes[cell]) fitted_for[cell] = candidate->second;
    if (fitted_for[cell] >= 0) continue;
    fitted_shapes.emplace(shapes[cell].hash, cell);
    to_fit.push_back(cell);
  }
  // Over several ranks each fits every count()-th of them and the fits are gathered, so
  // the fitting, most of the set-up, is divided while every rank holds every basis (the
  // mesh is replicated: docs/scaling.md).
  std::vector<int> fit_here;
  for (size_t k = 0; k < to_fit.size(); ++k)
    if (ranks::computes_item(k)) fit_here.push_back(to_fit[k]);
  // Each face's coordinates once, shared by its two cells; then the cells.
  const std::vector<std::optional<FaceHarmonicCoordinates>> faces = mesh_face_coordinates(mesh, fit_here, options);
  // A cell whose basis fails is recorded and its basis left empty.
  std::atomic<int> failed_cell{cells};
  const auto count = static_cast<int>(fit_here.size());
  // One cell at a time: a fit takes milliseconds, and an event fits a few cells (the
  // pencil's cut two), which chunks of four left to one thread.
#pragma omp parallel for schedule(dynamic, 1)
  for (int k = 0; k < count; ++k) {
    const int cell = fit_here[k];
    Cell& entry = cells_[cell];
    try {
      entry.mfs.emplace(cell_harmonic_basis(mesh, cell, faces, options));
      if (std::isfinite(entry.mfs->boundary_residual())) continue;
    } catch (const std::exception&) {
    }
    record_first(failed_cell, cell);
  }
  if (ranks::distributed()) {
    const std::vector<double> failed = ranks::gather(static_cast<double>(failed_cell.load()));
    failed_cell = static_cast<int>(*std::min_element(failed.begin(), failed.end()));
  }
  if (failed_cell < cells)
    throw NumericalError("harmonic basis of cell " + std::to_string(failed_cell.load()) +
                         ": the MFS least-squares fit failed or is not finite (degenerate polyhedron?)");
  ranks::exchange_items(
      to_fit.size(), "altfem harmonic fits 1", [&](BinaryWriter& out, size_t k) { cells_[to_fit[k]].mfs->write(out); },
      [&](BinaryReader& in, size_t k) { return (cells_[to_fit[k]].mfs = ElementHarmonicBasis::read(in)).has_value(); });
  for (int cell : mfs_cells) {
    const int source = fitted_for[cell];
    if (source < 0) continue;
    cells_[cell].mfs = moved_basis(*cells_[source].mfs, shapes[source], shapes[cell]);
    ++moved_bases_;
  }
  if (remember)
    for (int cell : to_fit) remember->add(shapes[cell], *cells_[cell].mfs);
}

double HarmonicElementBases::max_boundary_residual() const {
  double largest = 0;
  for (const auto& cell : cells_)
    if (cell.mfs) largest = std::max(largest, cell.mfs->boundary_residual());
  return largest;
}

std::vector<EarlierCell> HarmonicElementBases::cells_tabulated_earlier(const EarlierTabulation* earlier, int strength,
                                                                       const std::vector<char>& held) const {
  if (!earlier || earlier->strength != strength) return std::vector<EarlierCell>(static_cast<size_t>(cell_count()));
  const HarmonicElementBases& before = *earlier->bases;
  std::vector<const ElementHarmonicBasis*> bases, earlier_bases;
  std::vector<char> earlier_held;
  for (int cell = 0; cell < cell_count(); ++cell) bases.push_back(mfs_basis(cell));
  for (int cell = 0; cell < before.cell_count(); ++cell) {
    earlier_bases.push_back(before.mfs_basis(cell));
    earlier_held.push_back(earlier->elements->holds(cell) ? 1 : 0);
  }
  return match_earlier_cells(mesh_, bases, held, before.mesh_, earlier_bases, earlier_held);
}

TabulatedElements HarmonicElementBases::tabulate(int strength, const HarmonicQuadrature& quadrature,
                                                 const std::vector<int>& materials, const TabulatedHere& here,
                                                 const TabulatedElements* listed, const EarlierTabulation* earlier,
                                                 int* copied) const {
  const int cells = cell_count();
  const std::vector<char> held = tabulated_here(here, cells);
  const std::vector<EarlierCell> copy_from = cells_tabulated_earlier(earlier, strength, held);
  if (copied)
    *copied = static_cast<int>(
        std::count_if(copy_from.begin(), copy_from.end(), [](const EarlierCell& from) { return from.cell >= 0; }));
  // Plain cells: fem's Lagrange tabulation (tet_rule / hex_rule of `strength`) of the
  // cells of each type as one Lagrange mesh on all the mesh's nodes; plain_row[cell] is
  // the cell's element in its type's table.
  const std::array<ElementType, 2> plain_types{ElementType::tet4, ElementType::hex8};
  std::array<TabulatedElements, 2> plain_tables;
  std::vector<int> plain_row(cells, -1);
  for (size_t t = 0; t < plain_types.size(); ++t) {
    const int corners = element_corner_count(plain_types[t]);
    std::vector<int> rows;
    for (int cell = 0; cell < cells; ++cell)
      if (cells_[cell].plain == plain_types[t]) plain_row[cell] = static_cast<int>(rows.size()), rows.push_back(cell);
    if (rows.empty()) continue;
    VolumeMesh volume;
    volume.element_type = plain_types[t];
    volume.nodes = mesh_.nodes;
    volume.cells.resize(static_cast<Eigen::Index>(rows.size()), corners);
    for (size_t row = 0; row < rows.size(); ++row)
      for (int corner = 0; corner < corners; ++corner)
        volume.cells(static_cast<Eigen::Index>(row), corner) = cells_[rows[row]].nodes[corner];
    const bool tetrahedra = plain_types[t] == ElementType::tet4;
    plain_tables[t] =
        tabulate_lagrange(volume, LagrangeCellRules{tetrahedra ? tet_rule(strength) : hex_rule(strength), {}, {}},
                          [&](int row) { return held[rows[row]] != 0; });
  }
  // MFS cells: the chosen rule on the polyhedron and the consistency correction. A rule
  // without points would leave the cell unintegrated (the correction divides by its
  // volume): the first such cell is reported after the loop.
  std::vector<HarmonicTabulation> mfs_tables(cells);
  std::vector<int> elsewhere_points(static_cast<size_t>(cells), 0);  // a cell another rank tabulates
  std::atomic<int> empty_cell{cells};
  // One cell at a time, as the fits: after an event only its new cells are tabulated.
#pragma omp parallel for schedule(dynamic, 1)
  for (int cell = 0; cell < cells; ++cell) {
    if (!cells_[cell].mfs) continue;
    if (!held[cell] && listed) {
      elsewhere_points[cell] = listed->whole_point_count(cell);
      continue;
    }
    if (copy_from[cell].cell >= 0) continue;
    const PolyhedronRule rule = harmonic_cell_rule(cell_polyhedron(mesh_, cell), strength, quadrature, cell);
    if (rule.weights.size() == 0) {
      record_first(empty_cell, cell);
      continue;
    }
    if (held[cell]) mfs_tables[cell] = tabulate_harmonic_element(*cells_[cell].mfs, rule, quadrature.consistent);
    else elsewhere_points[cell] = static_cast<int>(rule.weights.size());
  }
  if (empty_cell < cells)
    throw NumericalError("harmonic quadrature of cell " + std::to_string(empty_cell.load()) +
                         ": its rule has no point inside the cell (raise subdivision_levels or monte_carlo_points)");
  // Laid out at its full size, then each cell's data copied into its place in parallel
  // (appended cell by cell, it was a serial copy of the whole tabulation into zeroed memory).
  const auto plain_table = [&](int cell) -> const TabulatedElements& {
    return plain_tables[*cells_[cell].plain == plain_types[0] ? 0 : 1];
  };
  // Plain cells that share one tabulation there (a grid's equal cells, tabulate_lagrange)
  // share it here too: the first of them is copied, the others read that copy.
  std::vector<int> same_as(static_cast<size_t>(cells), -1);
  std::unordered_map<const double*, int> first_reader;  // a plain table's points → the first cell reading them
  TabulatedElements elements;
  elements.lay_out(cells, [&](int cell) {
    const int material = materials.empty() ? 0 : materials[cell];
    if (cells_[cell].plain) {
      const TabulatedElements& table = plain_table(cell);
      const ElementView view = table[plain_row[cell]];
      if (held[cell] && view.point_count() > 0) {
        const auto [entry, inserted] = first_reader.try_emplace(view.weights.data(), cell);
        if (!inserted) same_as[cell] = entry->second;
      }
      return ElementLayout{view.basis, table.whole_point_count(plain_row[cell]), material, held[cell] != 0,
                           same_as[cell]};
    }
    const int points = copy_from[cell].cell >= 0 ? earlier->elements->whole_point_count(copy_from[cell].cell)
                       : held[cell]              ? static_cast<int>(mfs_tables[cell].weights.size())
                                                 : elsewhere_points[cell];
    return ElementLayout{cells_[cell].nodes, points, material, held[cell] != 0};
  });
#pragma omp parallel for schedule(dynamic, 16)
  for (int cell = 0; cell < cells; ++cell) {
    if (!held[cell] || same_as[cell] >= 0) continue;
    ElementSlots slots = elements.slots(cell);
    if (copy_from[cell].cell >= 0) {
      // The earlier cell's points, its nodes taken in this cell's order.
      const ElementView view = (*earlier->elements)[copy_from[cell].cell];
      const std::vector<int>& order = copy_from[cell].order;
      const auto nodes = static_cast<Eigen::Index>(order.size());
      std::copy(view.weights.begin(), view.weights.end(), slots.weights.begin());
      slots.values = view.values(Eigen::all, order);
      for (int point = 0; point < view.point_count(); ++point)
        slots.gradients.middleRows(point * nodes, nodes) = view.gradients_at(point)(order, Eigen::all);
      continue;
    }
    if (cells_[cell].plain) {
      const ElementView view = plain_table(cell)[plain_row[cell]];
      std::copy(view.weights.begin(), view.weights.end(), slots.weights.begin());
      slots.values = view.values;
      std::copy(view.gradients, view.gradients + slots.gradients.size(), slots.gradients.data());
      continue;
    }
    HarmonicTabulation& table = mfs_tables[cell];
    std::copy(table.weights.begin(), table.weights.end(), slots.weights.begin());
    slots.values = table.values;
    slots.gradients = table.gradients;
    table = {};  // release as we go
  }
  return elements;
}

bool HarmonicElementBases::evaluate(int cell, const Eigen::Vector3d& x, Eigen::VectorXd& values) const {
  const Cell& entry = cells_[cell];
  if (entry.mfs) {
    entry.mfs->evaluate(x, values);
    return true;
  }
  const ReferenceElement& element = reference_element(*entry.plain);
  const InverseMapResult inverse = map_to_reference(element, mesh_.nodes(entry.nodes, Eigen::all), x);
  if (!inverse.converged) return false;
  values.resize(element.node_count());
  element.evaluate(inverse.xi, values);
  return true;
}

void HarmonicElementBases::write(BinaryWriter& out) const {
  out.put<std::int64_t>(static_cast<std::int64_t>(cells_.size()));
  for (const Cell& cell : cells_) {
    out.matrix(Eigen::Map<const Eigen::VectorXi>(cell.nodes.data(), static_cast<Eigen::Index>(cell.nodes.size())));
    out.put<std::int32_t>(cell.plain ? static_cast<std::int32_t>(*cell.plain) : -1);
    if (cell.mfs) cell.mfs->write(out);
  }
}

std::optional<HarmonicElementBases> HarmonicElementBases::read(const PolyhedralMesh& mesh, BinaryReader& in) {
  const auto count = in.get<std::int64_t>();
  if (!count || *count != mesh.cell_count()) return std::nullopt;
  std::vector<Cell> cells(static_cast<size_t>(*count));
  for (Cell& cell : cells) {
    Eigen::VectorXi nodes;
    if (!in.matrix(nodes) || (nodes.size() > 0 && (nodes.minCoeff() < 0 || nodes.maxCoeff() >= mesh.nodes.rows())))
      return std::nullopt;
    cell.nodes.assign(nodes.begin(), nodes.end());
    const auto plain = in.get<std::int32_t>();
    if (!plain) return std::nullopt;
    if (*plain == static_cast<std::int32_t>(ElementType::tet4) ||
        *plain == static_cast<std::int32_t>(ElementType::hex8)) {
      cell.plain = static_cast<ElementType>(*plain);
      if (static_cast<int>(cell.nodes.size()) != element_corner_count(*cell.plain)) return std::nullopt;
      continue;
    }
    if (*plain != -1) return std::nullopt;
    cell.mfs = ElementHarmonicBasis::read(in);
    if (!cell.mfs || cell.mfs->node_count() != static_cast<int>(cell.nodes.size())) return std::nullopt;
  }
  if (!in.at_end()) return std::nullopt;
  return HarmonicElementBases(mesh, std::move(cells));
}

}  // namespace altfem::harmonic
