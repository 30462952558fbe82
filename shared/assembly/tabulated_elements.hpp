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

#include "shared/common/uninitialized_allocator.hpp"

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

/// One element's place in a tabulation laid out before it is filled (TabulatedElements::lay_out).
struct ElementLayout {
  std::span<const int> basis;  ///< #basis global basis-function indices (copied)
  int points = 0;
  int material = 0;
  bool held = true;  ///< false: another rank tabulates it (as add_held_elsewhere)
  /// An element laid out before it in the same call whose weights, values and gradients
  /// are this one's too (held, with as many points and basis functions): one copy for
  /// the many equal cells of a grid. −1: its own.
  int same_points_as = -1;
};

/// The storage of one laid-out element, shaped as ElementView, for its tabulator to fill.
struct ElementSlots {
  std::span<double> weights;                                                                  ///< #points
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> values;  ///< #points × #basis
  /// (#points·#basis) × 3, point-major: rows q·#basis .. q·#basis + #basis − 1 belong to point q
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>> gradients;
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
  /// Appends `elements` elements at once, element e as layout(e) says, with room for their
  /// weights, values and gradients left unwritten: the tabulator fills the slots() of each
  /// held element that does not share another's points once, from any thread. Unlike
  /// add(), nothing is copied or zeroed first, and the memory is first touched by the
  /// threads that fill it. Throws std::invalid_argument for a negative point count or a
  /// `same_points_as` that is not an earlier held element of the same sizes.
  void lay_out(int elements, const std::function<ElementLayout(int)>& layout);
  /// Where a laid-out held element's weights, values and gradients go.
  ElementSlots slots(int element);

  int size() const { return static_cast<int>(material_.size()); }
  /// One more than the largest basis index used.
  int basis_count() const { return basis_count_; }
  /// The points of the elements held here (all of them unless keep_only() left this
  /// rank's share), counted per element however many share their storage.
  long long point_count() const { return held_points_; }
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
  long long points_of(int element) const;
  void append(std::span<const int> basis, long long points, int material, bool held, long long point_begin,
              long long value_begin);

  std::vector<long long> basis_offsets_{0};  // #elements + 1
  std::vector<int> basis_;
  // #elements: where a held element's weights start in weights_, and its values in values_
  // (its gradients at 3× that); elements that share their points share these.
  std::vector<long long> point_begin_, value_begin_;
  using Doubles = std::vector<double, UninitializedAllocator<double>>;
  Doubles weights_;
  Doubles values_;
  Doubles gradients_;
  std::vector<int> material_;
  // Which elements' points are held here, and where they start in the whole tabulation
  // (#elements + 1), which also gives every element's point count.
  bool share_ = false;
  std::vector<char> held_;
  std::vector<long long> whole_point_offsets_{0};
  long long held_points_ = 0;
  int basis_count_ = 0;
  int max_element_basis_ = 0;
};

}  // namespace altfem
