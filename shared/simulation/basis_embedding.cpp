#include "shared/simulation/basis_embedding.hpp"

#include <algorithm>

#include "shared/mesh/point_locator.hpp"

namespace altfem {

BasisEmbedding::BasisEmbedding(const ElementBasisEvaluator& evaluator, const Eigen::MatrixXd& points,
                               const std::vector<std::vector<int>>& point_elements) {
  std::vector<Eigen::AlignedBox3d> boxes(static_cast<size_t>(evaluator.element_count()));
  for (int e = 0; e < evaluator.element_count(); ++e) boxes[e] = evaluator.element_bounds(e);
  const PointLocator locator(std::move(boxes));
  const double slack =
      points.rows() > 0 ? 1e-9 * (points.colwise().maxCoeff() - points.colwise().minCoeff()).norm() : 0.0;
  const bool average = evaluator.boundary_rule() == BoundaryPointRule::average;

  std::vector<int> candidates, basis;
  std::vector<double> values;
  for (Eigen::Index point = 0; point < points.rows(); ++point) {
    const Eigen::Vector3d x = points.row(point).transpose();
    if (point_elements.empty()) locator.candidates(x, slack, candidates);
    else candidates = point_elements[point];
    const size_t begin = basis_.size();
    int containing = 0;
    for (int element : candidates) {
      if (!evaluator.evaluate_inside(element, x, basis, values)) continue;
      ++containing;
      basis_.insert(basis_.end(), basis.begin(), basis.end());
      weights_.insert(weights_.end(), values.begin(), values.end());
      if (!average) break;
    }
    if (containing == 0) {
      ++outside_count_;
      max_outside_distance_ = std::max(max_outside_distance_, evaluator.evaluate_nearest(x, basis, values));
      basis_.insert(basis_.end(), basis.begin(), basis.end());
      weights_.insert(weights_.end(), values.begin(), values.end());
    } else if (containing > 1) {
      for (size_t i = begin; i < weights_.size(); ++i) weights_[i] /= containing;
    }
    offsets_.push_back(static_cast<long long>(basis_.size()));
  }
}

Eigen::MatrixXd BasisEmbedding::displacement(const Eigen::VectorXd& u) const {
  const auto count = static_cast<Eigen::Index>(offsets_.size() - 1);
  Eigen::MatrixXd result = Eigen::MatrixXd::Zero(count, 3);
  for (Eigen::Index point = 0; point < count; ++point)
    for (long long entry = offsets_[point]; entry < offsets_[point + 1]; ++entry)
      result.row(point) += weights_[entry] * u.segment<3>(3 * static_cast<Eigen::Index>(basis_[entry])).transpose();
  return result;
}

Eigen::VectorXd BasisEmbedding::load(const Eigen::MatrixXd& forces, int dof_count) const {
  Eigen::VectorXd result = Eigen::VectorXd::Zero(dof_count);
  for (Eigen::Index point = 0; point + 1 < static_cast<Eigen::Index>(offsets_.size()); ++point)
    for (long long entry = offsets_[point]; entry < offsets_[point + 1]; ++entry)
      result.segment<3>(3 * static_cast<Eigen::Index>(basis_[entry])) +=
          weights_[entry] * forces.row(point).transpose();
  return result;
}

}  // namespace altfem
