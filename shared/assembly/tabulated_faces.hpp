#pragma once
// Face quadrature for terms that couple two elements across a face (DG fluxes,
// Kaufmann et al. 2009 eqs. (19)-(21); FCM ghost penalties, Burman 2010) or act on a
// boundary face (weakly imposed conditions). Per face: the union of both neighbours'
// basis functions and, per quadrature point, the weight, the unit normal, and the
// traces of every basis function's value and gradient (and, if the faces carry them,
// Hessian: second-order derivative jumps of a ghost penalty) seen from each side. A function
// that lives on one side only has zero trace on the other (DG); a function shared by
// both sides (a conforming basis) has both traces.
//
// Jumps and averages follow from the traces: [[φ_a]] = φ_a⁻ − φ_a⁺ and
// {∇φ_a} = ½(∇φ_a⁻ + ∇φ_a⁺), with the normal pointing from the minus to the plus side.
// Storage is packed for all faces, like TabulatedElements.
#include <Eigen/Core>
#include <functional>
#include <span>
#include <vector>

#include "shared/assembly/basis_groups.hpp"
#include "shared/assembly/tabulated_elements.hpp"

namespace altfem {

/// A read-only view of one tabulated face.
struct FaceView {
  using Values = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>;
  using Gradients = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>;
  using Hessians = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor>>;

  std::span<const int> basis;       ///< #basis global indices (both neighbours' functions)
  std::span<const double> weights;  ///< #points, w_q × the face's area element
  const double* normals;            ///< #points × 3 (row-major), unit, minus → plus side
  Values values_minus;              ///< #points × #basis: φ_a(x_q) from the minus side
  Values values_plus;               ///< #points × #basis: φ_a(x_q) from the plus side (0 on a boundary face)
  const double* gradients_minus;    ///< point q's ∇φ_a (#basis × 3) start at + q·#basis·3
  const double* gradients_plus;
  /// Point q's Hessians (#basis × 9, each row ∂²φ_a/∂x_j∂x_k at column 3j + k) start at
  /// + q·#basis·9; nullptr when the faces were tabulated without them.
  const double* hessians_minus;
  const double* hessians_plus;
  int index;  ///< the face's position in its TabulatedFaces (per-face data of a kernel)
  int minus;  ///< the element on the minus side
  int plus;   ///< the element on the plus side; -1 on a boundary face

  int basis_count() const { return static_cast<int>(basis.size()); }
  int point_count() const { return static_cast<int>(weights.size()); }
  bool is_boundary() const { return plus < 0; }
  Eigen::Map<const Eigen::Vector3d> normal(int q) const { return Eigen::Map<const Eigen::Vector3d>(normals + 3 * q); }
  /// #basis × 3 gradients at point q from each side.
  Gradients gradients_minus_at(int q) const { return {gradients_minus + q * basis_count() * 3, basis_count(), 3}; }
  Gradients gradients_plus_at(int q) const { return {gradients_plus + q * basis_count() * 3, basis_count(), 3}; }
  bool has_hessians() const { return hessians_minus != nullptr; }
  /// #basis × 9 Hessians at point q from each side (only if has_hessians()).
  Hessians hessians_minus_at(int q) const { return {hessians_minus + q * basis_count() * 9, basis_count(), 9}; }
  Hessians hessians_plus_at(int q) const { return {hessians_plus + q * basis_count() * 9, basis_count(), 9}; }
};

class TabulatedFaces {
public:
  /// Appends one face. normals: #points × 3; values_*: #points × #basis;
  /// gradients_*: (#points·#basis) × 3, point-major; hessians_*: (#points·#basis) × 9,
  /// point-major, or empty (0 rows) for none — all faces with them or all without.
  /// Throws std::invalid_argument on mismatched sizes or a normal that is not of unit length.
  void add(std::span<const int> basis, std::span<const double> weights,
           const Eigen::Ref<const Eigen::MatrixXd>& normals, const Eigen::Ref<const Eigen::MatrixXd>& values_minus,
           const Eigen::Ref<const Eigen::MatrixXd>& values_plus,
           const Eigen::Ref<const Eigen::MatrixXd>& gradients_minus,
           const Eigen::Ref<const Eigen::MatrixXd>& gradients_plus, int minus, int plus,
           const Eigen::Ref<const Eigen::MatrixXd>& hessians_minus = Eigen::MatrixXd(0, 9),
           const Eigen::Ref<const Eigen::MatrixXd>& hessians_plus = Eigen::MatrixXd(0, 9));

  /// Appends a face that another rank tabulates (docs/scaling.md): its basis list and its
  /// sides only, no points, so that every rank knows every face's couplings.
  void add_held_elsewhere(std::span<const int> basis, int minus, int plus);

  int size() const { return static_cast<int>(minus_.size()); }
  long long point_count() const { return static_cast<long long>(weights_.size()); }
  int max_face_basis() const { return max_face_basis_; }
  /// Whether the tabulated faces carry Hessians (false when none is tabulated).
  bool has_hessians() const { return !hessians_minus_.empty(); }
  FaceView operator[](int face) const;
  /// Each face's basis list: the block couplings these faces add to a sparsity pattern.
  const BasisGroups& basis_groups() const { return basis_; }

private:
  BasisGroups basis_;
  std::vector<long long> point_offsets_{0};  // #faces + 1
  std::vector<double> weights_;
  std::vector<double> normals_;
  std::vector<long long> value_offsets_{0};  // #faces + 1; gradients start at 3× this
  std::vector<double> values_minus_, values_plus_;
  std::vector<double> gradients_minus_, gradients_plus_;
  std::vector<double> hessians_minus_, hessians_plus_;  // empty, or 9× the values
  std::vector<int> minus_, plus_;
  int max_face_basis_ = 0;
};

/// Tabulates the faces f with here(f) and lists the others (TabulatedFaces::
/// add_held_elsewhere); every face when `here` is empty. The faces and their order are the
/// same whatever `here` says.
using FaceTabulator = std::function<TabulatedFaces(const TabulatedHere& here)>;

}  // namespace altfem
