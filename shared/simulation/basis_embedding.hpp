#pragma once
// Material points embedded in any method's elements (docs/conventions.md,
// "Metrics"): every method deforms the same scene surface vertices, so the methods are
// compared point by point. A method supplies only "evaluate my basis at this physical
// point in this element" (ElementBasisEvaluator); locating points, the rule for points
// on element boundaries and the sparse product are shared.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "shared/simulation/point_embedding.hpp"

namespace altfem {

/// How a point that lies in several elements (on a shared face, within tolerance) is
/// evaluated. A conforming basis gives the same value from each side; a discontinuous
/// one (DG) does not, and its method chooses.
enum class BoundaryPointRule {
  first_element,  ///< the element of lowest index that contains the point
  average,        ///< the mean of every containing element's evaluation (stitching)
};

/// The basis of one method's elements, as the embedding asks for it. Implementations
/// may cache; BasisEmbedding calls them from one thread.
class ElementBasisEvaluator {
public:
  virtual ~ElementBasisEvaluator() = default;
  virtual int element_count() const = 0;
  virtual Eigen::AlignedBox3d element_bounds(int element) const = 0;
  /// If x lies in `element` (up to a relative tolerance of the method's choosing):
  /// true, with the global indices of the element's basis functions and their values
  /// at x in `basis` / `values` (resized). False otherwise.
  virtual bool evaluate_inside(int element, const Eigen::Vector3d& x, std::vector<int>& basis,
                               std::vector<double>& values) const = 0;
  /// For a point inside no element: the basis of the element it is extrapolated from
  /// (the nearest, by the method's measure) at x, and the distance from x to it.
  virtual double evaluate_nearest(const Eigen::Vector3d& x, std::vector<int>& basis,
                                  std::vector<double>& values) const = 0;
  virtual BoundaryPointRule boundary_rule() const { return BoundaryPointRule::first_element; }
  /// A 64-bit key of what evaluate_inside(element, ·) reads of the element, whatever the
  /// numbering of the elements and of the basis functions; 0 where the evaluator cannot
  /// tell (never taken as equal). Two elements of one key, of this evaluator or of
  /// another's mesh, hold the same points with the same values, of the functions
  /// element_functions lists at the same places, where holds_alone says so. What lets the
  /// embedding after an event keep the points of the elements the event left alone
  /// (BasisEmbedding's constructor with `previous`).
  virtual std::uint64_t element_key(int /*element*/) const { return 0; }
  /// The basis functions evaluate_inside lists for `element`, in its order (any point).
  virtual void element_functions(int /*element*/, std::vector<int>& basis) const { basis.clear(); }
  /// For x that `element` holds (evaluate_inside): whether it holds it whatever the other
  /// elements are, and whether an element before it (in index order) of the key one had
  /// before an event rejects x as it did, given that this one holds it. True unless
  /// elements overlap and share out the points among themselves (fcm's pieces of one
  /// background cell: the nearest holds a point).
  virtual bool holds_alone(int /*element*/, const Eigen::Vector3d& /*x*/) const { return true; }
  /// For x that `holder` holds alone (holds_alone): whether `element`, before it among the
  /// candidates, rejects x (evaluate_inside false). An evaluator whose elements share out
  /// the points among themselves may tell it without the whole evaluation.
  virtual bool rejects(int element, int /*holder*/, const Eigen::Vector3d& x) const {
    thread_local std::vector<int> basis;
    thread_local std::vector<double> values;
    return !evaluate_inside(element, x, basis, values);
  }
};

class BasisEmbedding final : public PointEmbedding {
public:
  /// points: #points × 3. Points outside every element are extrapolated from the
  /// nearest one (Mesh_3's surface only approximates the input); none is dropped.
  /// `point_elements` (optional, #points lists): the elements a point is evaluated in
  /// instead of every element containing its position — for mesh nodes, the elements
  /// holding the node, so that the copies a cut made of a node (one position, two sides)
  /// each take their own side.
  BasisEmbedding(const ElementBasisEvaluator& basis, const Eigen::MatrixXd& points,
                 const std::vector<std::vector<int>>& point_elements = {});
  /// The embedding of `points` after an event, from `previous`, the embedding of the points
  /// before it (built by this constructor; null: none): a point at the same index and
  /// position keeps its weights, on the functions its holder now lists, where its holder
  /// there is a candidate here (an element of its key; candidates: the elements whose box
  /// holds it, in index order), holds it alone (holds_alone), and every candidate before
  /// it either had the key of one that came before the holder there or rejects the point
  /// (ElementBasisEvaluator::rejects: a piece the event cut or added); with
  /// BoundaryPointRule::average, where every candidate has the key it had there. Every
  /// other point is located anew. The result is what the first constructor gives,
  /// bit for bit, and remembers what the embedding after the next event needs. A cut
  /// appends the surface's new vertices, so the vertices of the elements it left alone
  /// keep their index.
  BasisEmbedding(const ElementBasisEvaluator& basis, const Eigen::MatrixXd& points, const BasisEmbedding* previous);

