#pragma once
// Material points embedded in any method's elements (docs/conventions.md,
// "Metrics"): every method deforms the same scene surface vertices, so the methods are
// compared point by point. A method supplies only "evaluate my basis at this physical
// point in this element" (ElementBasisEvaluator); locating points, the rule for points
// on element boundaries and the sparse product are shared.
#include <Eigen/Core>
#include <Eigen/Geometry>
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

  /// Displacement at every point (#points × 3) from the coefficients u (#dofs; basis
  /// function a carries DOFs 3a..3a+2).
  Eigen::MatrixXd displacement(const Eigen::VectorXd& u) const override;
  /// {"surface_vertices_outside_mesh", "max_outside_distance"}.
  nlohmann::json facts() const override {
    return {{"surface_vertices_outside_mesh", outside_count_}, {"max_outside_distance", max_outside_distance_}};
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

private:
  std::vector<long long> offsets_{0};  // #points + 1
  std::vector<int> basis_;
  std::vector<double> weights_;
  int outside_count_ = 0;
  double max_outside_distance_ = 0;
};

}  // namespace altfem
