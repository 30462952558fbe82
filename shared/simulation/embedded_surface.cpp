#include "shared/simulation/embedded_surface.hpp"

#include "shared/simulation/basis_embedding.hpp"

namespace altfem {

const PointEmbedding& EmbeddedSurface::embedding() const {
  if (!embedding_) embedding_ = make_embedding(*this);
  return *embedding_;
}

nlohmann::json EmbeddedSurface::facts() const {
  nlohmann::json facts = embedding().facts();
  facts["surface_vertices"] = surface.vertices.rows();
  return facts;
}

std::unique_ptr<PointEmbedding> EmbeddedSurface::embed_in_basis(const EmbeddedSurface& surface) {
  return std::make_unique<BasisEmbedding>(*surface.evaluator, embedding_points(surface.surface));
}

}  // namespace altfem
