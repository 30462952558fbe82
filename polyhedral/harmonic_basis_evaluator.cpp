#include "polyhedral/harmonic_basis_evaluator.hpp"

#include <algorithm>
#include <limits>

#include "shared/common/error.hpp"
#include "shared/io/binary_cache.hpp"
#include "shared/mesh/polyhedral_cell_location.hpp"

namespace altfem::harmonic {

HarmonicBasisEvaluator::HarmonicBasisEvaluator(const PolyhedralMesh& mesh, const HarmonicElementBases& bases)
    : mesh_(mesh), bases_(bases), bounds_(static_cast<size_t>(bases.cell_count())) {
  for (int cell = 0; cell < bases.cell_count(); ++cell)
    for (int node : bases.nodes(cell)) bounds_[cell].extend(mesh.nodes.row(node).transpose());
}

bool HarmonicBasisEvaluator::evaluate(int cell, const Eigen::Vector3d& x, std::vector<int>& basis,
                                      std::vector<double>& values) const {
  Eigen::VectorXd cell_values;
  if (!bases_.evaluate(cell, x, cell_values)) return false;
  basis = bases_.nodes(cell);
  values.assign(cell_values.data(), cell_values.data() + cell_values.size());
  return true;
}

bool HarmonicBasisEvaluator::evaluate_inside(int cell, const Eigen::Vector3d& x, std::vector<int>& basis,
                                             std::vector<double>& values) const {
  const double tolerance = 1e-9 * mesh_.cell_diameters[cell];
  if (bounds_[cell].exteriorDistance(x) > tolerance) return false;
  if (!cell_holds(mesh_, cell, x, tolerance)) return false;
  return evaluate(cell, x, basis, values);
}

std::uint64_t HarmonicBasisEvaluator::element_key(int cell) const {
  CacheKeyHasher hasher;
  hasher.scalar<std::int32_t>(static_cast<std::int32_t>(mesh_.cell_kinds[cell]));
  hasher.scalar(mesh_.cell_diameters[cell]);
  if (convex_kind(mesh_.cell_kinds[cell])) {
    // Its face planes alone decide (cell_holds), in any order and whichever cell a face is
    // stored for: a cut renumbers the faces it left alone and may turn them. The
    // outward normal is the stored one negated exactly, and so is each plane distance.
    std::vector<std::uint64_t> planes;
    for (const int face : mesh_.cell_faces[cell]) {
      CacheKeyHasher plane;
      const double outward = mesh_.face_cells(face, 0) == cell ? 1.0 : -1.0;
      plane.matrix((outward * mesh_.face_normals.row(face)).eval());
      plane.matrix(mesh_.face_centroids.row(face).eval());
      planes.push_back(plane.value());
    }
    std::sort(planes.begin(), planes.end());
    hasher.bytes(planes.data(), planes.size() * sizeof(std::uint64_t));
  } else {
    for (const int face : mesh_.cell_faces[cell]) {
      hasher.scalar<std::int32_t>(mesh_.face_cells(face, 0) == cell);
      hasher.matrix(mesh_.face_centroids.row(face).eval());
      hasher.matrix(mesh_.face_normals.row(face).eval());
      for (const int node : mesh_.faces[face]) hasher.matrix(mesh_.nodes.row(node).eval());
    }
  }
  for (const int node : bases_.nodes(cell)) hasher.matrix(mesh_.nodes.row(node).eval());
  const std::optional<ElementType> plain = bases_.plain_type(cell);
  hasher.scalar<std::int32_t>(plain ? static_cast<std::int32_t>(*plain) : -1);
  if (const ElementHarmonicBasis* mfs = bases_.mfs_basis(cell)) hasher.scalar(mfs->content_key());
  return hasher.value();
}

double HarmonicBasisEvaluator::evaluate_nearest(const Eigen::Vector3d& x, std::vector<int>& basis,
                                                std::vector<double>& values) const {
  // The bounding-box distance bounds the boundary distance from below: only cells whose
  // box is nearer than the best so far are measured.
  std::vector<std::pair<double, int>> candidates;
  for (int cell = 0; cell < bases_.cell_count(); ++cell)
    candidates.emplace_back(bounds_[cell].exteriorDistance(x), cell);
  std::sort(candidates.begin(), candidates.end());
  // The nearest cell whose map can be inverted: a sliver next to the point cannot.
  std::vector<char> degenerate(candidates.size(), 0);
  for (;;) {
    double best = std::numeric_limits<double>::infinity();
    std::size_t nearest = candidates.size();
    for (std::size_t i = 0; i < candidates.size() && candidates[i].first < best; ++i) {
      if (degenerate[i]) continue;
      const double distance = distance_to_cell_boundary(mesh_, candidates[i].second, x);
      if (distance < best) best = distance, nearest = i;
    }
    if (nearest == candidates.size())
      throw NumericalError("harmonic embedding: no cell near a surface point has an invertible map");
    if (evaluate(candidates[nearest].second, x, basis, values)) return best;
    degenerate[nearest] = 1;
  }
}

}  // namespace altfem::harmonic
