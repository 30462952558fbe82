#include "shared/cut_cells/piece_basis_evaluator.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <map>

#include <Eigen/LU>  // Matrix3d::inverse

namespace altfem {

namespace {

/// Numbers the evaluators, so that a thread's cached last point (evaluate_inside) is
/// never taken for another evaluator's, even one built where an old one was.
std::atomic<long> next_serial{0};

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
  // The barycentric coordinates by the cofactor inverse: a pivoted LU per tetrahedron was
  // most of a surface's embedding in a cell of thousands of tetrahedra (the pencil's
  // tip). A flat tetrahedron gives no finite coordinates and is measured by its faces.
  const Eigen::Vector3d coordinates = edges.inverse() * (x - origin);
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
      serial_(next_serial++),
      piece_trees_(kept_rows.size()),
      split_cell_(kept_rows.size(), -1) {
  std::map<int, std::vector<int>> kept_pieces;  // background cell → its kept cells
  for (std::size_t cell = 0; cell < kept_rows.size(); ++cell)
    kept_pieces[pieces.background_cell[kept_rows[cell]]].push_back(static_cast<int>(cell));
  const auto tree_of = [&](const std::vector<int>& tetrahedra) {
    std::vector<Eigen::AlignedBox3d> boxes(tetrahedra.size());
    for (std::size_t k = 0; k < tetrahedra.size(); ++k)
      for (int i = 0; i < 4; ++i) boxes[k].extend(embedded.nodes.row(embedded.cells(tetrahedra[k], i)).transpose());
    return Eigen::KdBVH<double, 3, int>(tetrahedra.begin(), tetrahedra.end(), boxes.begin(), boxes.end());
  };
  std::vector<int> all_tetrahedra;
  for (const auto& [background_cell, cells] : kept_pieces) {
    if (cells.size() < 2) continue;
    all_tetrahedra.clear();
    for (const int cell : cells) {
      const std::vector<int>& tetrahedra = pieces.tetrahedra[kept_rows[cell]];
      piece_trees_[cell] = tree_of(tetrahedra);
      all_tetrahedra.insert(all_tetrahedra.end(), tetrahedra.begin(), tetrahedra.end());
      split_cell_[cell] = static_cast<int>(split_cell_trees_.size());
    }
    split_cell_trees_.push_back(tree_of(all_tetrahedra));
  }
}

namespace {

/// Eigen's BVMinimize's minimiser: the distance from x to the nearest tetrahedron, boxes
/// at `bound` or beyond left closed.
struct NearestTetrahedron {
  using Scalar = double;
  const VolumeMesh& embedded;
  const Eigen::Vector3d& x;
  double bound;

  double minimumOnVolume(const Eigen::AlignedBox3d& box) const {
    const double distance = box.exteriorDistance(x);
    return distance < bound ? distance : std::numeric_limits<double>::infinity();
  }
  double minimumOnObject(int tetrahedron) const {
    Eigen::Matrix<double, 4, 3> corners;
    for (int i = 0; i < 4; ++i) corners.row(i) = embedded.nodes.row(embedded.cells(tetrahedron, i));
    return distance_to_tetrahedron(x, corners);
  }
};

}  // namespace

double PieceBasisEvaluator::distance_to(const Eigen::KdBVH<double, 3, int>& tree, const Eigen::Vector3d& x,
                                        double bound) const {
  NearestTetrahedron nearest{embedded_, x, bound};
  return std::min(bound, Eigen::BVMinimize(tree, nearest));
}

bool PieceBasisEvaluator::evaluate_inside(int cell, const Eigen::Vector3d& x, std::vector<int>& basis,
                                          std::vector<double>& values) const {
  if (split_cell_[cell] < 0) return whole_.evaluate_inside(cell, x, basis, values);
  // The callers ask each piece of a cell in turn about the same point (BasisEmbedding
  // tries every candidate cell), and the pieces are one cell's geometry (node copies at
  // their node's position): each thread keeps the last point's reference point in the
  // cell and distance to the cell's material, for all of its pieces.
  struct LastPoint {
    long evaluator = -1;
    int split_cell = -1;
    Eigen::Vector3d x, xi;
    bool inside = false;
    double nearest = 0;
  };
  thread_local LastPoint last;
  if (last.evaluator != serial_ || last.split_cell != split_cell_[cell] || last.x != x) {
    last = {serial_, split_cell_[cell], x, Eigen::Vector3d::Zero(), false, 0.0};
    last.inside = whole_.reference_point(cell, x, last.xi);
    if (last.inside)
      last.nearest = distance_to(split_cell_trees_[split_cell_[cell]], x, std::numeric_limits<double>::infinity());
  }
  if (!last.inside) return false;
  // This piece is (one of) the nearest when nothing in its background cell is nearer.
  if (distance_to(piece_trees_[cell], x, std::nextafter(last.nearest, std::numeric_limits<double>::infinity())) >
      last.nearest)
    return false;
  whole_.evaluate(cell, last.xi, basis, values);
  return true;
}

}  // namespace altfem
