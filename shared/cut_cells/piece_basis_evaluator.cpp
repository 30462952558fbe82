#include "shared/cut_cells/piece_basis_evaluator.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <map>

#include <Eigen/LU>  // Matrix3d::inverse

#include "shared/io/binary_cache.hpp"

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

// The barycentric coordinates of x in the tetrahedron but the first (4 × 3 corners), by
// the cofactor inverse: a pivoted LU per tetrahedron was most of a surface's embedding in
// a cell of thousands of tetrahedra (the pencil's tip). A flat tetrahedron gives no finite
// coordinates.
Eigen::Vector3d barycentric_coordinates(const Eigen::Vector3d& x, const Eigen::Matrix<double, 4, 3>& corners) {
  Eigen::Matrix3d edges;
  for (int i = 0; i < 3; ++i) edges.col(i) = (corners.row(i + 1) - corners.row(0)).transpose();
  return edges.inverse() * (x - corners.row(0).transpose());
}

Eigen::Matrix<double, 4, 3> corners_of(const VolumeMesh& embedded, int tetrahedron) {
  Eigen::Matrix<double, 4, 3> corners;
  for (int i = 0; i < 4; ++i) corners.row(i) = embedded.nodes.row(embedded.cells(tetrahedron, i));
  return corners;
}

// A hash of a piece's tetrahedra, each by its corners in order (the distances read them
// so), whatever their numbering: a cut renumbers the tetrahedra it left alone.
std::uint64_t tetrahedra_key(const VolumeMesh& embedded, const std::vector<int>& tetrahedra) {
  std::vector<std::uint64_t> keys;
  keys.reserve(tetrahedra.size());
  for (const int tetrahedron : tetrahedra) {
    CacheKeyHasher hasher;
    hasher.matrix(corners_of(embedded, tetrahedron));
    keys.push_back(hasher.value());
  }
  std::sort(keys.begin(), keys.end());
  CacheKeyHasher hasher;
  hasher.bytes(keys.data(), keys.size() * sizeof(std::uint64_t));
  return hasher.value();
}

}  // namespace

