#pragma once
// Checks of cut polyhedral meshes: every cell's boundary closed and consistently
// oriented, and every node where its sources put it.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "shared/mesh/cut_polyhedral_mesh.hpp"
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

// Every node of `cut` where its NodeSource puts it among the nodes of the input (1e-15).
inline ::testing::AssertionResult every_node_at_its_source(const Eigen::MatrixXd& input_nodes,
                                                           const PolyhedralCut& cut) {
  if (cut.node_sources.size() != static_cast<std::size_t>(cut.mesh.nodes.rows()))
    return ::testing::AssertionFailure() << cut.node_sources.size() << " sources for " << cut.mesh.nodes.rows()
                                         << " nodes";
  for (Eigen::Index node = 0; node < cut.mesh.nodes.rows(); ++node) {
    const NodeSource& source = cut.node_sources[node];
    const Eigen::RowVector3d placed =
        (1 - source.weight) * input_nodes.row(source.first) + source.weight * input_nodes.row(source.second);
    if ((cut.mesh.nodes.row(node) - placed).norm() > 1e-15)
      return ::testing::AssertionFailure() << "node " << node << " is not where its sources put it";
  }
  return ::testing::AssertionSuccess();
}

}  // namespace altfem
