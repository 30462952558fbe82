#include "embedded_shapes.hpp"

#include <Eigen/Geometry>

#include "shared/mesh/structured_grid.hpp"

namespace altfem::fcm::testing {
namespace {

/// A prism: the counter-clockwise polygon (seen from +z) extruded from z = 0 to z = height.
Polyhedron extruded(const std::vector<Eigen::Vector2d>& polygon, double height) {
  const int n = static_cast<int>(polygon.size());
  Polyhedron prism;
  prism.vertices.resize(2 * n, 3);
  for (int i = 0; i < n; ++i) {
    prism.vertices.row(i) << polygon[i].x(), polygon[i].y(), 0.0;
    prism.vertices.row(n + i) << polygon[i].x(), polygon[i].y(), height;
  }
  std::vector<int> bottom, top;
  for (int i = 0; i < n; ++i) {
    bottom.push_back(n - 1 - i);
    top.push_back(n + i);
    prism.faces.push_back({i, (i + 1) % n, n + (i + 1) % n, n + i});
  }
  prism.faces.push_back(bottom);
  prism.faces.push_back(top);
  return prism;
}

void append(VolumeMesh& mesh, const VolumeMesh& part) {
  const Eigen::Index offset = mesh.nodes.rows();
  Eigen::MatrixXd nodes(offset + part.nodes.rows(), 3);
  nodes << mesh.nodes, part.nodes;
  Eigen::MatrixXi cells(mesh.cells.rows() + part.cells.rows(), 4);
  cells << mesh.cells, (part.cells.array() + static_cast<int>(offset)).matrix();
  mesh.nodes = nodes;
  mesh.cells = cells;
}

VolumeMesh gridded(const Eigen::Vector3d& low, const Eigen::Vector3d& high) {
  return structured_grid(Eigen::AlignedBox3d(low, high), Eigen::Vector3i(2, 2, 2), ElementType::tet4);
}

}  // namespace

std::vector<EmbeddedShape> corner_shapes(double a) {
  EmbeddedShape tetrahedron{"tetrahedron", {}, {}};
  tetrahedron.tetrahedra.nodes = (Eigen::MatrixXd(4, 3) << 0, 0, 0, a, 0, 0, 0, a, 0, 0, 0, a).finished();
  tetrahedron.tetrahedra.cells = (Eigen::MatrixXi(1, 4) << 0, 1, 2, 3).finished();
  tetrahedron.boundary.vertices = tetrahedron.tetrahedra.nodes;
  tetrahedron.boundary.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

  EmbeddedShape box{"box", gridded(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(a)),
                    extruded({{0, 0}, {a, 0}, {a, a}, {0, a}}, a)};

  EmbeddedShape l_prism{"L-prism", gridded(Eigen::Vector3d::Zero(), Eigen::Vector3d(2 * a, a, a)),
                        extruded({{0, 0}, {2 * a, 0}, {2 * a, a}, {a, a}, {a, 2 * a}, {0, 2 * a}}, a)};
  append(l_prism.tetrahedra, gridded(Eigen::Vector3d(0, a, 0), Eigen::Vector3d(a, 2 * a, a)));
  return {tetrahedron, box, l_prism};
}

EmbeddedShape mapped(const EmbeddedShape& shape, const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& map) {
  EmbeddedShape result = shape;
  for (Eigen::Index i = 0; i < result.tetrahedra.nodes.rows(); ++i)
    result.tetrahedra.nodes.row(i) = map(shape.tetrahedra.nodes.row(i).transpose()).transpose();
  for (Eigen::Index i = 0; i < result.boundary.vertices.rows(); ++i)
    result.boundary.vertices.row(i) = map(shape.boundary.vertices.row(i).transpose()).transpose();
  return result;
}

std::vector<TetrahedronCorners> corner_matrices(const VolumeMesh& mesh) {
  std::vector<TetrahedronCorners> corners(mesh.cells.rows());
  for (Eigen::Index t = 0; t < mesh.cells.rows(); ++t)
    for (int c = 0; c < 4; ++c) corners[t].row(c) = mesh.nodes.row(mesh.cells(t, c));
  return corners;
}

}  // namespace altfem::fcm::testing
