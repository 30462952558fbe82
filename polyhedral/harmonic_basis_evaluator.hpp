#pragma once
#include "polyhedral/harmonic_element_bases.hpp"
#include "shared/simulation/basis_embedding.hpp"

namespace altfem::harmonic {

/// The harmonic method's basis for BasisEmbedding. A point is in a cell when the
/// cell's winding number about it exceeds 1/2 or it lies within 1e-9 × the cell's
/// diameter of the cell's boundary (points on faces, edges and corners, where the
/// winding number is a fraction); a point in no cell is extrapolated from the cell whose
/// boundary is nearest. Basis function i is mesh node i. Keeps references to both.
class HarmonicBasisEvaluator final : public ElementBasisEvaluator {
public:
  HarmonicBasisEvaluator(const PolyhedralMesh& mesh, const HarmonicElementBases& bases);

  int element_count() const override { return bases_.cell_count(); }
  Eigen::AlignedBox3d element_bounds(int cell) const override { return bounds_[cell]; }
  bool evaluate_inside(int cell, const Eigen::Vector3d& x, std::vector<int>& basis,
                       std::vector<double>& values) const override;
  double evaluate_nearest(const Eigen::Vector3d& x, std::vector<int>& basis,
                          std::vector<double>& values) const override;
  /// The cell's faces as cell_holds reads them (a convex cell's outward planes, in any
  /// order), its nodes' positions in the order of its values, and its basis (closed-form
  /// type, or every MFS datum).
  std::uint64_t element_key(int cell) const override;
  void element_functions(int cell, std::vector<int>& basis) const override { basis = bases_.nodes(cell); }

private:
  bool evaluate(int cell, const Eigen::Vector3d& x, std::vector<int>& basis, std::vector<double>& values) const;

  const PolyhedralMesh& mesh_;
  const HarmonicElementBases& bases_;
  std::vector<Eigen::AlignedBox3d> bounds_;
};

}  // namespace altfem::harmonic
