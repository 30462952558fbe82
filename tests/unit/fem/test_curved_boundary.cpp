// Curved Tet10/Tet20 boundaries: boundary higher-order nodes land on the true surface,
// and the mesh volume approaches the ball's much faster than with straight edges.
#include <gtest/gtest.h>

#include <cmath>

#include "shared/fem/tabulate_lagrange.hpp"
#include "shared/geometry/analytic_shape.hpp"
#include "shared/mesh/boundary_surface.hpp"
#include "shared/mesh/curve_boundary.hpp"
#include "shared/mesh/elevate_order.hpp"
#include "shared/mesh/tetrahedralize.hpp"

namespace altfem {
namespace {

double mesh_volume(const VolumeMesh& mesh) {
  const TabulatedElements elements = tabulate_lagrange(mesh, 6);
  double volume = 0;
  for (int e = 0; e < elements.size(); ++e)
    for (double w : elements[e].weights) volume += w;
  return volume;
}

TEST(CurvedBoundary, Tet10NodesOnTheSphereAndVolumeCloser) {
  const auto ball = make_sphere(Eigen::Vector3d::Zero(), 1.0);
  const VolumeMesh linear = tetrahedralize_shape(*ball, 0.35);
  VolumeMesh straight = elevate_order(linear, ElementType::tet10);
  VolumeMesh curved = straight;
  const auto level_set = [&](const Eigen::Vector3d& x) { return ball->level_set(x); };
  const int moved =
      curve_boundary(curved, [&](const Eigen::Vector3d& x) { return project_to_level_set(level_set, x, 1e-7); });
  const BoundarySurface boundary = boundary_surface(linear);
  // Each boundary triangle has three edges, each shared by two triangles: E = 3T/2.
  EXPECT_EQ(moved, 3 * boundary.surface.triangles.rows() / 2);

  int on_sphere = 0;
  for (Eigen::Index node = linear.nodes.rows(); node < curved.nodes.rows(); ++node)
    if (std::abs(curved.nodes.row(node).norm() - 1.0) < 1e-9) ++on_sphere;
  EXPECT_EQ(on_sphere, moved);

  const double exact = 4.0 * M_PI / 3.0;
  const double straight_error = std::abs(mesh_volume(straight) - exact);
  const double curved_error = std::abs(mesh_volume(curved) - exact);
  EXPECT_LT(curved_error, 0.25 * straight_error) << "straight " << straight_error << ", curved " << curved_error;
}

}  // namespace
}  // namespace altfem
