#pragma once
// The surfaces a method works with and how its field reaches them, as one value: the
// scene surface every method deforms (docs/conventions.md, "Metrics": methods are
// compared on the same vertices), the surface its loads act on and the curved faces that
// surface stands for, the method's basis at any point, and the embedding of the surface's
// vertices. EmbeddedSurfaceMethod implements MethodInstance's surface functions from it
// once for every method.
#include <memory>

#include "shared/mesh/surface_mesh.hpp"
#include "shared/simulation/method_instance.hpp"
#include "shared/simulation/point_embedding.hpp"
#include "shared/simulation/surface_lift.hpp"

namespace altfem {

struct EmbeddedSurface {
  SurfaceMesh surface;       ///< what the method deforms (the scene's common surface, else its own boundary)
  SurfaceMesh load_surface;  ///< what surface loads act on: the boundary of the domain integrated
  SurfaceLift lift;          ///< the curved faces load_surface stands for; empty when it is exact
  std::unique_ptr<ElementBasisEvaluator> evaluator;
  std::unique_ptr<PointEmbedding> embedding;  ///< of surface.vertices

  /// {"surface_vertices": n} and the embedding's facts.
  nlohmann::json facts() const {
    nlohmann::json facts = embedding->facts();
    facts["surface_vertices"] = surface.vertices.rows();
    return facts;
  }
};

/// A MethodInstance whose surface functions read its EmbeddedSurface.
class EmbeddedSurfaceMethod : public MethodInstance {
public:
  const SurfaceMesh& embedded_surface() const override { return surface_.surface; }
  const SurfaceMesh& load_surface() const override { return surface_.load_surface; }
  SurfaceLift surface_lift() const override { return surface_.lift; }
  const ElementBasisEvaluator& basis_evaluator() const override { return *surface_.evaluator; }
  Eigen::MatrixXd embedded_displacement(const Eigen::VectorXd& displacement) const override {
    return surface_.embedding->displacement(displacement);
  }

protected:
  EmbeddedSurface surface_;
};

}  // namespace altfem
