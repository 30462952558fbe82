#pragma once
// Meshes shared by the fem, assembly and newton tests and the fem verification
// tests: structured grids, randomly distorted ones, and their boundary nodes.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <random>
#include <vector>

#include "shared/mesh/elevate_order.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem::test {

inline Eigen::AlignedBox3d unit_cube() { return {Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()}; }

inline bool on_box_boundary(const Eigen::Vector3d& x, const Eigen::AlignedBox3d& box, double tolerance = 1e-12) {
  return ((x - box.min()).array().abs() < tolerance).any() || ((x - box.max()).array().abs() < tolerance).any();
}

/// A structured grid of `type` whose interior corner vertices are moved by a uniform
/// random vector of up to `amplitude` × the cell size in each coordinate, BEFORE the
/// higher-order nodes are placed: tets stay straight-sided (affine), hexes become
/// general trilinear cells with their higher-order nodes on that trilinear map.
/// Boundary vertices stay on the box, so the mesh still fills it exactly.
inline VolumeMesh distorted_grid(const Eigen::AlignedBox3d& box, const Eigen::Vector3i& resolution, ElementType type,
                                 double amplitude, unsigned seed) {
  const ElementType linear = element_shape(type) == ElementShape::tetrahedron ? ElementType::tet4 : ElementType::hex8;
  VolumeMesh mesh = structured_grid(box, resolution, linear);
  const Eigen::Vector3d cell = box.sizes().cwiseQuotient(resolution.cast<double>());
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (Eigen::Index node = 0; node < mesh.nodes.rows(); ++node) {
    if (on_box_boundary(mesh.nodes.row(node).transpose(), box, 1e-9 * cell.minCoeff())) continue;
    for (int d = 0; d < 3; ++d) mesh.nodes(node, d) += amplitude * cell[d] * uniform(random);
  }
  return elevate_order(mesh, type);
}

/// x ↦ A x + b applied to every node (an affine image of a grid is a parallelepiped
/// grid: every element map stays affine).
inline void transform_nodes(VolumeMesh& mesh, const Eigen::Matrix3d& A, const Eigen::Vector3d& b) {
  mesh.nodes = ((mesh.nodes * A.transpose()).rowwise() + b.transpose()).eval();
}

/// The DOFs (3·node + k) of every node on the box's boundary, ascending.
inline std::vector<int> boundary_dofs(const VolumeMesh& mesh, const Eigen::AlignedBox3d& box) {
  std::vector<int> dofs;
  const double tolerance = 1e-9 * box.diagonal().norm();
  for (Eigen::Index node = 0; node < mesh.nodes.rows(); ++node)
    if (on_box_boundary(mesh.nodes.row(node).transpose(), box, tolerance))
      for (int k = 0; k < 3; ++k) dofs.push_back(3 * static_cast<int>(node) + k);
  return dofs;
}

/// u(x) evaluated at every node as a 3·#nodes DOF vector.
template <typename Field>
Eigen::VectorXd nodal_values(const VolumeMesh& mesh, Field&& field) {
  Eigen::VectorXd u(3 * mesh.nodes.rows());
  for (Eigen::Index node = 0; node < mesh.nodes.rows(); ++node)
    u.segment<3>(3 * node) = field(Eigen::Vector3d(mesh.nodes.row(node).transpose()));
  return u;
}

inline constexpr ElementType all_element_types[] = {ElementType::tet4, ElementType::tet10, ElementType::tet20,
                                                    ElementType::hex8, ElementType::hex20, ElementType::hex27};

}  // namespace altfem::test
