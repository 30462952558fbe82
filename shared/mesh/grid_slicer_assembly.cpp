// GridSlicer::assemble: the PolyhedralMesh from the surface pieces and the grid faces'
// regions — hexahedra, one cell per connected piece of a cut grid cell, and every face once
// with its cell pair.
#include <algorithm>

#include "shared/mesh/disjoint_sets.hpp"
#include "shared/mesh/grid_slicer.hpp"

namespace altfem {

SlicedMesh GridSlicer::assemble(const SurfacePieces& pieces) {
  SlicedMesh result;
  PolyhedralMesh& mesh = result.mesh;
  grid_hexahedra_.assign(grid_.cell_count(), -1);
  std::vector<int> piece_cell(pieces.polygons.size(), -1);
  // Per grid face of a cut cell (its key), the mesh cell of each of its loops on the lower
  // and on the upper side.
  std::unordered_map<long long, std::vector<int>> loop_cells_lower, loop_cells_upper;
  int cell_count = 0;
  for (int cell = 0; cell < grid_.cell_count(); ++cell) {
    if (state_[cell] == CellState::outside) continue;
    if (state_[cell] == CellState::inside) {
      grid_hexahedra_[cell] = cell_count;
      mesh.cell_kinds.push_back(PolyhedralCellKind::hexahedron);
      ++cell_count;
      ++result.hexahedra;
      continue;
    }
    // The cut cell's closed boundary: its pieces and its faces' loops; pieces are the
    // connected components by shared edges (a vertex alone does not join them).
    std::vector<const std::vector<int>*> boundary;
    for (int p : cell_pieces_[cell]) boundary.push_back(&pieces.polygons[p]);
    const Eigen::Vector3i coordinates = grid_.cell_coordinates(cell);
    std::array<long long, 6> keys;
    for (int local = 0; local < 6; ++local) {
      GridFace face{local / 2, coordinates};
      face.node(face.axis) += local % 2;
      keys[local] = face_key(face);
      for (const auto& loop : regions_.at(keys[local])) boundary.push_back(&loop);
    }
    DisjointSets components(static_cast<int>(boundary.size()));
    std::unordered_map<long long, int> edge_owner;
    for (int f = 0; f < static_cast<int>(boundary.size()); ++f) {
      const auto& loop = *boundary[f];
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const auto [it, inserted] = edge_owner.emplace(edge_key(loop[i], loop[(i + 1) % loop.size()]), f);
        if (!inserted) components.join(it->second, f);
      }
    }
    std::unordered_map<int, int> component_cell;
    auto mesh_cell_of = [&](int f) {
      const auto [it, inserted] = component_cell.emplace(components.find(f), cell_count);
      if (inserted) {
        mesh.cell_kinds.push_back(PolyhedralCellKind::cut);
        ++cell_count;
      }
      return it->second;
    };
    int f = 0;
    for (int p : cell_pieces_[cell]) piece_cell[p] = mesh_cell_of(f++);
    for (int local = 0; local < 6; ++local) {
      auto& cells = (local % 2 ? loop_cells_lower : loop_cells_upper)[keys[local]];
      for (std::size_t loop = 0; loop < regions_.at(keys[local]).size(); ++loop) cells.push_back(mesh_cell_of(f++));
    }
    result.cut_pieces += static_cast<int>(component_cell.size());
    result.split_grid_cells += component_cell.size() > 1;
  }

  // Faces: the surface pieces (boundary), then every grid face with material on a side.
  std::vector<std::array<int, 2>> face_cells;
  auto add_face = [&](std::vector<int> loop, int lower, int upper) {
    if (lower < 0) {
      std::reverse(loop.begin(), loop.end());
      std::swap(lower, upper);
    }
    mesh.faces.push_back(std::move(loop));
    face_cells.push_back({lower, upper});
  };
  for (std::size_t p = 0; p < pieces.polygons.size(); ++p) add_face(pieces.polygons[p], piece_cell[p], -1);
  for (int axis = 0; axis < 3; ++axis) {
    Eigen::Vector3i extent = grid_.cells;
    ++extent(axis);
    for (int k = 0; k < extent(2); ++k)
      for (int j = 0; j < extent(1); ++j)
        for (int i = 0; i < extent(0); ++i) {
          const GridFace face{axis, Eigen::Vector3i(i, j, k)};
          const int lower = lower_cell(face), upper = upper_cell(face);
          if (!has_material(lower) && !has_material(upper)) continue;
          const auto region = regions_.find(face_key(face));
          if (region == regions_.end()) {  // between uncut cells: the whole rectangle
            const auto corners = corners_up(face);
            add_face({corners.begin(), corners.end()}, has_material(lower) ? grid_hexahedra_[lower] : -1,
                     has_material(upper) ? grid_hexahedra_[upper] : -1);
            continue;
          }
          const auto side_cells = [&](int cell, const auto& loop_cells, std::size_t loop) {
            if (!has_material(cell)) return -1;
            return state_[cell] == CellState::inside ? grid_hexahedra_[cell] : loop_cells.at(region->first)[loop];
          };
          for (std::size_t loop = 0; loop < region->second.size(); ++loop)
            add_face(region->second[loop], side_cells(lower, loop_cells_lower, loop),
                     side_cells(upper, loop_cells_upper, loop));
        }
  }

  mesh.cell_faces.assign(cell_count, {});
  set_faces(mesh, std::move(mesh.faces), face_cells);
  const auto& points = nodes_.points();
  mesh.nodes.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t n = 0; n < points.size(); ++n) mesh.nodes.row(n) = points[n];
  result.grid_cells = grid_.cells;
  result.cell_size = grid_.cell_size;
  return result;
}

}  // namespace altfem
