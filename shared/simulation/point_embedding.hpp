#pragma once
// A field carried to fixed material points (the embedded surface's vertices): what the
// embeddings a method may deform the scene surface with share (BasisEmbedding; for
// discontinuous bases StitchedEmbedding and MlsEmbedding, Kaufmann et al. 2009 §7).
#include <Eigen/Core>
#include <nlohmann/json.hpp>

namespace altfem {

class PointEmbedding {
public:
  virtual ~PointEmbedding() = default;
  /// Displacement at every point (#points × 3) from the coefficients u (#dofs).
  virtual Eigen::MatrixXd displacement(const Eigen::VectorXd& u) const = 0;
  /// What summary.json's facts say of it (points outside the mesh, samples per point).
  virtual nlohmann::json facts() const = 0;
};

}  // namespace altfem
