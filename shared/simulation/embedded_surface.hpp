#pragma once
// The surfaces a method works with and how its field reaches them, as one value: the
// scene surface every method deforms (docs/conventions.md, "Metrics": methods are
// compared on the same vertices), the surface its loads act on and the curved faces that
// surface stands for, the method's basis at any point, and the embedding of the surface's
// vertices. EmbeddedSurfaceMethod implements MethodInstance's surface functions from it
// once for every method.
#include <functional>
#include <memory>
#include <optional>

#include "shared/mesh/surface_mesh.hpp"
#include "shared/simulation/method_instance.hpp"
#include "shared/simulation/point_embedding.hpp"
#include "shared/simulation/surface_lift.hpp"

namespace altfem {

struct EmbeddedSurface {
  SurfaceMesh surface;       ///< what the method deforms (the scene's common surface, else its own boundary)
  bool common = false;       ///< whether `surface` is the scene's common surface
  SurfaceMesh load_surface;  ///< what surface loads act on: the boundary of the domain integrated
  SurfaceLift lift;          ///< the curved faces load_surface stands for; empty when it is exact
  std::unique_ptr<ElementBasisEvaluator> evaluator;
  /// Embeds surface.vertices; by default each in the basis of the element holding it.
  /// Called by the first use of embedding(), so a run that writes no surface frames embeds
  /// nothing after a cut or a refinement (locating every vertex again, or dg's MLS weights,
  /// was most of a pencil cut's rebuild).
  std::function<std::unique_ptr<PointEmbedding>(const EmbeddedSurface&)> make_embedding = embed_in_basis;

  /// The embedding of surface.vertices, built on first use (from one thread: the run's).
  const PointEmbedding& embedding() const;
  /// {"surface_vertices": n, "surface_vertices_relocated": those located in the mesh (all,
  /// unless embed_in_basis kept some from the surface before an event)} and the
  /// embedding's facts.
  nlohmann::json facts() const;
  /// The seconds embedding() took to build; nullopt until it is built.
  std::optional<double> embedding_seconds() const { return embedding_seconds_; }
  /// Takes `before`'s embedding (the surface of the method before an event; if it never
  /// embedded, the one it had taken) for embed_in_basis to keep what the event left alone.
  void continue_from(const EmbeddedSurface& before);

  /// The embedding continue_from took (null: none, or already embedded): a method's own
  /// make_embedding may keep from it what the event left alone.
  const PointEmbedding* embedding_before() const { return before_.get(); }

  /// Each vertex in the basis of the element holding it; a vertex the embedding
  /// continue_from took holds in elements the event left alone keeps its weights
  /// (BasisEmbedding's constructor with `previous`).
  static std::unique_ptr<PointEmbedding> embed_in_basis(const EmbeddedSurface& surface);

private:
  mutable std::shared_ptr<const PointEmbedding> embedding_;
  mutable std::shared_ptr<const PointEmbedding> before_;  // continue_from's, released once embedded
  mutable std::optional<double> embedding_seconds_;
};

/// A MethodInstance whose surface functions read its EmbeddedSurface.
class EmbeddedSurfaceMethod : public MethodInstance {
public:
  const SurfaceMesh& embedded_surface() const override { return surface_.surface; }
  const SurfaceMesh& load_surface() const override { return surface_.load_surface; }
  SurfaceLift surface_lift() const override { return surface_.lift; }
  const ElementBasisEvaluator& basis_evaluator() const override { return *surface_.evaluator; }
  Eigen::MatrixXd embedded_displacement(const Eigen::VectorXd& displacement) const override {
    return surface_.embedding().displacement(displacement);
  }
  nlohmann::json surface_embedding_report() const override {
    if (!surface_.embedding_seconds()) return nullptr;
    return {{"seconds", *surface_.embedding_seconds()},
            {"vertices_relocated", surface_.facts()["surface_vertices_relocated"]}};
  }
  void continue_embedding(const MethodInstance& previous) override {
    if (const auto* before = dynamic_cast<const EmbeddedSurfaceMethod*>(&previous))
      surface_.continue_from(before->surface_);
  }
  void adopt_cut_surface(const SurfaceMesh& surface) override {
    if (surface_.common) surface_.surface = surface;
  }

protected:
  EmbeddedSurface surface_;
};

}  // namespace altfem
