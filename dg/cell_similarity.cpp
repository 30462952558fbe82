#include "dg/cell_similarity.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace altfem::dg {

namespace {

// The hash's quantisation step relative to a key's length: far coarser than any
// tolerance of similarity_tolerance (≤ 1e-10 relative in practice), far finer than the
// differences between cells of a mesh that are not translates.
constexpr double quantisation = 0x1p-20;

void combine(std::size_t& seed, std::size_t value) {
  seed ^= value + 0x9e3779b97f4a7c15ULL + (seed << 6) + (seed >> 2);
}

// A point relative to the centre on the hash's grid: the order in which keys list
// vertices, so that a translate numbered otherwise (a cell of a mesh whose faces are
// oriented for its neighbour, a face loop starting elsewhere) gets the same key.
using GridPoint = std::array<long long, 3>;
GridPoint grid_point(const Eigen::Vector3d& relative, double length) {
  const double step = quantisation * length;
  return {std::llround(relative[0] / step), std::llround(relative[1] / step), std::llround(relative[2] / step)};
}

}  // namespace

double similarity_tolerance(double length, double magnitude, double relative_tolerance) {
  return relative_tolerance * length + 16 * std::numeric_limits<double>::epsilon() * magnitude;
}

SimilarityKey cell_similarity_key(const Polyhedron& cell, const Eigen::Vector3d& centre, double diameter,
                                  const std::vector<int>& extra, double relative_tolerance) {
  const auto vertex_count = static_cast<int>(cell.vertices.rows());
  // Canonical numbering: vertices by their grid points, each face loop from its lowest
  // vertex (orientation kept), the loops in lexicographic order. Equal keys then mean the
  // same polyhedron whatever the numbering; a tie of grid points (vertices 1e-6 cell
  // sizes apart) only makes the order arbitrary, which can cost a hit, never give one.
  std::vector<GridPoint> points(vertex_count);
  for (int v = 0; v < vertex_count; ++v) points[v] = grid_point(cell.vertices.row(v).transpose() - centre, diameter);
  std::vector<int> order(vertex_count), rank(vertex_count);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return points[a] < points[b]; });
  for (int position = 0; position < vertex_count; ++position) rank[order[position]] = position;
  std::vector<std::vector<int>> loops;
  loops.reserve(cell.faces.size());
  for (const std::vector<int>& face : cell.faces) {
    std::vector<int> loop;
    loop.reserve(face.size());
    for (int v : face) loop.push_back(rank[v]);
    std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
    loops.push_back(std::move(loop));
  }
  std::sort(loops.begin(), loops.end());

  SimilarityKey key;
  key.structure.push_back(vertex_count);
  for (const std::vector<int>& loop : loops) {
    key.structure.push_back(static_cast<int>(loop.size()));
    key.structure.insert(key.structure.end(), loop.begin(), loop.end());
  }
  key.structure.insert(key.structure.end(), extra.begin(), extra.end());
  key.coordinates.reserve(3 * static_cast<size_t>(vertex_count));
  double magnitude = centre.cwiseAbs().maxCoeff();
  for (int v : order) {
    for (int d = 0; d < 3; ++d) key.coordinates.push_back(cell.vertices(v, d) - centre[d]);
    magnitude = std::max(magnitude, cell.vertices.row(v).cwiseAbs().maxCoeff());
  }
  key.length = diameter;
  key.tolerance = similarity_tolerance(diameter, magnitude, relative_tolerance);
  return key;
}

SimilarityKey face_similarity_key(const Eigen::MatrixXd& polygon, const Eigen::Vector3d& normal,
                                  const Eigen::Vector3d& centre, double length, const Eigen::Vector3d* other_centre,
                                  std::vector<int> structure, double relative_tolerance) {
  SimilarityKey key;
  key.structure = std::move(structure);
  const auto vertex_count = static_cast<int>(polygon.rows());
  key.structure.push_back(vertex_count);
  key.coordinates.reserve(3 * static_cast<size_t>(vertex_count) + 6);
  double magnitude = centre.cwiseAbs().maxCoeff();
  const auto add_point = [&](const Eigen::Vector3d& point) {
    for (int d = 0; d < 3; ++d) key.coordinates.push_back(point[d] - centre[d]);
    magnitude = std::max(magnitude, point.cwiseAbs().maxCoeff());
  };
  // The loop from its lowest grid point (the cell's canonical numbering, for one loop).
  int first = 0;
  for (int v = 1; v < vertex_count; ++v)
    if (grid_point(polygon.row(v).transpose() - centre, length) <
        grid_point(polygon.row(first).transpose() - centre, length))
      first = v;
  for (int v = 0; v < vertex_count; ++v) add_point(polygon.row((first + v) % vertex_count).transpose());
  for (int d = 0; d < 3; ++d) key.coordinates.push_back(normal[d] * length);
  if (other_centre) add_point(*other_centre);
  key.length = length;
  key.tolerance = similarity_tolerance(length, magnitude, relative_tolerance);
  return key;
}

std::size_t SimilarityClasses::hash(const SimilarityKey& key) {
  std::size_t seed = key.structure.size();
  for (int value : key.structure) combine(seed, static_cast<std::size_t>(value));
  const double step = quantisation * key.length;
  for (double value : key.coordinates) combine(seed, static_cast<std::size_t>(std::llround(value / step)));
  return seed;
}

bool SimilarityClasses::similar(const SimilarityKey& a, const SimilarityKey& b) {
  if (a.structure != b.structure || a.coordinates.size() != b.coordinates.size()) return false;
  const double tolerance = std::max(a.tolerance, b.tolerance);
  for (size_t i = 0; i < a.coordinates.size(); ++i)
    if (!(std::abs(a.coordinates[i] - b.coordinates[i]) <= tolerance)) return false;
  return true;
}

int SimilarityClasses::find(const SimilarityKey& key) const { return find(key, hash(key)); }

int SimilarityClasses::find(const SimilarityKey& key, std::size_t code) const {
  if (!enabled_) return -1;
  const auto [first, last] = buckets_.equal_range(code);
  for (auto candidate = first; candidate != last; ++candidate)
    if (similar(representatives_[candidate->second], key)) return candidate->second;
  return -1;
}

SimilarityClasses::Assignment SimilarityClasses::classify(SimilarityKey key) {
  ++key_count_;
  if (!enabled_) return {class_count_++, true};
  const std::size_t code = hash(key);
  if (const int found = find(key, code); found >= 0) return {found, false};
  buckets_.emplace(code, class_count_);
  representatives_.push_back(std::move(key));
  return {class_count_++, true};
}

}  // namespace altfem::dg
