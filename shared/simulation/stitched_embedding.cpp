#include "shared/simulation/stitched_embedding.hpp"

namespace altfem {

StitchedEmbedding::StitchedEmbedding(const ElementBasisEvaluator& field, const Eigen::MatrixXd& nodes,
                                     const ElementBasisEvaluator& interpolation, const Eigen::MatrixXd& points)
    : nodal_(field, nodes), interpolation_(interpolation, points) {}

Eigen::MatrixXd StitchedEmbedding::displacement(const Eigen::VectorXd& u) const {
  const Eigen::MatrixXd nodal = nodal_.displacement(u);  // #nodes × 3, eq. (30)
  const Eigen::MatrixXd transposed = nodal.transpose();  // node i's DOFs at 3i..3i+2
  return interpolation_.displacement(Eigen::Map<const Eigen::VectorXd>(transposed.data(), transposed.size()));
}

}  // namespace altfem
