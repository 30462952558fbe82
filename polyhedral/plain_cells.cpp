#include "polyhedral/plain_cells.hpp"

#include <algorithm>

namespace altfem::harmonic {

namespace {

// The loop of `face` counter-clockwise seen from outside `cell`.
std::vector<int> outward_loop(const PolyhedralMesh& mesh, int cell, int face) {
  std::vector<int> loop = mesh.faces[face];
  if (mesh.face_cells(face, 0) != cell) std::reverse(loop.begin(), loop.end());
  return loop;
}

bool contains(const std::vector<int>& nodes, int node) {
  return std::find(nodes.begin(), nodes.end(), node) != nodes.end();
}

}  // namespace

std::vector<int> cell_nodes(const PolyhedralMesh& mesh, int cell) {
  std::vector<int> nodes;
  for (int face : mesh.cell_faces[cell])
    for (int node : mesh.faces[face])
      if (!contains(nodes, node)) nodes.push_back(node);
  return nodes;
}

std::optional<PlainCell> plain_cell(const PolyhedralMesh& mesh, int cell) {
  const PolyhedralCellKind kind = mesh.cell_kinds[cell];
  const auto& faces = mesh.cell_faces[cell];
  const std::vector<int> nodes = cell_nodes(mesh, cell);
  const bool tetrahedron = kind == PolyhedralCellKind::tetrahedron && faces.size() == 4 && nodes.size() == 4;
  const bool hexahedron = kind == PolyhedralCellKind::hexahedron && faces.size() == 6 && nodes.size() == 8;
  for (int face : faces)
    if (static_cast<int>(mesh.faces[face].size()) != (tetrahedron ? 3 : 4)) return std::nullopt;
  if (!tetrahedron && !hexahedron) return std::nullopt;
  // VTK order: the first face, counter-clockwise seen from outside, is the base
  // (0, 1, 2[, 3]) reversed, since the base's right-hand normal points into the cell.
  const std::vector<int> first = outward_loop(mesh, cell, faces[0]);
  PlainCell plain{tetrahedron ? ElementType::tet4 : ElementType::hex8, {first[0]}};
  for (auto node = first.rbegin(); node + 1 != first.rend(); ++node) plain.nodes.push_back(*node);
  if (tetrahedron) {
    for (int node : nodes)
      if (!contains(first, node)) plain.nodes.push_back(node);
    return plain;
  }
  // Hex8: node 4 + k is the neighbour of base node k (along an edge of a side face)
  // that is not in the base.
  for (int k = 0; k < 4; ++k)
    for (int face : faces) {
      const std::vector<int>& loop = mesh.faces[face];
      const auto at = std::find(loop.begin(), loop.end(), plain.nodes[k]);
      if (at == loop.end()) continue;
      const auto position = at - loop.begin();
      const int next = loop[(position + 1) % 4], previous = loop[(position + 3) % 4];
      const int above = contains(first, next) ? previous : next;
      if (!contains(first, above)) {
        plain.nodes.push_back(above);
        break;
      }
    }
  if (plain.nodes.size() != 8) return std::nullopt;
  return plain;
}

}  // namespace altfem::harmonic
