// The surface-load vector of shared/simulation/surface_traction.hpp on a Lagrange mesh,
// against exact integrals: a pressure p on the whole closed boundary has zero resultant
// (∮ n dA = 0) and does virtual work −p ∮ x·n dA = −3 p V on the affine field u = x; a
// traction t on one face of area A does work t·∫x dA; ramps scale the vector; a
// region that holds no triangle is bad input naming its key. On a curved Tet10/Hex20
// mesh the lift to the isoparametric faces makes −3 p V exact with V the isoparametric
// volume; the chordal triangles alone do not.
#include <gtest/gtest.h>

#include <cmath>

#include "shared/common/error.hpp"
#include "shared/fem/lagrange_basis_evaluator.hpp"
#include "shared/fem/lagrange_discretization.hpp"
#include "shared/fem/lagrange_surface_lift.hpp"
#include "shared/material/material.hpp"
#include "shared/mesh/boundary_surface.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/simulation/nodal_basis.hpp"
#include "shared/simulation/surface_traction.hpp"

namespace altfem {
namespace {

const Eigen::AlignedBox3d box(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2, 1, 0.5));

SurfaceTraction load_on(const RegionSelector& region) {
  SurfaceTraction load;
  load.region = region;
  load.pointer = "/loads/traction/0";
  return load;
}

RegionSelector everything() {
  RegionSelector region;
  region.kind = RegionKind::sphere;
  region.radius = 10;
  return region;
}

class SurfaceTractionOnGrid : public testing::TestWithParam<ElementType> {
protected:
  SurfaceTractionOnGrid()
      : mesh_(structured_grid(box, {3, 2, 2}, GetParam())),
        evaluator_(mesh_),
        surface_(boundary_surface(mesh_).surface) {}
  Eigen::VectorXd load_vector(const SurfaceTraction& load) const {
    return SurfaceTractionLoad({load}, surface_, evaluator_, 3 * static_cast<int>(mesh_.nodes.rows()), 1e-9,
                               "s.json")(1.0);
  }
  // Σ_a f_a · u(x_a) for a field u: the virtual work of the load on u's interpolant.
  double work(const Eigen::VectorXd& load, const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& field) const {
    return load.dot(interpolate_at_nodes(mesh_.nodes, field));
  }
  VolumeMesh mesh_;
  LagrangeBasisEvaluator evaluator_;
  SurfaceMesh surface_;
};

TEST_P(SurfaceTractionOnGrid, PressureOnTheClosedBoundaryHasZeroResultantAndWorkMinusThreePV) {
  SurfaceTraction pressure = load_on(everything());
  pressure.pressure = 7.0;
  const Eigen::VectorXd load = load_vector(pressure);
  const double volume = box.volume();
  for (int axis = 0; axis < 3; ++axis)
    EXPECT_NEAR(work(load, [&](const Eigen::Vector3d&) { return Eigen::Vector3d::Unit(axis).eval(); }), 0.0, 1e-12);
  EXPECT_NEAR(work(load, [](const Eigen::Vector3d& x) { return x; }), -3 * 7.0 * volume, 1e-12 * volume);
}

TEST_P(SurfaceTractionOnGrid, TractionOnOneFaceDoesItsExactWork) {
  RegionSelector end;
  end.box = Eigen::AlignedBox3d(Eigen::Vector3d(2, -1, -1), Eigen::Vector3d(3, 2, 2));
  SurfaceTraction traction = load_on(end);
  traction.traction = Eigen::Vector3d(1, -2, 3);
  const Eigen::VectorXd load = load_vector(traction);
  // The face x = 2 has area 0.5 and centroid (2, 0.5, 0.25).
  EXPECT_NEAR(work(load, [](const Eigen::Vector3d&) { return Eigen::Vector3d(1, 1, 1); }), 0.5 * 2, 1e-12);
  EXPECT_NEAR(work(load, [](const Eigen::Vector3d& x) { return Eigen::Vector3d(x.y(), x.z(), x.x()); }),
              0.5 * (1 * 0.5 - 2 * 0.25 + 3 * 2), 1e-12);
}

TEST_P(SurfaceTractionOnGrid, RampScalesTheLoad) {
  SurfaceTraction traction = load_on(everything());
  traction.traction = Eigen::Vector3d(0, 0, -1);
  const Eigen::VectorXd full = load_vector(traction);
  traction.ramp = 0.5;
  const SurfaceTractionLoad ramped({traction}, surface_, evaluator_, static_cast<int>(full.size()), 1e-9, "s.json");
  EXPECT_TRUE(ramped(0.0).isZero(0.0));
  EXPECT_LT((ramped(0.25) - 0.5 * full).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LT((ramped(2.0) - full).cwiseAbs().maxCoeff(), 1e-14);
}

// The normal field −p n written as expressions is the pressure p; a field in t is
// integrated again at each time.
TEST_P(SurfaceTractionOnGrid, TractionFieldOfTheNormalIsThePressure) {
  SurfaceTraction pressure = load_on(everything());
  pressure.pressure = 7.0;
  SurfaceTraction field = load_on(everything());
  field.traction_field = VectorExpression({"-p*nx", "-p*ny", "-p*nz"}, {{"p", 7.0}}, "s.json",
                                          "/loads/traction/0/traction", ExpressionVariables::surface);
  const Eigen::VectorXd expected = load_vector(pressure);
  EXPECT_LT((load_vector(field) - expected).cwiseAbs().maxCoeff(), 1e-13 * expected.cwiseAbs().maxCoeff());

  field.traction_field = VectorExpression({"-p*t*nx", "-p*t*ny", "-p*t*nz"}, {{"p", 7.0}}, "s.json",
                                          "/loads/traction/0/traction", ExpressionVariables::surface);
  const SurfaceTractionLoad timed({field}, surface_, evaluator_, static_cast<int>(expected.size()), 1e-9, "s.json");
  EXPECT_LT((timed(0.5) - 0.5 * expected).cwiseAbs().maxCoeff(), 1e-13 * expected.cwiseAbs().maxCoeff());
  EXPECT_LT((timed(3.0) - 3.0 * expected).cwiseAbs().maxCoeff(), 1e-13 * expected.cwiseAbs().maxCoeff());
}

// A position-dependent field t = (0, 0, x) on the face z = 0.5 (outward normal +z, area 2,
// x from 0 to 2): its work on u = (0, 0, 1) is ∫ x dA = 2, on u = (0, 0, x) it is ∫ x² dA = 8/3.
TEST_P(SurfaceTractionOnGrid, TractionFieldOfPositionDoesItsExactWork) {
  RegionSelector top;
  top.box = Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, 0.5), Eigen::Vector3d(3, 2, 1));
  SurfaceTraction field = load_on(top);
  field.traction_field =
      VectorExpression({"0", "0", "x*nz"}, {}, "s.json", "/loads/traction/0/traction", ExpressionVariables::surface);
  const Eigen::VectorXd load = load_vector(field);
  EXPECT_NEAR(work(load, [](const Eigen::Vector3d&) { return Eigen::Vector3d(0, 0, 1); }), 2.0, 1e-12);
  if (GetParam() != ElementType::tet4 && GetParam() != ElementType::hex8) {  // x² is interpolated exactly
    EXPECT_NEAR(work(load, [](const Eigen::Vector3d& x) { return Eigen::Vector3d(0, 0, x.x()); }), 8.0 / 3.0, 1e-12);
  }
}

