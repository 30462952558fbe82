#include <Eigen/LU>
#include <cmath>

#include "shared/mesh/corner_tetrahedra.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

namespace {
// Volume of the trilinear map through the 8 corners (VTK order): the Jacobian
// determinant has degree 2 in each reference coordinate, so 2×2×2 Gauss–Legendre
// integrates it exactly. Written here because only the corners are needed.
double trilinear_hexahedron_volume(const Eigen::Matrix<double, 8, 3>& corners) {
  static constexpr int sign[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                     {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  const double gauss = 1.0 / std::sqrt(3.0);
  double volume = 0;
  for (const auto& point : sign) {
    const double xi[3] = {point[0] * gauss, point[1] * gauss, point[2] * gauss};
    Eigen::Matrix3d jacobian = Eigen::Matrix3d::Zero();  // ∂x/∂ξ on [-1,1]³
    for (int node = 0; node < 8; ++node)
      for (int axis = 0; axis < 3; ++axis) {
        double derivative = sign[node][axis] / 8.0;
        for (int other = 0; other < 3; ++other)
          if (other != axis) derivative *= 1 + sign[node][other] * xi[other];
        jacobian.col(axis) += derivative * corners.row(node).transpose();
      }
    volume += jacobian.determinant();  // Gauss weights are all 1
  }
  return volume;
}
}  // namespace

double volume_mesh_volume(const VolumeMesh& mesh) {
  double volume = 0;
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell) {
    if (element_shape(mesh.element_type) == ElementShape::tetrahedron) {
      volume += six_signed_volume(mesh.nodes.row(mesh.cells(cell, 0)), mesh.nodes.row(mesh.cells(cell, 1)),
                                  mesh.nodes.row(mesh.cells(cell, 2)), mesh.nodes.row(mesh.cells(cell, 3))) /
                6;
    } else {
      Eigen::Matrix<double, 8, 3> corners;
      for (int node = 0; node < 8; ++node) corners.row(node) = mesh.nodes.row(mesh.cells(cell, node));
      volume += trilinear_hexahedron_volume(corners);
    }
  }
  return volume;
}

Eigen::MatrixX3d corner_centroids(const VolumeMesh& mesh) {
  const int corners = element_corner_count(mesh.element_type);
  Eigen::MatrixX3d centroids = Eigen::MatrixX3d::Zero(mesh.cells.rows(), 3);
  for (Eigen::Index c = 0; c < mesh.cells.rows(); ++c)
    for (int a = 0; a < corners; ++a) centroids.row(c) += mesh.nodes.row(mesh.cells(c, a)) / corners;
  return centroids;
}

}  // namespace altfem
