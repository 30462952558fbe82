// Example 8: hanging nodes — how a conforming Lagrange space survives local refinement
// (issue #34; the hanging-node constraints of deal.II's step-6, in 3D).
//
//   build/bin/ex8_hanging_nodes
//
// A 3 × 3 × 3 grid of Hex8 cells on the unit cube whose middle cell is split into eighths
// (hexahedral_forest.hpp). The children have nodes on the faces and edges they share with
// their unsplit neighbours that are not nodes of those neighbours: hanging nodes. Left as
// free DOFs, they let the displacement tear along those faces — the space is not
// conforming. Constrained, each takes its neighbour's own interpolation at it,
//     u(x_h) = Σ_m N_m(x_h) u_m   (m: the neighbour's nodes; ¼ each at a face centre, ½ at
//                                   an edge midpoint),
// and the space is conforming and holds the coarse one. The patch test tells the two apart:
// an affine displacement has a constant stress, so its internal forces
//     f_a = ∫ σ : ∇N_a dV
// cancel at every node inside the cube — in a conforming space. The program prints the
// constraints, then checks the patch test with and without them.
#include <cmath>
#include <cstdio>

#include "shared/fem/lagrange_discretization.hpp"
#include "shared/mesh/hexahedral_forest.hpp"

using namespace altfem;

// u(x) = G x: a constant strain.
Eigen::Vector3d affine(const Eigen::Vector3d& x) {
  Eigen::Matrix3d gradient;
  gradient << 1e-3, 2e-4, 0, -1e-4, 5e-4, 3e-4, 0, 1e-4, -2e-4;
  return gradient * x;
}

// The largest internal force at a node inside the cube, relative to the largest anywhere.
double largest_inside_force(const Discretization& discretization, const Eigen::MatrixXd& nodes) {
  Eigen::VectorXd u(discretization.dof_count()), forces;
  for (Eigen::Index node = 0; node < u.size() / 3; ++node) u.segment<3>(3 * node) = affine(nodes.row(node));
  discretization.gradient(u, forces);
  double inside = 0, largest = 0;
  for (Eigen::Index node = 0; node < u.size() / 3; ++node) {
    const double force = forces.segment<3>(3 * node).norm();
    largest = std::max(largest, force);
    const Eigen::Array3d x = nodes.row(node);
    if ((x > 1e-12).all() && (x < 1 - 1e-12).all()) inside = std::max(inside, force);
  }
  return inside / largest;
}

int main() {
  const HexahedralForest forest = refine_forest(
      grid_forest({Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()}, Eigen::Vector3i::Constant(3), ElementType::hex8),
      {13});
  const ConstrainedHexahedralMesh refined = forest_mesh(forest);
  const NodeConstraints& constraints = refined.constraints;
  std::printf("3 x 3 x 3 Hex8 grid, middle cell split: %d cells, %d free nodes, %d hanging nodes\n\n",
              forest.leaf_count(), constraints.free_nodes, constraints.hanging_nodes());
  // One hanging node of each kind: on an edge (2 masters) and in a face (4).
  for (const std::size_t kind : {2u, 4u}) {
    int i = 0;
    while (constraints.masters[i].size() != kind) ++i;
    const Eigen::Vector3d x = refined.mesh.nodes.row(constraints.free_nodes + i);
    std::printf("hanging node at (%.3f, %.3f, %.3f) =", x.x(), x.y(), x.z());
    for (std::size_t k = 0; k < kind; ++k) {
      const Eigen::Vector3d m = refined.mesh.nodes.row(constraints.masters[i][k]);
      std::printf(" %s%.2f u(%.2f, %.2f, %.2f)", k ? "+ " : "", constraints.weights[i][k], m.x(), m.y(), m.z());
    }
    std::printf("\n");
  }

  const auto material = make_material(MaterialModel::linear, 1e6, 0.3, 1000);
  // Constrained: the basis is the free nodes, each hanging node's function handed to its masters.
  const auto conforming =
      make_lagrange_discretization(refined.mesh, {material.get()}, {}, {}, 2, "example", &constraints);
  // Unconstrained: every node a DOF, the hanging ones too.
  const auto torn = make_lagrange_discretization(refined.mesh, *material, {}, 2);
  const double conforming_force = largest_inside_force(*conforming, refined.mesh.nodes);
  const double torn_force = largest_inside_force(*torn, refined.mesh.nodes);
  std::printf(
      "\npatch test: the largest internal force of an affine displacement inside the cube,\n"
      "relative to the largest on its boundary (0 in a conforming space)\n");
  std::printf("  hanging nodes constrained: %9.2e\n", conforming_force);
  std::printf("  hanging nodes free:        %9.2e\n", torn_force);

  const bool passed = conforming_force < 1e-12 && torn_force > 1e-3;
  std::printf("\n%s: the constraints make the refined space conforming; without them it is not\n",
              passed ? "verified" : "NOT verified");
  return passed ? 0 : 1;
}
