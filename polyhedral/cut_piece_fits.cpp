#include "polyhedral/cut_piece_fits.hpp"

#include <cmath>
#include <optional>
#include <unordered_map>

#include "polyhedral/mesh_face_coordinates.hpp"
#include "polyhedral/plain_cells.hpp"

namespace altfem::harmonic {

std::vector<bool> cells_whose_fit_fails(const PolyhedralMesh& pieces, const std::vector<int>& candidates,
                                        HarmonicBasisKind kind, const MfsOptions& options, double max_residual,
                                        HarmonicBasisMemory& memory) {
  const std::size_t count = candidates.size();
  std::vector<CellShapeKey> shapes(count);
  std::vector<std::size_t> to_fit;                                 // into candidates, one per new shape
  std::vector<std::optional<std::size_t>> fitted_as(count);        // the candidate whose fit a candidate shares
  std::unordered_multimap<std::uint64_t, std::size_t> new_shapes;  // by hash, into candidates
  for (std::size_t k = 0; k < count; ++k) {
    const int cell = candidates[k];
    if (kind == HarmonicBasisKind::automatic && plain_cell(pieces, cell)) continue;
    shapes[k] = cell_shape_key(pieces, cell);
    if (memory.holds(shapes[k], options)) continue;
    const auto [first, last] = new_shapes.equal_range(shapes[k].hash);
    for (auto other = first; other != last && !fitted_as[k]; ++other)
      if (shapes[other->second] == shapes[k]) fitted_as[k] = other->second;
    if (fitted_as[k]) continue;
    fitted_as[k] = k;
    new_shapes.emplace(shapes[k].hash, k);
    to_fit.push_back(k);
  }
  std::vector<int> cells;
  for (const std::size_t k : to_fit) cells.push_back(candidates[k]);
  const std::vector<std::optional<FaceHarmonicCoordinates>> faces = mesh_face_coordinates(pieces, cells, options);
  std::vector<std::optional<ElementHarmonicBasis>> fits(to_fit.size());
  const auto fit_count = static_cast<int>(to_fit.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (int k = 0; k < fit_count; ++k) {
    try {
      fits[k].emplace(cell_harmonic_basis(pieces, cells[k], faces, options));
    } catch (const std::exception&) {  // a degenerate face or cell: refused below
    }
  }
  std::vector<bool> fails(count, false);
  for (std::size_t k = 0; k < to_fit.size(); ++k) {
    const bool passes =
        fits[k] && std::isfinite(fits[k]->boundary_residual()) && fits[k]->boundary_residual() <= max_residual;
    fails[to_fit[k]] = !passes;
    if (passes) memory.add(shapes[to_fit[k]], *fits[k]);
  }
  for (std::size_t k = 0; k < count; ++k)
    if (fitted_as[k]) fails[k] = fails[*fitted_as[k]];
  return fails;
}

}  // namespace altfem::harmonic
