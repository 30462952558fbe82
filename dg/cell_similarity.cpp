#include "dg/cell_similarity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace altfem::dg {

namespace {

// The hash's quantisation step relative to a key's length: far coarser than any
// tolerance of similarity_tolerance (≤ 1e-10 relative in practice), far finer than the
// differences between cells of a mesh that are not translates.
constexpr double quantisation = 0x1p-20;

void combine(std::size_t& seed, std::size_t value) { seed ^= value + 0x9e3779b97f4a7c15ULL + (seed << 6) + (seed >> 2); }

}  // namespace

double similarity_tolerance(double length, double magnitude, double relative_tolerance) {
  return relative_tolerance * length + 16 * std::numeric_limits<double>::epsilon() * magnitude;
}

SimilarityKey cell_similarity_key(const Polyhedron& cell, const Eigen::Vector3d& centre, double diameter,
                                  const std::vector<int>& extra, double relative_tolerance) {
  SimilarityKey key;
  const auto vertex_count = static_cast<int>(cell.vertices.rows());
  key.structure.push_back(vertex_count);
  for (const std::vector<int>& loop : cell.faces) {
    key.structure.push_back(static_cast<int>(loop.size()));
    key.structure.insert(key.structure.end(), loop.begin(), loop.end());
  }
  key.structure.insert(key.structure.end(), extra.begin(), extra.end());
  key.coordinates.reserve(3 * static_cast<size_t>(vertex_count));
  double magnitude = centre.cwiseAbs().maxCoeff();
  for (int v = 0; v < vertex_count; ++v) {
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
  key.structure.push_back(static_cast<int>(polygon.rows()));
  key.coordinates.reserve(3 * static_cast<size_t>(polygon.rows()) + 6);
  double magnitude = centre.cwiseAbs().maxCoeff();
  const auto add_point = [&](const Eigen::Vector3d& point) {
    for (int d = 0; d < 3; ++d) key.coordinates.push_back(point[d] - centre[d]);
    magnitude = std::max(magnitude, point.cwiseAbs().maxCoeff());
  };
  for (Eigen::Index v = 0; v < polygon.rows(); ++v) add_point(polygon.row(v).transpose());
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

SimilarityClasses::Assignment SimilarityClasses::classify(SimilarityKey key) {
  ++key_count_;
  if (!enabled_) return {class_count_++, true};
  const std::size_t code = hash(key);
  const auto [first, last] = buckets_.equal_range(code);
  for (auto candidate = first; candidate != last; ++candidate)
    if (similar(representatives_[candidate->second], key)) return {candidate->second, false};
  buckets_.emplace(code, class_count_);
  representatives_.push_back(std::move(key));
  return {class_count_++, true};
}

}  // namespace altfem::dg
