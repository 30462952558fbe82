#pragma once
// Which elements may contain a point: a uniform grid of buckets over the elements'
// axis-aligned bounding boxes. Point location in curved Lagrange cells, polyhedra or
// cut cells is a question only each method's basis can answer exactly (the inverse
// map, a polyhedron's faces); this narrows it to a few candidates. CGAL's AABB tree
// answers box queries too, but costs a CGAL translation unit for a few lines.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <vector>

namespace altfem {

class PointLocator {
public:
  /// boxes: one per element. Buckets are about the mean box diagonal wide (at most
  /// 256 per axis).
  explicit PointLocator(std::vector<Eigen::AlignedBox3d> boxes);

  /// Elements whose box, enlarged by `slack` on every side, contains x (in element
  /// order) into `elements` (cleared first).
  void candidates(const Eigen::Vector3d& x, double slack, std::vector<int>& elements) const;
  const Eigen::AlignedBox3d& box(int element) const { return boxes_[element]; }
  int size() const { return static_cast<int>(boxes_.size()); }

private:
  Eigen::Vector3i bucket(const Eigen::Vector3d& x) const;
  size_t index(const Eigen::Vector3i& bucket) const;

  std::vector<Eigen::AlignedBox3d> boxes_;
  std::vector<std::vector<int>> buckets_;
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  double spacing_ = 1;
  std::array<int, 3> counts_{1, 1, 1};
};

}  // namespace altfem
