#include "dg/multigrid_coarse_space.hpp"

#include <Eigen/Core>
#include <vector>

#include "dg/affine_coarse_space.hpp"
#include "dg/vertex_coarse_space.hpp"

namespace altfem::dg {

namespace {

// `space` as one scalar function per vertex (a cell fits each component alike), placed
// with the constant function of a cell holding its vertex; its near-null space the rigid
// motions at the vertices, which P maps to the fine ones exactly (they are affine).
CoarseSpace scalar_vertex_space(const VertexCoarseSpace& space, const PolyhedralMesh& mesh,
                                const DgLinearSystem& system) {
  CoarseSpace coarse;
  const auto vertices = static_cast<Eigen::Index>(space.nodes.size());
  std::vector<int> vertex_of_node(mesh.nodes.rows(), -1);
  for (Eigen::Index vertex = 0; vertex < vertices; ++vertex)
    vertex_of_node[space.nodes[vertex]] = static_cast<int>(vertex);
  coarse.fine_function.assign(space.nodes.size(), -1);
  for (int cell = 0; cell < mesh.cell_count(); ++cell)
    for (int face : mesh.cell_faces[cell])
      for (int node : mesh.faces[face])
        if (int& fine = coarse.fine_function[vertex_of_node[node]]; fine < 0) fine = system.offset(cell);
  // Component 0's rows and columns of the vector prolongation: every component's fit is the same.
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index column = 0; column < space.prolongation.outerSize(); column += 3)
    for (Eigen::SparseMatrix<double>::InnerIterator entry(space.prolongation, column); entry; ++entry)
      if (entry.row() % 3 == 0) entries.emplace_back(entry.row() / 3, column / 3, entry.value());
  coarse.prolongation.resize(space.prolongation.rows() / 3, vertices);
  coarse.prolongation.setFromTriplets(entries.begin(), entries.end());
  // The rigid motions as shared/simulation/rigid_motion.cpp interpolates them: e_i and e_i × x.
  coarse.near_null_space.resize(3 * vertices, 6);
  for (Eigen::Index vertex = 0; vertex < vertices; ++vertex) {
    const Eigen::Vector3d x = mesh.nodes.row(space.nodes[vertex]).transpose();
    for (int axis = 0; axis < 3; ++axis) {
      const Eigen::Vector3d direction = Eigen::Vector3d::Unit(axis);
      coarse.near_null_space.block<3, 1>(3 * vertex, axis) = direction;
      coarse.near_null_space.block<3, 1>(3 * vertex, 3 + axis) = direction.cross(x);
    }
  }
  return coarse;
}

}  // namespace

CoarseSpace multigrid_coarse_space(const PolyhedralMesh& mesh, const DgLinearSystem& system) {
  if (!system.constrained_dofs().empty()) return {};
  const VertexCoarseSpace space = vertex_coarse_space(mesh, system);
  if (space.prolongation.cols() >= system.dof_count()) return affine_coarse_space(system);
  CoarseSpace vertices = scalar_vertex_space(space, mesh, system);
  // Its rows couple each vertex with those of its cells' neighbours (about 50 on a
  // hexahedral grid), so MIS-2 on the squared graph aggregates 3,075 of them into 108 at
  // once. Gently coarsened, CG took 34, 26 and 21 iterations on the k = 2 cantilever (20 ×
  // 2 × 2 to 80 × 8 × 8) against 45, 47 and 36, and the 80 × 8 × 8 set-up and solve 15.9 s
  // against 20.2 s: for degree ≥ 2 an iteration is mostly the fine level's. On k = 1 the
  // dearer set-up outweighed its fewer iterations there (13 against 26; 5.9 s against 4.4 s).
  vertices.coarsen_gently = system.offset(1) - system.offset(0) > 4;  // beyond the affine monomials
  return vertices;
}

}  // namespace altfem::dg
