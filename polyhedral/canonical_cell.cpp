#include "polyhedral/canonical_cell.hpp"

#include <algorithm>
#include <numeric>

#include "polyhedral/plain_cells.hpp"

namespace altfem::harmonic {

CanonicalCell canonical_cell(const PolyhedralMesh& mesh, int cell) {
  const Polyhedron listed = cell_polyhedron(mesh, cell);
  const Eigen::MatrixXd& vertices = listed.vertices;
  const auto count = static_cast<int>(vertices.rows());
  CanonicalCell canonical;
  canonical.nodes = cell_nodes(mesh, cell);
  canonical.local.resize(count);
  std::iota(canonical.local.begin(), canonical.local.end(), 0);
  std::sort(canonical.local.begin(), canonical.local.end(), [&](int a, int b) {
    const auto x = vertices.row(a), y = vertices.row(b);
    return std::lexicographical_compare(x.begin(), x.end(), y.begin(), y.end());
  });
  canonical.sorted.resize(count);
  for (int k = 0; k < count; ++k) canonical.sorted[canonical.local[k]] = k;
  canonical.polyhedron.vertices = vertices(canonical.local, Eigen::all);
  // cell_polyhedron lists the cell's faces in cell_faces order.
  std::vector<std::vector<int>> loops(listed.faces.size());
  for (size_t f = 0; f < listed.faces.size(); ++f) {
    for (int vertex : listed.faces[f]) loops[f].push_back(canonical.sorted[vertex]);
    std::rotate(loops[f].begin(), std::min_element(loops[f].begin(), loops[f].end()), loops[f].end());
  }
  std::vector<int> order(loops.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return loops[a] < loops[b]; });
  for (int f : order) {
    canonical.polyhedron.faces.push_back(std::move(loops[f]));
    canonical.mesh_faces.push_back(mesh.cell_faces[cell][f]);
  }
  return canonical;
}

}  // namespace altfem::harmonic