double distance_to_tetrahedron(const Eigen::Vector3d& x, const Eigen::Matrix<double, 4, 3>& corners, double below) {
  // A flat tetrahedron, whose coordinates are not finite, is measured by its faces.
  const Eigen::Vector3d coordinates = barycentric_coordinates(x, corners);
  // A point on a face (a surface vertex on the material's boundary) comes out a rounding
  // off it: within 1e-12 is on it, distance 0, so that the nearest-piece search stops.
  constexpr double on_face = 1e-12;
  if (coordinates.minCoeff() >= -on_face && coordinates.sum() <= 1 + on_face) return 0.0;
  if (below <= std::numeric_limits<double>::denorm_min()) return below;  // only containment was asked
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
      split_cell_(kept_rows.size(), -1),
      piece_keys_(kept_rows.size(), 0) {
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
  std::vector<std::pair<int, int>> split_cell_pieces;
  for (const auto& [background_cell, cells] : kept_pieces) {
    if (cells.size() < 2) continue;
    all_tetrahedra.clear();
    for (const int cell : cells) {
      const std::vector<int>& tetrahedra = pieces.tetrahedra[kept_rows[cell]];
      piece_trees_[cell] = tree_of(tetrahedra);
      all_tetrahedra.insert(all_tetrahedra.end(), tetrahedra.begin(), tetrahedra.end());
      split_cell_[cell] = static_cast<int>(split_cell_trees_.size());
      piece_keys_[cell] = tetrahedra_key(embedded, tetrahedra);
      for (const int tetrahedron : tetrahedra) split_cell_pieces.push_back({tetrahedron, cell});
    }
    split_cell_trees_.push_back(tree_of(all_tetrahedra));
    std::sort(split_cell_pieces.begin(), split_cell_pieces.end());
    split_cell_pieces_.push_back(std::move(split_cell_pieces));
    split_cell_pieces.clear();
  }
}

namespace {

/// Eigen's BVMinimize's minimiser: the distance from x to the nearest tetrahedron, boxes
/// at `bound` or beyond left closed; `nearest` the first tetrahedron measured at the least
/// distance.
struct NearestTetrahedron {
  using Scalar = double;
  const VolumeMesh& embedded;
  const Eigen::Vector3d& x;
  double bound;
  mutable int nearest = -1;
  mutable double nearest_distance = std::numeric_limits<double>::infinity();

  double minimumOnVolume(const Eigen::AlignedBox3d& box) const {
    // Less what a tetrahedron in the box forgives as rounding (distance_to_tetrahedron:
    // 1e-12 of its heights, at a corner √3 times that): a lower bound of what any of them
    // measures.
    const double distance = std::max(0.0, box.exteriorDistance(x) - 2e-12 * box.diagonal().norm());
    return distance < bound ? distance : std::numeric_limits<double>::infinity();
  }
  double minimumOnObject(int tetrahedron) const {
    const double distance = distance_to_tetrahedron(x, corners_of(embedded, tetrahedron), bound);
    if (distance < nearest_distance) {
      nearest = tetrahedron;
      nearest_distance = distance;
    }
    return distance;
  }
};

// Whether x lies inside the tetrahedron by more than rounding: then no other piece of
// its cell holds it, since the pieces' tetrahedra do not overlap.
bool well_inside(const Eigen::Vector3d& x, const Eigen::Matrix<double, 4, 3>& corners) {
  const Eigen::Vector3d coordinates = barycentric_coordinates(x, corners);
  return coordinates.minCoeff() > 1e-9 && coordinates.sum() < 1 - 1e-9;
}

}  // namespace

double PieceBasisEvaluator::distance_to(const Eigen::KdBVH<double, 3, int>& tree, const Eigen::Vector3d& x,
                                        double bound, int* nearest) const {
  NearestTetrahedron search{embedded_, x, bound};
  const double distance = std::min(bound, Eigen::BVMinimize(tree, search));
  if (nearest) *nearest = search.nearest_distance == distance ? search.nearest : -1;
  return distance;
}

std::uint64_t PieceBasisEvaluator::element_key(int cell) const {
  const std::uint64_t whole = whole_.element_key(cell);
  if (split_cell_[cell] < 0) return whole;
  CacheKeyHasher hasher;
  hasher.scalar(whole);
  hasher.scalar(piece_keys_[cell]);
  return hasher.value();
}

int PieceBasisEvaluator::piece_of(int split_cell, int tetrahedron) const {
  const auto& pieces = split_cell_pieces_[split_cell];
  const auto found = std::lower_bound(pieces.begin(), pieces.end(), std::pair<int, int>(tetrahedron, -1));
  return found != pieces.end() && found->first == tetrahedron ? found->second : -1;
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
    int holding_piece = -1;  // the kept cell whose tetrahedron holds x well inside, if known
  };
  thread_local LastPoint last;
  if (last.evaluator != serial_ || last.split_cell != split_cell_[cell] || last.x != x) {
    last = {serial_, split_cell_[cell], x, Eigen::Vector3d::Zero(), false, 0.0, -1};
    last.inside = whole_.reference_point(cell, x, last.xi);
    if (last.inside) {
      // Inside a piece's tetrahedron by more than rounding, x is nearest to that piece
      // alone, and the other pieces need no search: a surface vertex of a pencil's chip
      // searched the tip's thousands of long tetrahedra, whose boxes hold it, for nothing.
      // The tetrahedron that held the point before is tried first: the surface's vertices
      // come in order, and neighbours mostly share one.
      thread_local std::pair<long, int> hint{-1, -1};  // (evaluator, tetrahedron)
      const int split_cell = split_cell_[cell];
      int tetrahedron = -1;
      if (hint.first == serial_ && piece_of(split_cell, hint.second) >= 0 &&
          distance_to_tetrahedron(x, corners_of(embedded_, hint.second), std::numeric_limits<double>::denorm_min()) ==
              0) {
        tetrahedron = hint.second;
        last.nearest = 0;
      } else {
        last.nearest =
            distance_to(split_cell_trees_[split_cell], x, std::numeric_limits<double>::infinity(), &tetrahedron);
      }
      if (last.nearest == 0 && tetrahedron >= 0) {
        hint = {serial_, tetrahedron};
        if (well_inside(x, corners_of(embedded_, tetrahedron))) last.holding_piece = piece_of(split_cell, tetrahedron);
      }
    }
  }
  if (!last.inside) return false;
  if (last.holding_piece >= 0) {
    if (cell != last.holding_piece) return false;
  } else if (distance_to(piece_trees_[cell], x, std::nextafter(last.nearest, std::numeric_limits<double>::infinity())) >
             last.nearest) {
    // This piece is (one of) the nearest when nothing in its background cell is nearer.
    return false;
  }
  whole_.evaluate(cell, last.xi, basis, values);
  return true;
}

}  // namespace altfem
