#include "shared/simulation/embedded_surface.hpp"

#include <chrono>

#include "shared/simulation/basis_embedding.hpp"

namespace altfem {

const PointEmbedding& EmbeddedSurface::embedding() const {
  if (!embedding_) {
    const auto start = std::chrono::steady_clock::now();
    embedding_ = make_embedding(*this);
    embedding_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    before_.reset();
  }
  return *embedding_;
}

nlohmann::json EmbeddedSurface::facts() const {
  nlohmann::json facts = embedding().facts();
  facts["surface_vertices"] = surface.vertices.rows();
  if (!facts.contains("surface_vertices_relocated")) facts["surface_vertices_relocated"] = surface.vertices.rows();
  return facts;
}

void EmbeddedSurface::continue_from(const EmbeddedSurface& before) {
  if (!before.embedding_) {
    before_ = before.before_;  // keyed when `before` took it
    return;
  }
  before_ = before.embedding_;
  // Keyed now, while the elements it was built on are alive.
  if (const auto* embedding = dynamic_cast<const BasisEmbedding*>(before_.get()))
    embedding->remember_keys(*before.evaluator);
}

std::unique_ptr<PointEmbedding> EmbeddedSurface::embed_in_basis(const EmbeddedSurface& surface) {
  return std::make_unique<BasisEmbedding>(*surface.evaluator, embedding_points(surface.surface),
                                          dynamic_cast<const BasisEmbedding*>(surface.before_.get()));
}

}  // namespace altfem
