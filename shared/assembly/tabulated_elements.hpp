#pragma once
// The meeting point of every discretization (docs/architecture.md, "Core abstractions"): for each
// element, the global indices of its basis functions, the quadrature weights already
// multiplied by |det J|, and the basis values and physical gradients at the quadrature
// points. Lagrange tets/hexes, FCM cut cells, DG monomials on polyhedra and harmonic
// bases all become this, and one assembler turns it into energy, forces, Hessians and
// mass matrices. The displacement is vector valued with the same scalar basis for each
// component: basis function a carries the DOFs 3a, 3a+1, 3a+2.
//
// Storage is packed for all elements (no per-element heap blocks), so assembly streams
// through memory.
#include <Eigen/Core>
#include <functional>
#include <span>
#include <vector>

namespace altfem {

/// A read-only view of one tabulated element.
struct ElementView {
  std::span<const int> basis;       ///< #basis global basis-function indices
  std::span<const double> weights;  ///< #points, w_q |det J(ξ_q)|
  /// #points × #basis, row q holds N_a(x_q)
  Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> values;
  /// point q's gradients ∇N_a(x_q) (#basis × 3, row-major) start at gradients + q·#basis·3
  const double* gradients;
  int material;

  int basis_count() const { return static_cast<int>(basis.size()); }
  int point_count() const { return static_cast<int>(weights.size()); }
  /// #basis × 3 physical gradients at point q.
  Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>> gradients_at(int q) const {
    return {gradients + static_cast<std::ptrdiff_t>(q) * basis_count() * 3, basis_count(), 3};
  }
};

/// Whether element e is tabulated on this rank; an empty function: every element.
using TabulatedHere = std::function<bool(int element)>;

class TabulatedElements {
public:
  /// Appends one element. values: #points × #basis; gradients: (#points·#basis) × 3,
  /// point-major (rows q·#basis .. q·#basis + #basis − 1 belong to point q).
  void add(std::span<const int> basis, std::span<const double> weights, const Eigen::Ref<const Eigen::MatrixXd>& values,
           const Eigen::Ref<const Eigen::MatrixXd>& gradients, int material = 0);
  /// Appends an element another rank tabulates (docs/scaling.md): its basis list, its
  /// material and how many points it has, none of them held here. Makes this a share.
  void add_held_elsewhere(std::span<const int> basis, int points, int material = 0);
  void reserve(int elements, long long basis_entries, long long point_entries, long long value_entries);

  int size() const { return static_cast<int>(material_.size()); }
  /// One more than the largest basis index used.
  int basis_count() const { return basis_count_; }
  /// The points held here: all of them unless keep_only() left this rank's share.
  long long point_count() const { return static_cast<long long>(weights_.size()); }
  /// Element e; an element another rank holds (keep_only) has its basis and material
  /// but no points.
  ElementView operator[](int element) const;

  /// One rank's share of a run over several processes (docs/scaling.md): frees the
  /// weights, values and gradients of every element whose `keep` entry (#elements) is
  /// zero, which keep their basis lists, materials and point counts. What is then summed
  /// over elements is this rank's part, and sum_over_ranks() makes it the whole.
  void keep_only(std::span<const char> keep);
  /// Whether keep_only() or add_held_elsewhere() made this a share (even one holding every
  /// element).
  bool is_share() const { return share_; }
  /// Whether element e's points are held here.
  bool holds(int element) const { return held_[element] != 0; }
  /// Element e's points in the whole tabulation, held here or not.
  int whole_point_count(int element) const {
    return static_cast<int>(whole_point_offsets_[element + 1] - whole_point_offsets_[element]);
  }
  /// Where element e's points start in the whole tabulation (e = size(): their count).
  long long whole_point_offset(int element) const { return whole_point_offsets_[element]; }
  long long whole_point_count() const { return whole_point_offsets_.back(); }
  /// Over a share, each entry (a sum over this rank's elements, or zero for elements it does
  /// not hold) replaced by its sum over the ranks; nothing for a whole tabulation.
  void sum_over_ranks(std::span<double> values) const;
  double sum_over_ranks(double value) const;
  /// Where element e's basis list starts in the packed lists of all elements.
  long long basis_offset(int element) const { return basis_offsets_[element]; }
  /// The largest #basis of any element (sizes the per-thread scratch).
  int max_element_basis() const { return max_element_basis_; }

private:
  std::vector<long long> basis_offsets_{0};  // #elements + 1
  std::vector<int> basis_;
  std::vector<long long> point_offsets_{0};  // #elements + 1
  std::vector<double> weights_;
  std::vector<long long> value_offsets_{0};  // #elements + 1; gradients start at 3× this
  std::vector<double> values_;
  std::vector<double> gradients_;
  std::vector<int> material_;
  // Which elements' points are held here, and where they start in the whole tabulation
  // (#elements + 1): point_offsets_ unless this is a share.
  bool share_ = false;
  std::vector<char> held_;
  std::vector<long long> whole_point_offsets_{0};
  int basis_count_ = 0;
  int max_element_basis_ = 0;
};

}  // namespace altfem
