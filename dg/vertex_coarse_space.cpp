#include "dg/vertex_coarse_space.hpp"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <string>

#include "shared/common/error.hpp"
#include "shared/geometry/monomial_index.hpp"

namespace altfem::dg {

namespace {

// The mesh nodes of a cell's faces, sorted, each once.
std::vector<int> cell_nodes(const PolyhedralMesh& mesh, int cell) {
  std::vector<int> nodes;
  for (int face : mesh.cell_faces[cell]) nodes.insert(nodes.end(), mesh.faces[face].begin(), mesh.faces[face].end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

// The least-squares fit X⁺ (4 × #nodes) of a cell's design matrix X (#nodes × 4: 1 and the
// centred, scaled coordinates of its vertices). By the normal equations XᵀX (a 4 × 4
// eigenproblem) when they are well conditioned — κ(X) ≤ 10⁴, every reasonable cell, since
// the coordinates are centred and scaled — else by X's SVD, which resolves slivers down to
// σ_min/σ_max = 1e-10 (squaring κ would lose them).
Eigen::MatrixXd affine_fit(const Eigen::MatrixXd& design, int cell) {
  const Eigen::Matrix4d gram = design.transpose() * design;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eigen(gram);
  const Eigen::Vector4d& squares = eigen.eigenvalues();  // ascending
  if (squares[0] > 1e-8 * squares[3])
    return eigen.eigenvectors() * squares.cwiseInverse().asDiagonal() * eigen.eigenvectors().transpose() *
           design.transpose();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(design, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::Vector4d singular = svd.singularValues();
  // Centred and scaled, X's singular values are O(1) on any reasonable cell; 1e-10 of the
  // largest only on a cell flattened to a plane.
  if (!(singular[3] > 1e-10 * singular[0]))
    throw NumericalError("dg two-level coarse space: the vertices of cell " + std::to_string(cell) +
                         " lie in a plane (no affine fit)");
  return svd.matrixV() * singular.cwiseInverse().asDiagonal() * svd.matrixU().transpose();
}

}  // namespace

VertexCoarseSpace vertex_coarse_space(const PolyhedralMesh& mesh, const DgLinearSystem& system) {
  std::vector<std::vector<int>> nodes_of_cell(mesh.cell_count());
  std::vector<int> vertex_of_node(mesh.nodes.rows(), -1);
  for (int cell = 0; cell < mesh.cell_count(); ++cell) {
    nodes_of_cell[cell] = cell_nodes(mesh, cell);
    for (int node : nodes_of_cell[cell]) vertex_of_node[node] = 0;
  }
  VertexCoarseSpace space;
  for (int node = 0; node < static_cast<int>(vertex_of_node.size()); ++node)
    if (vertex_of_node[node] == 0) {
      vertex_of_node[node] = static_cast<int>(space.nodes.size());
      space.nodes.push_back(node);
    }

  // The affine monomials 1, (x − c)/h, (y − c)/h, (z − c)/h of every element's basis.
  const int affine[4] = {monomial_index(0, 0, 0), monomial_index(1, 0, 0), monomial_index(0, 1, 0),
                         monomial_index(0, 0, 1)};
  std::vector<Eigen::Triplet<double>> entries;
  for (int cell = 0; cell < mesh.cell_count(); ++cell) {
    const std::vector<int>& nodes = nodes_of_cell[cell];
    const MonomialBasis& basis = system.basis(cell);
    // Least squares: the fit's coefficients are X⁺ values, X (#nodes × 4) the affine monomials at the vertices.
    Eigen::MatrixXd design(nodes.size(), 4);
    for (size_t v = 0; v < nodes.size(); ++v) {
      design(v, 0) = 1;
      design.row(v).tail<3>() = (mesh.nodes.row(nodes[v]).transpose() - basis.centre()) / basis.scale();
    }
    const Eigen::MatrixXd fit = affine_fit(design, cell);  // 4 × #nodes
    // The monomial coefficients of the fit (#functions × #nodes), or, for a cell whose functions
    // are combinations φ_j = Σ_a C_aj m_a (strong conditions), their coefficients C⁻¹ μ.
    Eigen::MatrixXd coefficients = Eigen::MatrixXd::Zero(basis.size(), static_cast<Eigen::Index>(nodes.size()));
    for (int m = 0; m < 4; ++m) coefficients.row(affine[m]) = fit.row(m);
    if (basis.combination().size() > 0) coefficients = basis.combination().partialPivLu().solve(coefficients).eval();
    const int first_function = system.offset(cell);
    for (Eigen::Index a = 0; a < coefficients.rows(); ++a)
      for (size_t v = 0; v < nodes.size(); ++v)
        if (coefficients(a, v) != 0)
          for (int i = 0; i < 3; ++i)
            entries.emplace_back(3 * (first_function + static_cast<int>(a)) + i, 3 * vertex_of_node[nodes[v]] + i,
                                 coefficients(a, v));
  }
  space.prolongation.resize(system.dof_count(), 3 * static_cast<Eigen::Index>(space.nodes.size()));
  space.prolongation.setFromTriplets(entries.begin(), entries.end());
  return space;
}

}  // namespace altfem::dg
