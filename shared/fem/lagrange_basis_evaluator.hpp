#pragma once
#include <memory>

#include "shared/fem/lagrange_element_key.hpp"
#include "shared/mesh/node_constraints.hpp"
#include "shared/mesh/volume_mesh.hpp"
#include "shared/simulation/basis_embedding.hpp"

namespace altfem {

/// The basis of a Lagrange mesh (fem, and fcm's kept background cells) for
/// BasisEmbedding: a point is in a cell when the cell's inverse map (Newton) lands in
/// the reference element; a point in no cell is attached to the cell of the nearest
/// boundary point (CGAL AABB tree over the mesh's boundary faces, built on first need)
/// and extrapolated with that cell's inverse map. Basis function i is node i.
class LagrangeBasisEvaluator final : public ElementBasisEvaluator {
public:
  /// Keeps a reference to `mesh` and `constraints` (null: none).
  explicit LagrangeBasisEvaluator(const VolumeMesh& mesh, const NodeConstraints* constraints = nullptr);
  ~LagrangeBasisEvaluator() override;

  int element_count() const override { return static_cast<int>(mesh_.cells.rows()); }
  Eigen::AlignedBox3d element_bounds(int cell) const override;
  bool evaluate_inside(int cell, const Eigen::Vector3d& x, std::vector<int>& basis,
                       std::vector<double>& values) const override;
  double evaluate_nearest(const Eigen::Vector3d& x, std::vector<int>& basis,
                          std::vector<double>& values) const override;
  std::uint64_t element_key(int cell) const override { return lagrange_element_key(mesh_, constraints_, cell); }
  void element_functions(int cell, std::vector<int>& basis) const override {
    lagrange_element_functions(mesh_, constraints_, cell, basis);
  }

  /// Whether x lies in `cell`, and its reference point ξ there (the inverse map, Newton).
  bool reference_point(int cell, const Eigen::Vector3d& x, Eigen::Vector3d& xi) const;
  /// Basis indices and values of `cell` at reference point ξ.
  void evaluate(int cell, const Eigen::Vector3d& xi, std::vector<int>& basis, std::vector<double>& values) const;

private:
  class NearestBoundaryCell;

  const VolumeMesh& mesh_;
  const NodeConstraints* constraints_;
  mutable std::unique_ptr<NearestBoundaryCell> nearest_;
};

}  // namespace altfem
