// Centre of mass and initial velocity from any basis (issue #14, item 2): through
// MethodInstance::interpolate and body_force, for a Lagrange L-shaped body and for the
// two-cube degree-1 monomial basis (not a partition of unity).
#include <gtest/gtest.h>

#include "shared/assembly/tabulated_discretization.hpp"
#include "shared/fem/tabulate_lagrange.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/simulation/rigid_motion.hpp"
#include "tests/unit/assembly/face_fixture.hpp"
#include "tests/unit/fem/test_meshes.hpp"

namespace altfem {
namespace {

using Field = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;

// A basis with no elements: rigid_motion evaluates none.
class NoElements final : public ElementBasisEvaluator {
public:
  int element_count() const override { return 0; }
  Eigen::AlignedBox3d element_bounds(int) const override { return {}; }
  bool evaluate_inside(int, const Eigen::Vector3d&, std::vector<int>&, std::vector<double>&) const override {
    return false;
  }
  double evaluate_nearest(const Eigen::Vector3d&, std::vector<int>&, std::vector<double>&) const override { return 0; }
};

// A method reduced to what rigid_motion asks of it: a discretization and interpolation.
class InterpolatingMethod final : public MethodInstance {
public:
  InterpolatingMethod(DiscretizationParts parts, std::function<Eigen::VectorXd(const Field&)> interpolate)
      : discretization_(std::move(parts)), interpolate_(std::move(interpolate)) {}
  const Discretization& discretization() const override { return discretization_; }
  nlohmann::json element_counts() const override { return {}; }
  long long quadrature_points() const override { return discretization_.elements().point_count(); }
  double quadrature_seconds() const override { return 0; }
  UnstructuredGrid volume_grid(const Eigen::VectorXd&) const override { return {}; }
  const SurfaceMesh& embedded_surface() const override { return surface_; }
  const ElementBasisEvaluator& basis_evaluator() const override { return no_elements_; }
  Eigen::MatrixXd embedded_displacement(const Eigen::VectorXd&) const override { return {}; }
  Eigen::VectorXd interpolate(const Field& field) const override { return interpolate_(field); }

private:
  TabulatedDiscretization discretization_;
  std::function<Eigen::VectorXd(const Field&)> interpolate_;
  SurfaceMesh surface_;
  NoElements no_elements_;
};

// [0,2]×[0,2]×[0,1] without the quarter [1,2]×[1,2], shifted by `offset`, in Hex20
// cells of 1/2, with its nodes renumbered so that every node belongs to a cell.
VolumeMesh l_shape(const Eigen::Vector3d& offset) {
  const VolumeMesh grid = structured_grid({offset, offset + Eigen::Vector3d(2, 2, 1)}, {4, 4, 2}, ElementType::hex20);
  std::vector<int> kept;
  for (Eigen::Index c = 0; c < grid.cells.rows(); ++c) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (Eigen::Index k = 0; k < grid.cells.cols(); ++k) centroid += grid.nodes.row(grid.cells(c, k)).transpose();
    centroid = centroid / static_cast<double>(grid.cells.cols()) - offset;
    if (centroid.x() < 1 || centroid.y() < 1) kept.push_back(static_cast<int>(c));
  }
  std::vector<int> renumbered(static_cast<size_t>(grid.nodes.rows()), -1);
  VolumeMesh mesh{grid.element_type, Eigen::MatrixXd(),
                  Eigen::MatrixXi(static_cast<Eigen::Index>(kept.size()), grid.cells.cols())};
  std::vector<Eigen::Vector3d> nodes;
  for (size_t c = 0; c < kept.size(); ++c)
    for (Eigen::Index k = 0; k < grid.cells.cols(); ++k) {
      int& node = renumbered[grid.cells(kept[c], k)];
      if (node < 0) {
        node = static_cast<int>(nodes.size());
        nodes.push_back(grid.nodes.row(grid.cells(kept[c], k)).transpose());
      }
      mesh.cells(static_cast<Eigen::Index>(c), k) = node;
    }
  mesh.nodes.resize(static_cast<Eigen::Index>(nodes.size()), 3);
  for (size_t n = 0; n < nodes.size(); ++n) mesh.nodes.row(static_cast<Eigen::Index>(n)) = nodes[n].transpose();
  return mesh;
}

TEST(RigidMotion, CentreOfMassOfLagrangeLShape) {
  const Eigen::Vector3d offset(0.7, -0.3, 2.0);
  const VolumeMesh mesh = l_shape(offset);
  ASSERT_EQ(mesh.cells.rows(), 24);
  const auto material = make_material(MaterialModel::linear, 1e5, 0.3, 1000);
  DiscretizationParts parts;
  parts.elements = tabulate_lagrange(mesh, 4);
  parts.materials = {material.get()};
  const InterpolatingMethod method(std::move(parts),
                                   [&](const Field& field) { return test::nodal_values(mesh, field); });
  // Three unit squares centred at (1/2, 1/2), (3/2, 1/2), (1/2, 3/2), depth 1.
  const Eigen::Vector3d exact = offset + Eigen::Vector3d(2.5 / 3, 2.5 / 3, 0.5);
  EXPECT_LT((centre_of_mass(method) - exact).norm(), 1e-12);

  // v + ω × (x − c) about the centre of mass, at every node.
  InitialConditions initial;
  initial.velocity = Eigen::Vector3d(1, 0, -2);
  initial.angular_velocity = Eigen::Vector3d(0.5, -1, 3);
  const Eigen::VectorXd velocity = initial_velocity(method, initial);
  for (Eigen::Index node = 0; node < mesh.nodes.rows(); ++node) {
    const Eigen::Vector3d x = mesh.nodes.row(node).transpose();
    const Eigen::Vector3d expected = initial.velocity + initial.angular_velocity.cross(x - exact);
    EXPECT_LT((velocity.segment<3>(3 * node) - expected).norm(), 1e-12) << "node " << node;
  }
}

TEST(RigidMotion, CentreOfMassOfMonomialCubes) {
  const auto material = make_material(MaterialModel::linear, 1e5, 0.3, 1000);
  DiscretizationParts parts;
  parts.elements = test::two_cube_elements(3);
  parts.materials = {material.get()};
  parts.explicit_mass = ExplicitMassKind::block_per_element;
  // An affine field f on cube c: f(x_c) on its constant, the columns of ∇f on the
  // centred monomials x − x_c, y − 1/2, z − 1/2 (finite differences are exact).
  const InterpolatingMethod method(std::move(parts), [](const Field& field) {
    Eigen::VectorXd coefficients(24);
    for (int cube = 0; cube < 2; ++cube) {
      const Eigen::Vector3d centre = test::cube_centre(cube);
      coefficients.segment<3>(12 * cube) = field(centre);
      for (int d = 0; d < 3; ++d)
        coefficients.segment<3>(12 * cube + 3 * (d + 1)) = field(centre + Eigen::Vector3d::Unit(d)) - field(centre);
    }
    return coefficients;
  });
  EXPECT_LT((centre_of_mass(method) - Eigen::Vector3d(1, 0.5, 0.5)).norm(), 1e-14);
}

}  // namespace
}  // namespace altfem
