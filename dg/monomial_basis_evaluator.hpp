#pragma once
// The DG basis as the shared embedding asks for it (shared/simulation/basis_embedding):
// each polyhedral element's own monomials. A point on a face shared by several elements
// gets the mean of their values — the stitching of Kaufmann et al. 2009 §7, eq. (30).
#include <vector>

#include "dg/dg_linear_system.hpp"
#include "shared/mesh/polyhedral_mesh.hpp"
#include "shared/simulation/basis_embedding.hpp"

namespace altfem::dg {

/// Point location assumes convex cells (those of converted tetrahedral and hexahedral
/// meshes): x lies in a cell when it is behind every face plane, up to 1e-9 × the
/// cell's diameter. Both references must outlive the evaluator.
class MonomialBasisEvaluator final : public ElementBasisEvaluator {
public:
  MonomialBasisEvaluator(const PolyhedralMesh& mesh, const DgLinearSystem& system);

  int element_count() const override { return mesh_.cell_count(); }
  Eigen::AlignedBox3d element_bounds(int element) const override { return bounds_[element]; }
  bool evaluate_inside(int element, const Eigen::Vector3d& x, std::vector<int>& basis,
                       std::vector<double>& values) const override;
  /// The nearest cell by the larger of two lower bounds of the distance to a convex cell:
  /// to its bounding box and in front of its face planes (exact when the nearest point
  /// is inside a face).
  double evaluate_nearest(const Eigen::Vector3d& x, std::vector<int>& basis, std::vector<double>& values) const override;
  BoundaryPointRule boundary_rule() const override { return BoundaryPointRule::average; }

private:
  // max over the cell's faces of (x − face centroid)·(outward normal): ≤ 0 inside.
  double plane_distance(int element, const Eigen::Vector3d& x) const;
  void fill(int element, const Eigen::Vector3d& x, std::vector<int>& basis, std::vector<double>& values) const;

  const PolyhedralMesh& mesh_;
  const DgLinearSystem& system_;
  std::vector<Eigen::AlignedBox3d> bounds_;  // #cells
};

}  // namespace altfem::dg