  /// Displacement at every point (#points × 3) from the coefficients u (#dofs; basis
  /// function a carries DOFs 3a..3a+2).
  Eigen::MatrixXd displacement(const Eigen::VectorXd& u) const override;
  /// {"surface_vertices_outside_mesh", "max_outside_distance", "surface_vertices_relocated"}.
  nlohmann::json facts() const override {
    return {{"surface_vertices_outside_mesh", outside_count_},
            {"max_outside_distance", max_outside_distance_},
            {"surface_vertices_relocated", relocated_count_}};
  }
  /// The load vector (#dofs) of forces at the points (#points × 3 [N]), the transpose of
  /// displacement(): f_(3a+i) = Σ_p φ_a(x_p) F_(p,i).
  Eigen::VectorXd load(const Eigen::MatrixXd& forces, int dof_count) const;
  int outside_count() const { return outside_count_; }
  /// The basis functions that point `point`'s displacement combines (those of every
  /// element containing it, or of the nearest one).
  std::span<const int> basis_of(Eigen::Index point) const {
    return {basis_.data() + offsets_[point], static_cast<size_t>(offsets_[point + 1] - offsets_[point])};
  }
  /// The largest distance from an outside point to its element (0 if none).
  double max_outside_distance() const { return max_outside_distance_; }
  /// The points located in the mesh (all but those kept from `previous`).
  int relocated_count() const { return relocated_count_; }
  /// Keys the elements the points' candidates were (ElementBasisEvaluator::element_key),
  /// for the embedding after an event to compare with: called once, with the evaluator
  /// this embedding was built on, before the event replaces it. A run without events
  /// computes no key.
  void remember_keys(const ElementBasisEvaluator& evaluator) const;

private:
  // What the embedding after the next event reads to keep a point (the constructor with
  // `previous`): the points, and per point its candidate elements (their keys once
  // remember_keys ran) and the places among them of the elements its entries came from
  // (none: extrapolated).
  struct Memory {
    Eigen::MatrixXd points;
    std::vector<long long> candidate_offsets{0}, holder_offsets{0};
    std::vector<int> candidates, holders;
    std::vector<std::uint64_t> candidate_keys;  // empty until remember_keys
  };

  /// Appends the entries of x found in `candidates` (in order, or the nearest element's
  /// when none holds it) and the places of the candidates that held it to `holders`.
  void locate(const ElementBasisEvaluator& evaluator, const Eigen::Vector3d& x, const std::vector<int>& candidates,
              std::vector<int>& holders);
  /// Appends the entries of x in the nearest element (extrapolated), counted as outside;
  /// `basis` and `values` are scratch.
  void append_nearest(const ElementBasisEvaluator& evaluator, const Eigen::Vector3d& x, std::vector<int>& basis,
                      std::vector<double>& values);
  /// Appends the entries `previous` holds for `point` on the functions of its holders,
  /// found among `candidates` by their keys as the constructor says (`keys`: the
  /// evaluator's, per element, computed on first need), and sets `holders` to their places;
  /// false, appending nothing, else.
  bool keep(const ElementBasisEvaluator& evaluator, const BasisEmbedding& previous, Eigen::Index point,
            const Eigen::Vector3d& x, const std::vector<int>& candidates, std::vector<std::uint64_t>& keys,
            std::vector<char>& known, std::vector<int>& holders);
  /// Sets `holders` to the places in `candidates` of `point`'s holders in `previous`; false,
  /// leaving it alone, where the rules of keep do not find them. `key_of` gives an
  /// element's key.
  template <typename KeyOf>
  bool kept_holders(const ElementBasisEvaluator& evaluator, const BasisEmbedding& previous, Eigen::Index point,
                    const Eigen::Vector3d& x, const std::vector<int>& candidates, const KeyOf& key_of,
                    std::vector<int>& holders) const;

  std::vector<long long> offsets_{0};  // #points + 1
  std::vector<int> basis_;
  std::vector<double> weights_;
  int outside_count_ = 0;
  double max_outside_distance_ = 0;
  int relocated_count_ = 0;
  mutable std::unique_ptr<Memory> memory_;  // only from the constructor with `previous`
};

}  // namespace altfem
