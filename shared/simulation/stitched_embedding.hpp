#pragma once
// Stitching, the comparison embedding of Kaufmann et al. 2009 §7: a discontinuous field
// is averaged at the nodes of a conforming mesh over the elements containing each node
// (eq. (30), BoundaryPointRule::average), and the nodal averages are interpolated at the
// embedded points by that mesh's own C⁰ basis (linear/trilinear for tetrahedra and
// hexahedra: "stitching followed by barycentric interpolation", their Fig. 5 left).
#include <Eigen/Core>

#include "shared/simulation/basis_embedding.hpp"

namespace altfem {

class StitchedEmbedding final : public PointEmbedding {
public:
  /// field: the discontinuous basis; nodes: #nodes × 3; interpolation: a conforming basis
  /// whose function i is node i; points: #points × 3.
  StitchedEmbedding(const ElementBasisEvaluator& field, const Eigen::MatrixXd& nodes,
                    const ElementBasisEvaluator& interpolation, const Eigen::MatrixXd& points);

  /// Displacement at every point (#points × 3) from the field's coefficients u.
  Eigen::MatrixXd displacement(const Eigen::VectorXd& u) const override;
  /// The interpolation's location facts (points outside its mesh are extrapolated).
  nlohmann::json facts() const override { return interpolation_.facts(); }

private:
  BasisEmbedding nodal_, interpolation_;
};

}  // namespace altfem
