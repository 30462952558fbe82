#include "shared/fem/refine_marking.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "shared/simulation/cell_stresses.hpp"

namespace altfem {

Eigen::VectorXd traction_jump_indicator(int cell_count, std::span<const SharedFace> faces,
                                        const std::vector<Eigen::Matrix3d>& stresses) {
  Eigen::VectorXd squared_jumps = Eigen::VectorXd::Zero(cell_count);
  Eigen::VectorXd areas = Eigen::VectorXd::Zero(cell_count);
  for (const SharedFace& face : faces) {
    const double weighted = face.area * ((stresses[face.first] - stresses[face.second]) * face.normal).squaredNorm();
    for (const int cell : {face.first, face.second}) {
      squared_jumps[cell] += weighted;
      areas[cell] += face.area;
    }
  }
  Eigen::VectorXd indicator = Eigen::VectorXd::Zero(cell_count);
  for (int cell = 0; cell < cell_count; ++cell)
    if (areas[cell] > 0) indicator[cell] = std::sqrt(squared_jumps[cell] / areas[cell]);
  return indicator;
}

RefineMarks mark_cells_to_refine(const RefineSpec& refine, const std::vector<Eigen::Matrix3d>& stresses,
                                 std::span<const SharedFace> faces, const Eigen::MatrixXd& centroids,
                                 const std::vector<int>& levels, double tolerance, nlohmann::json& facts) {
  const int cell_count = static_cast<int>(stresses.size());
  if (centroids.rows() != cell_count || (!levels.empty() && static_cast<int>(levels.size()) != cell_count))
    throw std::invalid_argument("mark_cells_to_refine: one stress, centroid and level per cell");
  const bool by_indicator = refine.criterion == RefineCriterion::error_indicator;
  const Eigen::VectorXd indicator =
      by_indicator ? traction_jump_indicator(cell_count, faces, stresses) : Eigen::VectorXd();
  RefineMarks marks;
  int at_max_level = 0;
  double largest = 0;
  for (int cell = 0; cell < cell_count; ++cell) {
    const PrincipalStress principal = largest_principal_stress(stresses[cell]);
    largest = std::max(largest, principal.value);
    if (!((by_indicator ? indicator[cell] : principal.value) > refine.threshold)) continue;
    if (refine.region && !refine.region->contains(centroids.row(cell).transpose(), tolerance)) continue;
    if (!levels.empty() && levels[cell] >= refine.max_level) {
      ++at_max_level;
      continue;
    }
    marks.cells.push_back(cell);
    marks.directions.push_back(principal.direction);
  }
  facts = {{"marked_cells", marks.cells.size()}, {"at_max_level", at_max_level}, {"largest_stress", largest}};
  if (by_indicator) facts["largest_indicator"] = indicator.size() > 0 ? indicator.maxCoeff() : 0.0;
  return marks;
}

}  // namespace altfem
