#pragma once
// The DG basis as the shared embedding asks for it (shared/simulation/basis_embedding):
// each polyhedral element's own monomials. A point on a face shared by several elements
// gets the mean of their values — the stitching of Kaufmann et al. 2009 §7, eq. (30).
#include <vector>

#include "dg/dg_linear_system.hpp"
#include "shared/mesh/polyhedral_mesh.hpp"
#include "shared/simulation/basis_embedding.hpp"

namespace altfem::dg {

/// Point location: x lies in a cell when it is behind every face plane, up to 1e-9 × the
/// cell's diameter, or, for cells that may be non-convex (cut, merged and coarse cells
/// of a sliced mesh), when the cell's winding number about x exceeds 1/2 or x lies that
/// close to its boundary. Both references must outlive the evaluator.
class MonomialBasisEvaluator final : public ElementBasisEvaluator {
public:
  MonomialBasisEvaluator(const PolyhedralMesh& mesh, const DgLinearSystem& system);

  int element_count() const override { return mesh_.cell_count(); }
  Eigen::AlignedBox3d element_bounds(int element) const override { return bounds_[element]; }
  bool evaluate_inside(int element, const Eigen::Vector3d& x, std::vector<int>& basis,
                       std::vector<double>& values) const override;
  /// The cell whose boundary is nearest (its bounding box's distance prunes).
  double evaluate_nearest(const Eigen::Vector3d& x, std::vector<int>& basis,
                          std::vector<double>& values) const override;
  BoundaryPointRule boundary_rule() const override { return BoundaryPointRule::average; }

private:
  void fill(int element, const Eigen::Vector3d& x, std::vector<int>& basis, std::vector<double>& values) const;

  const PolyhedralMesh& mesh_;
  const DgLinearSystem& system_;
  std::vector<Eigen::AlignedBox3d> bounds_;  // #cells
};

}  // namespace altfem::dg
