#include "shared/mesh/face_neighbours.hpp"

#include <algorithm>
#include <array>
#include <cstddef>

#include "shared/element/element_faces.hpp"

namespace altfem {

std::vector<FaceNeighbour> face_neighbours(const VolumeMesh& mesh) {
  const ElementShape shape = element_shape(mesh.element_type);
  const auto faces = element_faces(shape);
  const auto face_count = faces.size();
  const int corners = face_corner_count(shape);
  const std::size_t sides = static_cast<std::size_t>(mesh.cells.rows()) * face_count;
  // Each side's corner nodes, sorted (unused corners −1), by side index cell · F + f.
  std::vector<std::array<int, 4>> keys(sides);
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell)
    for (std::size_t f = 0; f < face_count; ++f) {
      std::array<int, 4>& key = keys[static_cast<std::size_t>(cell) * face_count + f];
      key = {-1, -1, -1, -1};
      for (int c = 0; c < corners; ++c) key[c] = mesh.cells(cell, faces[f][c]);
      std::sort(key.begin(), key.begin() + corners);
    }
  // The sides bucketed by their smallest node (a counting sort, in side order), then each
  // bucket sorted by key: the sides of one face are a run, its first side the first in
  // cell order. Buckets, not one sort of every side: a pencil's tip cell holds thousands
  // of tetrahedra, matched again at every cut.
  std::vector<std::size_t> offsets(static_cast<std::size_t>(mesh.nodes.rows()) + 1, 0);
  for (const std::array<int, 4>& key : keys) ++offsets[static_cast<std::size_t>(key[0]) + 1];
  for (std::size_t n = 1; n < offsets.size(); ++n) offsets[n] += offsets[n - 1];
  std::vector<std::size_t> order(sides);
  std::vector<std::size_t> next(offsets.begin(), offsets.end() - 1);
  for (std::size_t side = 0; side < sides; ++side) order[next[static_cast<std::size_t>(keys[side][0])]++] = side;

  std::vector<FaceNeighbour> neighbours(sides);
  const auto by_key = [&](std::size_t a, std::size_t b) { return keys[a] < keys[b] || (keys[a] == keys[b] && a < b); };
  const auto side_of = [&](std::size_t side) {
    return FaceNeighbour{static_cast<int>(side / face_count), static_cast<int>(side % face_count)};
  };
  for (std::size_t n = 0; n + 1 < offsets.size(); ++n) {
    const auto begin = order.begin() + static_cast<std::ptrdiff_t>(offsets[n]);
    const auto end = order.begin() + static_cast<std::ptrdiff_t>(offsets[n + 1]);
    std::sort(begin, end, by_key);
    for (auto first = begin; first != end;) {
      auto later = first + 1;
      // Each later side of the face meets the first (a face of more than two sides: the last).
      for (; later != end && keys[*later] == keys[*first]; ++later) {
        neighbours[*later] = side_of(*first);
        neighbours[*first] = side_of(*later);
      }
      first = later;
    }
  }
  return neighbours;
}

}  // namespace altfem
