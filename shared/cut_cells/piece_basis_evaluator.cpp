#include "shared/cut_cells/piece_basis_evaluator.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <map>

#include <Eigen/LU>

namespace altfem {

namespace {

/// The closest point of triangle abc to x (Ericson, Real-Time Collision Detection, §5.1.5).
Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& x, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                    const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ax = x - a;
  const double d1 = ab.dot(ax), d2 = ac.dot(ax);
  if (d1 <= 0 && d2 <= 0) return a;
  const Eigen::Vector3d bx = x - b;
  const double d3 = ab.dot(bx), d4 = ac.dot(bx);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Eigen::Vector3d cx = x - c;
  const double d5 = ab.dot(cx), d6 = ac.dot(cx);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denominator = 1.0 / (va + vb + vc);
  return a + ab * (vb * denominator) + ac * (vc * denominator);
}

}  // namespace

double distance_to_tetrahedron(const Eigen::Vector3d& x, const Eigen::Matrix<double, 4, 3>& corners) {
  const Eigen::Vector3d origin = corners.row(0).transpose();
  Eigen::Matrix3d edges;
  for (int i = 0; i < 3; ++i) edges.col(i) = corners.row(i + 1).transpose() - origin;
  const Eigen::Vector3d coordinates = edges.fullPivLu().solve(x - origin);
  if (coordinates.minCoeff() >= 0 && coordinates.sum() <= 1) return 0.0;
  static constexpr std::array<std::array<int, 3>, 4> faces{{{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}}};
  double distance = std::numeric_limits<double>::infinity();
  for (const auto& face : faces) {
    const Eigen::Vector3d closest = closest_on_triangle(
        x, corners.row(face[0]).transpose(), corners.row(face[1]).transpose(), corners.row(face[2]).transpose());
    distance = std::min(distance, (x - closest).norm());
  }
  return distance;
}

PieceBasisEvaluator::PieceBasisEvaluator(const VolumeMesh& mesh, const PieceMesh& pieces,
                                         const std::vector<int>& kept_rows, const VolumeMesh& embedded,
                                         const NodeConstraints* constraints)
    : whole_(mesh, constraints),
      embedded_(embedded),
      piece_tetrahedra_(kept_rows.size()),
      piece_boxes_(kept_rows.size()),
      siblings_(kept_rows.size()) {
  std::map<int, std::vector<int>> kept_pieces;  // background cell → its kept cells
  for (std::size_t cell = 0; cell < kept_rows.size(); ++cell)
    kept_pieces[pieces.background_cell[kept_rows[cell]]].push_back(static_cast<int>(cell));
  for (const auto& [background_cell, cells] : kept_pieces) {
    if (cells.size() < 2) continue;
    for (const int cell : cells) {
      piece_tetrahedra_[cell] = pieces.tetrahedra[kept_rows[cell]];
      for (const int t : piece_tetrahedra_[cell]) {
        Eigen::AlignedBox3d box;
        for (int i = 0; i < 4; ++i) box.extend(embedded.nodes.row(embedded.cells(t, i)).transpose());
        piece_boxes_[cell].push_back(box);
      }
      for (const int other : cells)
        if (other != cell) siblings_[cell].push_back(other);
    }
  }
}

double PieceBasisEvaluator::distance_to_piece(int cell, const Eigen::Vector3d& x, double bound) const {
  double distance = bound;
  Eigen::Matrix<double, 4, 3> corners;
  const std::vector<int>& tetrahedra = piece_tetrahedra_[cell];
  for (std::size_t k = 0; k < tetrahedra.size() && distance > 0; ++k) {
    if (piece_boxes_[cell][k].exteriorDistance(x) >= distance) continue;
    for (int i = 0; i < 4; ++i) corners.row(i) = embedded_.nodes.row(embedded_.cells(tetrahedra[k], i));
    distance = std::min(distance, distance_to_tetrahedron(x, corners));
  }
  return distance;
}

bool PieceBasisEvaluator::evaluate_inside(int cell, const Eigen::Vector3d& x, std::vector<int>& basis,
                                          std::vector<double>& values) const {
  if (!whole_.evaluate_inside(cell, x, basis, values)) return false;
  if (siblings_[cell].empty()) return true;
  const double distance = distance_to_piece(cell, x, std::numeric_limits<double>::infinity());
  return std::none_of(siblings_[cell].begin(), siblings_[cell].end(),
                      [&](int other) { return distance_to_piece(other, x, distance) < distance; });
}

}  // namespace altfem
