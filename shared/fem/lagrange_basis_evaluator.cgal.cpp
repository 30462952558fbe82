#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>

#include "shared/element/geometry_map.hpp"
#include "shared/fem/lagrange_basis_evaluator.hpp"
#include "shared/mesh/boundary_surface.hpp"

namespace altfem {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangle = Kernel::Triangle_3;
using TriangleIterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, TriangleIterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Eigen::MatrixXd cell_nodes(const VolumeMesh& mesh, int cell) {
  Eigen::MatrixXd nodes(mesh.cells.cols(), 3);
  for (Eigen::Index a = 0; a < mesh.cells.cols(); ++a) nodes.row(a) = mesh.nodes.row(mesh.cells(cell, a));
  return nodes;
}

}  // namespace

// The mesh's boundary triangles in an AABB tree, each knowing its cell.
class LagrangeBasisEvaluator::NearestBoundaryCell {
public:
  explicit NearestBoundaryCell(const VolumeMesh& mesh) : boundary_(boundary_surface(mesh)) {
    const SurfaceMesh& surface = boundary_.surface;
    triangles_.reserve(static_cast<size_t>(surface.triangles.rows()));
    for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t) {
      const auto vertex = [&](int c) {
        const auto row = surface.vertices.row(surface.triangles(t, c));
        return Kernel::Point_3(row(0), row(1), row(2));
      };
      triangles_.emplace_back(vertex(0), vertex(1), vertex(2));
    }
    tree_ = std::make_unique<Tree>(triangles_.cbegin(), triangles_.cend());
  }
  /// The cell of the boundary point nearest to x, and the distance to it.
  std::pair<int, double> find(const Eigen::Vector3d& x) const {
    const Kernel::Point_3 query(x.x(), x.y(), x.z());
    const auto [closest, primitive] = tree_->closest_point_and_primitive(query);
    return {boundary_.cells[static_cast<size_t>(primitive - triangles_.cbegin())],
            std::sqrt(CGAL::squared_distance(query, closest))};
  }

private:
  BoundarySurface boundary_;
  std::vector<Triangle> triangles_;
  std::unique_ptr<Tree> tree_;
};

LagrangeBasisEvaluator::LagrangeBasisEvaluator(const VolumeMesh& mesh, const NodeConstraints* constraints)
    : mesh_(mesh), constraints_(constraints) {}
LagrangeBasisEvaluator::~LagrangeBasisEvaluator() = default;

Eigen::AlignedBox3d LagrangeBasisEvaluator::element_bounds(int cell) const {
  Eigen::AlignedBox3d box;
  for (Eigen::Index a = 0; a < mesh_.cells.cols(); ++a) box.extend(mesh_.nodes.row(mesh_.cells(cell, a)).transpose());
  return box;
}

void LagrangeBasisEvaluator::evaluate(int cell, const Eigen::Vector3d& xi, std::vector<int>& basis,
                                      std::vector<double>& values) const {
  const ReferenceElement& element = reference_element(mesh_.element_type);
  Eigen::VectorXd shape(element.node_count());
  element.evaluate(xi, shape);
  basis.resize(static_cast<size_t>(element.node_count()));
  values.resize(basis.size());
  for (int a = 0; a < element.node_count(); ++a) {
    basis[a] = mesh_.cells(cell, a);
    values[a] = shape[a];
  }
  if (constraints_) constraints_->substitute(basis, values);
}

bool LagrangeBasisEvaluator::reference_point(int cell, const Eigen::Vector3d& x, Eigen::Vector3d& xi) const {
  const InverseMapResult result =
      map_to_reference(reference_element(mesh_.element_type), cell_nodes(mesh_, cell), x, 1e-10);
  xi = result.xi;
  return result.inside;
}

bool LagrangeBasisEvaluator::evaluate_inside(int cell, const Eigen::Vector3d& x, std::vector<int>& basis,
                                             std::vector<double>& values) const {
  Eigen::Vector3d xi;
  if (!reference_point(cell, x, xi)) return false;
  evaluate(cell, xi, basis, values);
  return true;
}

double LagrangeBasisEvaluator::evaluate_nearest(const Eigen::Vector3d& x, std::vector<int>& basis,
                                                std::vector<double>& values) const {
  if (!nearest_) nearest_ = std::make_unique<NearestBoundaryCell>(mesh_);
  const auto [cell, distance] = nearest_->find(x);
  const InverseMapResult result =
      map_to_reference(reference_element(mesh_.element_type), cell_nodes(mesh_, cell), x, 1e-10);
  evaluate(cell, result.xi, basis, values);
  return distance;
}

}  // namespace altfem
