// Patch test: an affine displacement imposed on the boundary nodes of a distorted
// 3×3×3 mesh is reproduced at every node by linear elasticity (no body force).
//
// Meshes: the interior corner vertices are moved randomly by up to 15% of h in each
// coordinate before the higher-order nodes are placed (test_meshes.hpp), so tets are
// straight-sided and hexes are general trilinear cells with their higher-order nodes
// on the trilinear map; every hex type also runs on a parallelepiped (affine) grid.
// Hex20 passes on the trilinear cells too: the 20-node serendipity space contains
// ξηζ, so the trilinear geometry — and with it every affine field — is in the
// isoparametric space; what serendipity elements lose on non-affine cells is their
// approximation order (Arnold, Boffi & Falk 2002), not the patch test.
//
// Quadrature: with constant stress σ the residual at node a is Σ_q w_q σ : (∂N_a/∂ξ)
// adj J(ξ_q), a polynomial (degree p−1 on affine tets; ≤ 7 for Hex8/Hex20 and ≤ 9 for
// Hex27 on trilinear cells), so strength 9 integrates it exactly for hexes.
#include <gtest/gtest.h>

#include <chrono>

#include "shared/fem/tabulate_lagrange.hpp"
#include "tests/unit/fem/test_meshes.hpp"
#include "tests/unit/newton/loaded_potential.hpp"

namespace altfem {
namespace {

enum class Distortion { random_vertices, parallelepiped };

struct Case {
  ElementType type;
  Distortion distortion;
};

VolumeMesh patch_mesh(const Case& c) {
  if (c.distortion == Distortion::random_vertices)
    return test::distorted_grid(test::unit_cube(), {3, 3, 3}, c.type, 0.15, 21);
  VolumeMesh mesh = structured_grid(test::unit_cube(), {3, 3, 3}, c.type);
  Eigen::Matrix3d shear;
  shear << 1.0, 0.3, -0.2, 0.1, 0.9, 0.25, -0.15, 0.2, 1.1;
  test::transform_nodes(mesh, shear, Eigen::Vector3d(0.5, -0.2, 0.1));
  return mesh;
}

class PatchTest : public ::testing::TestWithParam<Case> {};

TEST_P(PatchTest, AffineDisplacementReproducedAtEveryNode) {
  const auto start = std::chrono::steady_clock::now();
  const VolumeMesh mesh = patch_mesh(GetParam());
  const ElementType type = GetParam().type;
  const int strength = element_shape(type) == ElementShape::tetrahedron ? 2 * element_degree(type) : 9;
  const TabulatedElements elements = tabulate_lagrange(mesh, strength);
  const auto material = make_material(MaterialModel::linear, 1.0, 0.3, 1.0);
  const ElasticAssembler assembler(elements, {material.get()});

  Eigen::Matrix3d A;
  A << 0.12, -0.05, 0.08, 0.03, -0.1, 0.06, -0.07, 0.04, 0.09;
  const Eigen::Vector3d b(0.01, -0.02, 0.03);
  const Eigen::VectorXd exact =
      test::nodal_values(mesh, [&](const Eigen::Vector3d& x) -> Eigen::Vector3d { return A * x + b; });

  // Boundary nodes, found on the undistorted grid: distortion and transformation
  // keep the node numbering.
  const std::vector<int> constrained =
      test::boundary_dofs(structured_grid(test::unit_cube(), {3, 3, 3}, type), test::unit_cube());
  Eigen::VectorXd prescribed(static_cast<Eigen::Index>(constrained.size()));
  for (size_t i = 0; i < constrained.size(); ++i) prescribed[static_cast<Eigen::Index>(i)] = exact[constrained[i]];
  ASSERT_LT(constrained.size(), size_t(3 * mesh.nodes.rows()));

  const Eigen::VectorXd u =
      test::solve_static(assembler, Eigen::VectorXd::Zero(assembler.dof_count()), constrained, prescribed);
  const double error = (u - exact).lpNorm<Eigen::Infinity>();
  EXPECT_LE(error, 1e-10);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("[ patch    ] %s %s: max nodal error %.2e, %ld DOFs, %.2f s\n", std::string(element_name(type)).c_str(),
              GetParam().distortion == Distortion::random_vertices ? "random vertices" : "parallelepiped", error,
              static_cast<long>(assembler.dof_count()), seconds);
}

std::vector<Case> all_cases() {
  std::vector<Case> cases;
  for (ElementType type : test::all_element_types) {
    cases.push_back({type, Distortion::random_vertices});
    cases.push_back({type, Distortion::parallelepiped});
  }
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Fem, PatchTest, ::testing::ValuesIn(all_cases()), [](const auto& info) {
  return std::string(element_name(info.param.type)) +
         (info.param.distortion == Distortion::random_vertices ? "_random_vertices" : "_parallelepiped");
});

}  // namespace
}  // namespace altfem
