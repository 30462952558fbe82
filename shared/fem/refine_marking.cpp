#include "shared/fem/refine_marking.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "shared/simulation/cell_stresses.hpp"

namespace altfem {

namespace {

// Per cell, Σ_F |F| |r_F|² and Σ_F |F| over its interior and loaded boundary faces.
std::pair<Eigen::VectorXd, Eigen::VectorXd> traction_jumps(int cell_count, const IndicatorFaces& faces,
                                                           const std::vector<Eigen::Matrix3d>& stresses) {
  Eigen::VectorXd squared_jumps = Eigen::VectorXd::Zero(cell_count);
  Eigen::VectorXd areas = Eigen::VectorXd::Zero(cell_count);
  for (const SharedFace& face : faces.interior) {
    const double weighted = face.area * ((stresses[face.first] - stresses[face.second]) * face.normal).squaredNorm();
    for (const int cell : {face.first, face.second}) {
      squared_jumps[cell] += weighted;
      areas[cell] += face.area;
    }
  }
  for (const LoadedBoundaryFace& face : faces.boundary) {
    squared_jumps[face.cell] += face.area * (stresses[face.cell] * face.normal - face.traction).squaredNorm();
    areas[face.cell] += face.area;
  }
  return {squared_jumps, areas};
}

// Per cell, whether bulk marking takes it: of the `candidates`, the fewest with the largest
// `estimates` (squared) whose sum reaches `fraction` of theirs.
std::vector<char> bulk_marks(const Eigen::VectorXd& estimates, std::vector<int> candidates, double fraction) {
  std::stable_sort(candidates.begin(), candidates.end(), [&](int a, int b) { return estimates[a] > estimates[b]; });
  double total = 0;
  for (const int cell : candidates) total += estimates[cell];
  std::vector<char> marked(static_cast<std::size_t>(estimates.size()), 0);
  double sum = 0;
  for (const int cell : candidates) {
    if (sum >= fraction * total || estimates[cell] <= 0) break;
    marked[cell] = 1;
    sum += estimates[cell];
  }
  return marked;
}

}  // namespace

Eigen::VectorXd traction_jump_indicator(int cell_count, const IndicatorFaces& faces,
                                        const std::vector<Eigen::Matrix3d>& stresses) {
  const auto [squared_jumps, areas] = traction_jumps(cell_count, faces, stresses);
  Eigen::VectorXd indicator = Eigen::VectorXd::Zero(cell_count);
  for (int cell = 0; cell < cell_count; ++cell)
    if (areas[cell] > 0) indicator[cell] = std::sqrt(squared_jumps[cell] / areas[cell]);
  return indicator;
}

RefineMarks mark_cells_to_refine(const RefineSpec& refine, const std::vector<Eigen::Matrix3d>& stresses,
                                 const IndicatorFaces& faces, const Eigen::MatrixXd& centroids,
                                 const Eigen::VectorXd& volumes, const std::vector<int>& levels, double tolerance,
                                 nlohmann::json& facts) {
  const int cell_count = static_cast<int>(stresses.size());
  if (centroids.rows() != cell_count || volumes.size() != cell_count ||
      (!levels.empty() && static_cast<int>(levels.size()) != cell_count))
    throw std::invalid_argument("mark_cells_to_refine: one stress, centroid, volume and level per cell");
  const bool by_indicator = refine.criterion == RefineCriterion::error_indicator;
  const Eigen::VectorXd indicator =
      by_indicator ? traction_jump_indicator(cell_count, faces, stresses) : Eigen::VectorXd();
  std::vector<PrincipalStress> principal(static_cast<std::size_t>(cell_count));
  std::vector<int> in_region;
  for (int cell = 0; cell < cell_count; ++cell) {
    principal[cell] = largest_principal_stress(stresses[cell]);
    if (!refine.region || refine.region->contains(centroids.row(cell).transpose(), tolerance))
      in_region.push_back(cell);
  }
  std::vector<char> bulk;
  if (refine.fraction) {
    Eigen::VectorXd estimates(cell_count);
    if (by_indicator) {
      const Eigen::VectorXd squared_jumps = traction_jumps(cell_count, faces, stresses).first;
      for (int cell = 0; cell < cell_count; ++cell) estimates[cell] = std::cbrt(volumes[cell]) * squared_jumps[cell];
    } else {
      for (int cell = 0; cell < cell_count; ++cell)
        estimates[cell] = volumes[cell] * principal[cell].value * principal[cell].value;
    }
    bulk = bulk_marks(estimates, in_region, *refine.fraction);
  }
  RefineMarks marks;
  int at_max_level = 0;
  for (const int cell : in_region) {
    const bool above =
        refine.fraction ? bulk[cell] != 0 : (by_indicator ? indicator[cell] : principal[cell].value) > refine.threshold;
    if (!above) continue;
    if (!levels.empty() && levels[cell] >= refine.max_level) {
      ++at_max_level;
      continue;
    }
    marks.cells.push_back(cell);
    marks.directions.push_back(principal[cell].direction);
  }
  double largest = 0;
  for (const PrincipalStress& stress : principal) largest = std::max(largest, stress.value);
  facts = {{"marked_cells", marks.cells.size()}, {"at_max_level", at_max_level}, {"largest_stress", largest}};
  if (by_indicator) facts["largest_indicator"] = indicator.size() > 0 ? indicator.maxCoeff() : 0.0;
  return marks;
}

}  // namespace altfem
