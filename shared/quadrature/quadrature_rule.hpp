#pragma once
// A quadrature rule on a reference domain: the common currency of every integrator
// in altfem (reference elements, FCM cut cells, DG faces).
#include <Eigen/Core>

namespace altfem {

struct QuadratureRule {
  Eigen::MatrixXd points;   ///< #points × dim (dim 1, 2 or 3), reference coordinates
  Eigen::VectorXd weights;  ///< #points; they sum to the measure of the reference domain
  int strength = 0;         ///< every polynomial of total degree <= strength is integrated exactly
};

}  // namespace altfem