TEST_P(SurfaceTractionOnGrid, RegionHoldingNoTriangleNamesTheKey) {
  RegionSelector corner;
  corner.kind = RegionKind::sphere;
  corner.radius = 1e-3;  // holds a vertex, no triangle's centroid
  SurfaceTraction pressure = load_on(corner);
  pressure.pressure = 1;
  try {
    load_vector(pressure);
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("s.json: /loads/traction/0/region: holds the centroid of no triangle"),
              std::string::npos)
        << error.what();
  }
}

// The box bent smoothly, node by node (mid-nodes too): curved isoparametric cells.
VolumeMesh bent_grid(ElementType type) {
  VolumeMesh mesh = structured_grid(box, {3, 2, 2}, type);
  for (Eigen::Index node = 0; node < mesh.nodes.rows(); ++node) {
    const Eigen::Vector3d x = mesh.nodes.row(node).transpose();
    mesh.nodes.row(node) << x.x() + 0.1 * std::sin(2 * x.y()), x.y() + 0.15 * x.x() * x.x(), x.z() * (1 + 0.2 * x.x());
  }
  return mesh;
}

TEST(SurfaceTractionOnCurvedCells, LiftMakesTheClosedPressureWorkExact) {
  for (ElementType type : {ElementType::tet10, ElementType::hex20, ElementType::hex27}) {
    SCOPED_TRACE(std::string(element_name(type)));
    const VolumeMesh mesh = bent_grid(type);
    const auto material = make_material(MaterialModel::linear, 1.0, 0.3, 2.0);
    const auto discretization = make_lagrange_discretization(mesh, *material, {}, 8);
    const Eigen::VectorXd ones =
        interpolate_at_nodes(mesh.nodes, [](const Eigen::Vector3d&) { return Eigen::Vector3d::UnitX().eval(); });
    const double volume = ones.dot(discretization->body_force(Eigen::Vector3d::UnitX())) / 2.0;  // ∫ρ dV / ρ
    SurfaceTraction pressure = load_on(everything());
    pressure.pressure = 3.0;
    const BoundarySurface boundary = boundary_surface(mesh);
    const LagrangeBasisEvaluator evaluator(mesh);
    const Eigen::VectorXd identity = interpolate_at_nodes(mesh.nodes, [](const Eigen::Vector3d& x) { return x; });
    const auto work = [&](const SurfaceLift& lift) {
      return identity.dot(SurfaceTractionLoad({pressure}, boundary.surface, evaluator, discretization->dof_count(),
                                              1e-9, "s.json", lift)(1.0));
    };
    EXPECT_NEAR(work(lagrange_surface_lift(mesh, boundary)), -3 * 3.0 * volume, 1e-11 * volume);
    EXPECT_GT(std::abs(work({}) + 3 * 3.0 * volume), 1e-4 * volume) << "the chordal surface is not the cells' boundary";
  }
}

INSTANTIATE_TEST_SUITE_P(Elements, SurfaceTractionOnGrid,
                         testing::Values(ElementType::tet4, ElementType::tet10, ElementType::hex8, ElementType::hex20,
                                         ElementType::hex27),
                         [](const auto& info) { return std::string(element_name(info.param)); });

}  // namespace
}  // namespace altfem
