#pragma once
// A check of cut polyhedral meshes: every cell's boundary closed and consistently oriented.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "shared/mesh/polyhedral_mesh.hpp"

namespace altfem {

// Every directed edge of a cell's outward face loops is matched by its reverse: the
// cell's boundary is closed and consistently oriented.
inline ::testing::AssertionResult every_cell_closed(const PolyhedralMesh& mesh) {
  for (int cell = 0; cell < mesh.cell_count(); ++cell) {
    std::map<std::pair<int, int>, int> edges;
    for (const int face : mesh.cell_faces[cell]) {
      std::vector<int> loop = mesh.faces[face];
      if (loop.size() < 3)
        return ::testing::AssertionFailure() << "face " << face << " has " << loop.size() << " nodes";
      if (mesh.face_cells(face, 0) != cell) std::reverse(loop.begin(), loop.end());
      for (std::size_t k = 0; k < loop.size(); ++k) ++edges[{loop[k], loop[(k + 1) % loop.size()]}];
    }
    for (const auto& [edge, count] : edges) {
      const auto reverse = edges.find({edge.second, edge.first});
      if (reverse == edges.end() || reverse->second != count)
        return ::testing::AssertionFailure()
               << "cell " << cell << ": edge " << edge.first << " → " << edge.second << " has no matching reverse";
    }
  }
  return ::testing::AssertionSuccess();
}

}  // namespace altfem
