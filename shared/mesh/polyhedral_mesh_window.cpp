#include "shared/mesh/polyhedral_mesh_window.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <stdexcept>

#include "shared/mesh/merge_slivers.hpp"

namespace altfem {

std::vector<Eigen::AlignedBox3d> polyhedral_cell_boxes(const PolyhedralMesh& mesh) {
  std::vector<Eigen::AlignedBox3d> boxes(static_cast<std::size_t>(mesh.cell_count()));
  for (int cell = 0; cell < mesh.cell_count(); ++cell)
    for (const int face : mesh.cell_faces[cell])
      for (const int node : mesh.faces[face]) boxes[cell].extend(mesh.nodes.row(node).transpose());
  return boxes;
}

PolyhedralMeshWindow polyhedral_mesh_window(const PolyhedralMesh& mesh,
                                            const std::vector<Eigen::AlignedBox3d>& cell_boxes,
                                            const Eigen::AlignedBox3d& box) {
  PolyhedralMeshWindow window;
  const int cells = mesh.cell_count();
  // The cells the box meets, their nodes marked; then every cell holding one of those,
  // whose box touches theirs (boxes are closed).
  std::vector<bool> marked(static_cast<std::size_t>(mesh.nodes.rows()), false);
  Eigen::AlignedBox3d reach;
  for (int cell = 0; cell < cells; ++cell)
    if (cell_boxes[cell].intersects(box)) {
      reach.extend(cell_boxes[cell]);
      for (const int face : mesh.cell_faces[cell])
        for (const int node : mesh.faces[face]) marked[node] = true;
    }
  if (reach.isEmpty()) return window;
  const auto holds_a_marked_node = [&](int cell) {
    for (const int face : mesh.cell_faces[cell])
      for (const int node : mesh.faces[face])
        if (marked[node]) return true;
    return false;
  };
  for (int cell = 0; cell < cells; ++cell)
    if (cell_boxes[cell].intersects(reach) && holds_a_marked_node(cell)) window.cells.push_back(cell);
  std::vector<bool> keep(static_cast<std::size_t>(cells), false);
  for (const int cell : window.cells) keep[cell] = true;
  std::vector<int> kept, kept_faces;
  window.mesh = polyhedral_mesh_with_cells(mesh, keep, kept, &kept_faces);
  window.nodes = drop_unused_nodes(window.mesh);
  for (std::size_t face = 0; face < kept_faces.size(); ++face) {
    const int whole = kept_faces[face], second = mesh.face_cells(whole, 1);
    if (second >= 0 && !(keep[mesh.face_cells(whole, 0)] && keep[second])) {
      window.shell_faces.push_back(whole);
      window.shell_window_faces.push_back(static_cast<int>(face));
    }
  }
  return window;
}

void splice_polyhedral_mesh_window(PolyhedralMesh& mesh, std::vector<Eigen::AlignedBox3d>& cell_boxes,
                                   std::vector<int>& parent_cell, const PolyhedralMeshWindow& window,
                                   PolyhedralMesh&& cut, const std::vector<int>& cut_parent) {
  const int cells = mesh.cell_count(), faces = mesh.face_count();
  const auto window_nodes = static_cast<Eigen::Index>(window.nodes.size());
  const Eigen::Index nodes = mesh.nodes.rows();
  // The cut's nodes: the window's, then its new ones appended to the mesh's.
  std::vector<int> mesh_node(static_cast<std::size_t>(cut.nodes.rows()));
  for (Eigen::Index node = 0; node < cut.nodes.rows(); ++node)
    mesh_node[node] = node < window_nodes ? window.nodes[node] : static_cast<int>(nodes + node - window_nodes);
  mesh.nodes.conservativeResize(nodes + cut.nodes.rows() - window_nodes, 3);
  mesh.nodes.bottomRows(cut.nodes.rows() - window_nodes) = cut.nodes.bottomRows(cut.nodes.rows() - window_nodes);

  // Cells: each window cell's pieces where it was.
  std::vector<int> window_of(static_cast<std::size_t>(cells), -1);
  for (std::size_t inside = 0; inside < window.cells.size(); ++inside)
    window_of[window.cells[inside]] = static_cast<int>(inside);
  std::vector<std::vector<int>> pieces_of(window.cells.size());
  for (std::size_t piece = 0; piece < cut_parent.size(); ++piece)
    pieces_of[cut_parent[piece]].push_back(static_cast<int>(piece));
  std::vector<int> new_cell(static_cast<std::size_t>(cells), -1), piece_cell(cut_parent.size());
  int next_cell = 0;
  for (int cell = 0; cell < cells; ++cell)
    if (window_of[cell] < 0) {
      new_cell[cell] = next_cell++;
    } else {
      for (const int piece : pieces_of[window_of[cell]]) piece_cell[piece] = next_cell++;
      if (pieces_of[window_of[cell]].size() == 1) new_cell[cell] = piece_cell[pieces_of[window_of[cell]][0]];
    }

  // Faces: those outside the window and its shell as they were, then the cut's others.
  std::vector<bool> is_shell(static_cast<std::size_t>(faces), false);
  for (const int face : window.shell_faces) is_shell[face] = true;
  std::vector<int> new_face(static_cast<std::size_t>(faces), -1);
  int next_face = 0;
  for (int face = 0; face < faces; ++face) {
    const int first = mesh.face_cells(face, 0), second = mesh.face_cells(face, 1);
    if (is_shell[face] || (window_of[first] < 0 && (second < 0 || window_of[second] < 0))) new_face[face] = next_face++;
  }
  std::map<std::vector<int>, int> shell_of;  // window loop → shell face
  for (std::size_t k = 0; k < window.shell_faces.size(); ++k)
    shell_of.emplace(window.mesh.faces[window.shell_window_faces[k]], window.shell_faces[k]);
  std::vector<int> cut_face(cut.faces.size());
  std::size_t shells_found = 0;
  for (std::size_t face = 0; face < cut.faces.size(); ++face) {
    if (cut.face_cells(static_cast<Eigen::Index>(face), 1) < 0) {
      const auto shell = shell_of.find(cut.faces[face]);
      if (shell != shell_of.end()) {
        cut_face[face] = new_face[shell->second];
        ++shells_found;
        continue;
      }
    }
    cut_face[face] = next_face++;
  }
  if (shells_found != window.shell_faces.size())
    throw std::logic_error("cut window: a cut changed a face between the window and the rest of the mesh");

  std::vector<std::vector<int>> new_faces(static_cast<std::size_t>(next_face));
  Eigen::MatrixXi new_face_cells(next_face, 2);
  for (int face = 0; face < faces; ++face) {
    if (new_face[face] < 0) continue;
    for (const int side : {0, 1}) {
      const int cell = mesh.face_cells(face, side);
      if (cell >= 0 && new_cell[cell] < 0)
        throw std::logic_error("cut window: a cut split a cell next to the rest of the mesh");
      new_face_cells(new_face[face], side) = cell >= 0 ? new_cell[cell] : -1;
    }
    new_faces[new_face[face]] = std::move(mesh.faces[face]);
  }
  for (std::size_t face = 0; face < cut.faces.size(); ++face) {
    const int index = cut_face[face];
    if (!new_faces[index].empty()) continue;  // a shell face, kept as it was
    for (int& node : cut.faces[face]) node = mesh_node[node];
    new_faces[index] = std::move(cut.faces[face]);
    for (const int side : {0, 1}) {
      const int piece = cut.face_cells(static_cast<Eigen::Index>(face), side);
      new_face_cells(index, side) = piece >= 0 ? piece_cell[piece] : -1;
    }
  }

  // The cells outside the window keep their face lists, renumbered (set_faces would build
  // every cell's anew, at every window: the whole mesh for each triangle of a blade).
  std::vector<std::vector<int>> cell_faces(static_cast<std::size_t>(next_cell));
  std::vector<PolyhedralCellKind> kinds(static_cast<std::size_t>(next_cell));
  std::vector<int> parents(static_cast<std::size_t>(next_cell));
  std::vector<Eigen::AlignedBox3d> boxes(static_cast<std::size_t>(next_cell));
  for (int cell = 0; cell < cells; ++cell) {
    if (window_of[cell] >= 0) continue;
    const int index = new_cell[cell];
    cell_faces[index] = std::move(mesh.cell_faces[cell]);
    for (int& face : cell_faces[index]) face = new_face[face];
    kinds[index] = mesh.cell_kinds[cell];
    parents[index] = parent_cell[cell];
    boxes[index] = cell_boxes[cell];
  }
  for (std::size_t piece = 0; piece < cut_parent.size(); ++piece) {
    const int index = piece_cell[piece];
    cell_faces[index] = std::move(cut.cell_faces[piece]);
    for (int& face : cell_faces[index]) {
      face = cut_face[face];
      for (const int node : new_faces[face]) boxes[index].extend(mesh.nodes.row(node).transpose());
    }
    kinds[index] = cut.cell_kinds[piece];
    parents[index] = parent_cell[window.cells[cut_parent[piece]]];
  }
  mesh.faces = std::move(new_faces);
  mesh.face_cells = std::move(new_face_cells);
  mesh.cell_faces = std::move(cell_faces);
  mesh.cell_kinds = std::move(kinds);
  parent_cell = std::move(parents);
  cell_boxes = std::move(boxes);
  mesh.cell_volumes.resize(0);
  mesh.cell_centroids.resize(0, 3);
  mesh.cell_diameters.resize(0);
  mesh.face_areas.resize(0);
  mesh.face_normals.resize(0, 3);
  mesh.face_centroids.resize(0, 3);
}

}  // namespace altfem
