#include "dg/strong_conditions.hpp"

#include <Eigen/QR>
#include <stdexcept>
#include <string>

#include "dg/face_polynomials.hpp"
#include "shared/common/eigen_decompositions.hpp"
#include "shared/quadrature/polyhedron_rule.hpp"

namespace altfem::dg {

namespace {

// Rank tolerance of the QR of Cᵀ, relative to its largest pivot: the face mass rows of
// one face are exactly dependent (the traces of n monomials span only P_k of the plane),
// and C is assembled from exact moments, so its numerical rank is clear-cut.
constexpr double rank_tolerance = 1e-10;

}  // namespace

StrongCell strong_cell(int cell, const MonomialBasis& monomials, const std::vector<DgFace>& faces,
                       const std::vector<int>& face_indices) {
  StrongCell result;
  result.cell = cell;
  result.faces = face_indices;
  result.components = faces.at(face_indices.front()).components;
  for (int f : face_indices)
    if (faces[f].components != result.components)
      throw std::invalid_argument("strong_cell: faces " + std::to_string(face_indices.front()) + " and " +
                                  std::to_string(f) + " of cell " + std::to_string(cell) +
                                  " prescribe different components");
  const int n = monomials.size();
  // Cᵀ: column (face, b) = ∫_f m_a m_b dA over a, from the face's exact moments.
  Eigen::MatrixXd constraints_transposed(n, n * static_cast<Eigen::Index>(face_indices.size()));
  for (size_t k = 0; k < face_indices.size(); ++k) {
    const FaceIntegrals face(faces[face_indices[k]].polygon, monomials.degree(), monomials.centre(), monomials.scale());
    const Eigen::MatrixXd unit = Eigen::MatrixXd::Identity(n, n);  // the monomials' coefficients
    constraints_transposed.middleCols(static_cast<Eigen::Index>(k) * n, n) = face.products(unit, unit);
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(constraints_transposed);
  qr.setThreshold(rank_tolerance);
  result.constrained = static_cast<int>(qr.rank());
  result.combination = qr.householderQ();  // its first r columns span C's rows
  const Eigen::MatrixXd constrained_part =
      constraints_transposed.transpose() * result.combination.leftCols(result.constrained);  // C Q₁
  // (C Q₁)⁺ = ((C Q₁)ᵀ)⁺ᵀ: the decomposition of the wide transpose solves against an r × r
  // identity, not against one of #faces · n rows (a cut cell's hundreds of strong facets
  // made that cost seconds per cell).
  result.data_map = constrained_part.transpose().completeOrthogonalDecomposition().pseudoInverse().transpose();
  return result;
}

Eigen::MatrixXd constrained_values(const StrongCell& cell, const MonomialBasis& monomials,
                                   const std::vector<DgFace>& faces, const ConditionData& data) {
  const int n = monomials.size();
  int prescribed = 0;
  for (bool component : cell.components) prescribed += component;
  // d_b = ∫_f g_i m_b dA, by a rule exact for data of degree ≤ k + 2.
  Eigen::MatrixXd stacked = Eigen::MatrixXd::Zero(n * static_cast<Eigen::Index>(cell.faces.size()), 3);
  Eigen::VectorXd values;
  Eigen::MatrixXd gradients;
  for (size_t k = 0; k < cell.faces.size(); ++k) {
    const DgFace& face = faces[cell.faces[k]];
    const PolyhedronRule rule = polygon_rule(face.polygon, 2 * monomials.degree() + 2);
    for (Eigen::Index q = 0; q < rule.weights.size(); ++q) {
      const Eigen::Vector3d x = rule.points.row(q).transpose();
      monomials.evaluate(x, values, gradients);
      const Eigen::Vector3d g = data(face.condition, x);
      stacked.middleRows(static_cast<Eigen::Index>(k) * n, n) += rule.weights[q] * values * g.transpose();
    }
  }
  Eigen::MatrixXd result(prescribed, cell.constrained);
  int row = 0;
  for (int i = 0; i < 3; ++i)
    if (cell.components[i]) result.row(row++) = (cell.data_map * stacked.col(i)).transpose();
  return result;
}

}  // namespace altfem::dg
