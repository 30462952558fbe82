#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "shared/element/geometry_map.hpp"
#include "shared/fem/point_embedding.hpp"
#include "shared/mesh/boundary_surface.hpp"

namespace altfem {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangle = Kernel::Triangle_3;
using TriangleIterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, TriangleIterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

// Candidate cells of a point: a uniform grid of buckets over the cells' bounding
// boxes (finding the containing cell is a point-location query CGAL's AABB tree does
// not answer for curved cells; the grid is a few lines).
class CellGrid {
public:
  CellGrid(const VolumeMesh& mesh, int nodes_per_cell) {
    const Eigen::Index cells = mesh.cells.rows();
    boxes_.resize(cells);
    Eigen::AlignedBox3d all;
    double size = 0;
    for (Eigen::Index cell = 0; cell < cells; ++cell) {
      for (int a = 0; a < nodes_per_cell; ++a) boxes_[cell].extend(mesh.nodes.row(mesh.cells(cell, a)).transpose());
      all.extend(boxes_[cell]);
      size += boxes_[cell].diagonal().norm();
    }
    size = std::max(size / std::max<Eigen::Index>(cells, 1), 1e-300);
    origin_ = all.min();
    spacing_ = size;
    for (int d = 0; d < 3; ++d) counts_[d] = std::clamp(static_cast<int>(std::ceil(all.sizes()[d] / size)), 1, 256);
    buckets_.resize(static_cast<size_t>(counts_[0]) * counts_[1] * counts_[2]);
    for (Eigen::Index cell = 0; cell < cells; ++cell) {
      const Eigen::Vector3i low = bucket(boxes_[cell].min()), high = bucket(boxes_[cell].max());
      for (int k = low.z(); k <= high.z(); ++k)
        for (int j = low.y(); j <= high.y(); ++j)
          for (int i = low.x(); i <= high.x(); ++i) buckets_[index(i, j, k)].push_back(static_cast<int>(cell));
    }
  }
  const std::vector<int>& candidates(const Eigen::Vector3d& x) const {
    const Eigen::Vector3i b = bucket(x);
    return buckets_[index(b.x(), b.y(), b.z())];
  }
  bool in_box(int cell, const Eigen::Vector3d& x, double slack) const {
    return (x.array() >= boxes_[cell].min().array() - slack).all() && (x.array() <= boxes_[cell].max().array() + slack).all();
  }

private:
  Eigen::Vector3i bucket(const Eigen::Vector3d& x) const {
    Eigen::Vector3i b;
    for (int d = 0; d < 3; ++d) b[d] = std::clamp(static_cast<int>(std::floor((x[d] - origin_[d]) / spacing_)), 0, counts_[d] - 1);
    return b;
  }
  size_t index(int i, int j, int k) const { return static_cast<size_t>(i) + counts_[0] * (j + static_cast<size_t>(counts_[1]) * k); }

  std::vector<Eigen::AlignedBox3d> boxes_;
  std::vector<std::vector<int>> buckets_;
  Eigen::Vector3d origin_;
  double spacing_ = 1;
  std::array<int, 3> counts_{1, 1, 1};
};

}  // namespace

PointEmbedding::PointEmbedding(const VolumeMesh& mesh, const Eigen::MatrixXd& points) {
  const ReferenceElement& element = reference_element(mesh.element_type);
  nodes_per_cell_ = element.node_count();
  const Eigen::Index count = points.rows();
  nodes_.assign(static_cast<size_t>(count) * nodes_per_cell_, 0);
  weights_.assign(static_cast<size_t>(count) * nodes_per_cell_, 0.0);
  const CellGrid grid(mesh, nodes_per_cell_);

  Eigen::MatrixXd cell_nodes(nodes_per_cell_, 3);
  Eigen::VectorXd values(nodes_per_cell_);
  const auto attach = [&](Eigen::Index point, int cell, const Eigen::Vector3d& xi) {
    element.evaluate(xi, values);
    for (int a = 0; a < nodes_per_cell_; ++a) {
      nodes_[point * nodes_per_cell_ + a] = mesh.cells(cell, a);
      weights_[point * nodes_per_cell_ + a] = values[a];
    }
  };
  const auto load = [&](int cell) {
    for (int a = 0; a < nodes_per_cell_; ++a) cell_nodes.row(a) = mesh.nodes.row(mesh.cells(cell, a));
  };

  std::vector<Eigen::Index> outside;
  const double slack = 1e-9 * (points.colwise().maxCoeff() - points.colwise().minCoeff()).norm();
  for (Eigen::Index point = 0; point < count; ++point) {
    const Eigen::Vector3d x = points.row(point).transpose();
    bool found = false;
    for (int cell : grid.candidates(x)) {
      if (!grid.in_box(cell, x, slack)) continue;
      load(cell);
      const InverseMapResult result = map_to_reference(element, cell_nodes, x, 1e-10);
      if (result.inside) {
        attach(point, cell, result.xi);
        found = true;
        break;
      }
    }
    if (!found) outside.push_back(point);
  }
  outside_count_ = static_cast<int>(outside.size());
  if (outside.empty()) return;

  const BoundarySurface boundary = boundary_surface(mesh);
  std::vector<Triangle> triangles;
  for (Eigen::Index t = 0; t < boundary.surface.triangles.rows(); ++t) {
    const auto vertex = [&](int c) {
      const auto row = boundary.surface.vertices.row(boundary.surface.triangles(t, c));
      return Kernel::Point_3(row(0), row(1), row(2));
    };
    triangles.emplace_back(vertex(0), vertex(1), vertex(2));
  }
  const Tree tree(triangles.cbegin(), triangles.cend());
  for (Eigen::Index point : outside) {
    const Kernel::Point_3 query(points(point, 0), points(point, 1), points(point, 2));
    const auto [closest, primitive] = tree.closest_point_and_primitive(query);
    max_outside_distance_ = std::max(max_outside_distance_, std::sqrt(CGAL::squared_distance(query, closest)));
    const int cell = boundary.cells[static_cast<size_t>(primitive - triangles.cbegin())];
    load(cell);
    const InverseMapResult result = map_to_reference(element, cell_nodes, points.row(point).transpose(), 1e-10);
    attach(point, cell, result.xi);
  }
}

Eigen::MatrixXd PointEmbedding::displacement(const Eigen::VectorXd& u) const {
  const Eigen::Index count = static_cast<Eigen::Index>(nodes_.size() / std::max(nodes_per_cell_, 1));
  Eigen::MatrixXd result = Eigen::MatrixXd::Zero(count, 3);
  for (Eigen::Index point = 0; point < count; ++point)
    for (int a = 0; a < nodes_per_cell_; ++a) {
      const size_t entry = static_cast<size_t>(point) * nodes_per_cell_ + a;
      result.row(point) += weights_[entry] * u.segment<3>(3 * nodes_[entry]).transpose();
    }
  return result;
}

}  // namespace altfem
