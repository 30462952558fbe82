// The harmonic method end to end (issue #19), each test printing its table:
//   - the shipped cantilever (clamped, own weight, linear material) with MFS bases on
//     every hexahedron of a [20, 2, 2] grid: tip deflection within 3% of fem Hex8 on the
//     same grid (the MFS basis of a hex approaches the trilinear one, Martin et al. 2008 §5);
//     basis `auto` (closed-form trilinear) gives fem Hex8's deflection to round-off;
//   - on the bases of the method's mesh (1 × 0.6 × 0.8 hexahedra, where the trilinear
//     basis is harmonic, hence what MFS should find): partition of unity ≤ 1e-10,
//     N_i(x_j) = δ_ij to the fit's accuracy (shrinking with samples per edge), and MFS
//     against trilinear ≤ 1e-3 pointwise from 4 samples per edge on;
//   - the patch test under the method's own quadrature with MFS bases: an affine
//     displacement leaves no force on interior nodes (no ghost forces), rigid translation none anywhere;
//   - a sliced hollow tube, whose cut cells are star-shaped about no point and hold more
//     nodes than their default kernels: it bends as Timoshenko's beam, within 15%; and the
//     shipped hollow ball on `slice` takes fem's first step, within 3%.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "polyhedral/harmonic_element_bases.hpp"
#include "polyhedral/harmonic_method.hpp"
#include "shared/element/reference_element.hpp"
#include "shared/fem/method/fem_method.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/simulation/simulation.hpp"
#include "shared/solve/time_integrator.hpp"

namespace altfem::harmonic {
namespace {

Scene cantilever(const std::string& basis) {
  Scene scene = load_scene(std::filesystem::path(ALTFEM_SOURCE_DIR) / "scenes/cantilever.json");
  scene.resolved["discretization"]["fem"] = {{"element", "hex8"}, {"mesh", "grid"}, {"resolution", {20, 2, 2}}};
  scene.resolved["discretization"]["harmonic"] = {{"convert", {{"mesh", "grid"}, {"resolution", {20, 2, 2}}}},
                                                  {"basis", basis}};
  return scene;
}

// Mean z-displacement of the embedded surface's vertices on the free end x = 1 (static, gravity).
double tip_deflection(const Scene& scene, const MethodFactory& factory, int& dofs) {
  const SceneGeometry geometry = load_scene_geometry(scene);
  const auto method = factory(scene, geometry);
  const Discretization& discretization = method->discretization();
  dofs = discretization.dof_count();
  const auto solver = make_linear_solver({});
  IntegratorOptions options;
  options.kind = IntegrationScheme::static_equilibrium;
  options.gravity = scene.gravity;
  TimeIntegrator integrator(discretization, *solver, options);
  State state{Eigen::VectorXd::Zero(dofs), Eigen::VectorXd::Zero(dofs)};
  integrator.apply_constraints(state);
  integrator.step(state);
  const Eigen::MatrixXd moved = method->embedded_displacement(state.displacement);
  const Eigen::MatrixXd& vertices = method->embedded_surface().vertices;
  double sum = 0;
  int count = 0;
  for (Eigen::Index v = 0; v < vertices.rows(); ++v)
    if (std::abs(vertices(v, 0) - 1.0) < 1e-12) sum += moved(v, 2), ++count;
  return -sum / count;
}

TEST(HarmonicMethod, CantileverWithMfsBasesMatchesHex8) {
  int fem_dofs = 0, mfs_dofs = 0, auto_dofs = 0;
  const double hex8 = tip_deflection(cantilever("mfs"), make_fem_method, fem_dofs);
  const double mfs = tip_deflection(cantilever("mfs"), make_harmonic_method, mfs_dofs);
  const double closed_form = tip_deflection(cantilever("auto"), make_harmonic_method, auto_dofs);
  std::printf("[ beam     ] [20,2,2] grid, linear, own weight   DOFs   tip deflection (m)   vs fem hex8\n");
  std::printf("[ beam     ] fem hex8                          %6d   %.6e\n", fem_dofs, hex8);
  std::printf("[ beam     ] harmonic, basis auto (trilinear)  %6d   %.6e   %+.2e\n", auto_dofs, closed_form,
              (closed_form - hex8) / hex8);
  std::printf("[ beam     ] harmonic, basis mfs               %6d   %.6e   %+.2e\n", mfs_dofs, mfs,
              (mfs - hex8) / hex8);
  EXPECT_EQ(mfs_dofs, fem_dofs);
  EXPECT_NEAR(closed_form, hex8, 1e-10 * hex8);
  EXPECT_NEAR(mfs, hex8, 0.03 * hex8);
}

// A polyhedral mesh of 2 × 2 × 1 non-cubic hexahedra (1 × 0.6 × 0.8 cells).
PolyhedralMesh hexahedra() {
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 1.2, 0.8));
  return polyhedral_mesh_from_volume_mesh(structured_grid(box, {2, 2, 1}, ElementType::hex8));
}

struct BasisErrors {
  double unity = 0;               // max |Σ_i N_i − 1| at random points
  double nodal = 0;               // max |N_i(x_j) − δ_ij|
  double trilinear = 0;           // max |N_i − N_i^trilinear| at random points
  double trilinear_gradient = 0;  // max |∇N_i − ∇N_i^trilinear| × cell diameter
};

// The MFS bases of every (box-shaped) cell of `mesh` against the trilinear basis, at
// the nodes and at 50 random points per cell (the same points for every call).
BasisErrors mfs_basis_errors(const PolyhedralMesh& mesh, const MfsOptions& options) {
  const HarmonicElementBases mfs(mesh, HarmonicBasisKind::mfs, options);
  const HarmonicElementBases trilinear(mesh, HarmonicBasisKind::automatic, {});
  const ReferenceElement& hex8 = reference_element(ElementType::hex8);
  std::mt19937 random(19);
  std::uniform_real_distribution<double> unit(0, 1);
  BasisErrors errors;
  Eigen::VectorXd values, plain_values(8);
  Eigen::MatrixXd gradients, reference_gradients(8, 3);
  for (int cell = 0; cell < mesh.cell_count(); ++cell) {
    const ElementHarmonicBasis& basis = *mfs.mfs_basis(cell);
    const std::vector<int>& nodes = mfs.nodes(cell);
    const std::vector<int>& plain_nodes = trilinear.nodes(cell);
    for (size_t j = 0; j < nodes.size(); ++j) {
      basis.evaluate(mesh.nodes.row(nodes[j]).transpose(), values, gradients);
      for (size_t i = 0; i < nodes.size(); ++i)
        errors.nodal = std::max(errors.nodal, std::abs(values[i] - (i == j ? 1.0 : 0.0)));
    }
    // The plain Hex8 of an axis-aligned box: ξ = 2 (x − x₀) / h − 1 from its node 0
    // (whichever corner that is), so ∂ξ/∂x = diag(±2 / h).
    const Eigen::Vector3d origin = mesh.nodes.row(plain_nodes[0]).transpose();
    const Eigen::Vector3d step = mesh.nodes.row(plain_nodes[6]).transpose() - origin;  // node 6 opposite node 0
    const double diameter = mesh.cell_diameters[cell];
    for (int p = 0; p < 50; ++p) {
      const Eigen::Vector3d xi(2 * unit(random) - 1, 2 * unit(random) - 1, 2 * unit(random) - 1);
      const Eigen::Vector3d x = origin + (xi.array() + 1).matrix().cwiseProduct(step) / 2;
      basis.evaluate(x, values, gradients);
      hex8.evaluate(xi, plain_values);
      hex8.evaluate_gradients(xi, reference_gradients);
      const Eigen::MatrixXd plain_gradients = reference_gradients * (2 * step.cwiseInverse()).asDiagonal();
      errors.unity = std::max(errors.unity, std::abs(values.sum() - 1));
      for (size_t i = 0; i < nodes.size(); ++i) {
        const auto k = std::find(plain_nodes.begin(), plain_nodes.end(), nodes[i]) - plain_nodes.begin();
        errors.trilinear = std::max(errors.trilinear, std::abs(values[i] - plain_values[k]));
        errors.trilinear_gradient = std::max(
            errors.trilinear_gradient,
            diameter * (gradients.row(static_cast<Eigen::Index>(i)) - plain_gradients.row(k)).cwiseAbs().maxCoeff());
      }
    }
  }
  return errors;
}

// The hollow tube of tests/verify/events/scenes/tube_cut.json sliced at resolution 10
// (1 m long, radii 0.05 and 0.03 m, clamped at x = 0, own weight): its cut cells hold up to
// 220 nodes, and their inner wall is concave, so no point sees every face. Their volume
// rules once had 10 points (a rank-30 stiffness for 220 nodes) and their kernels merged
// below the node count: the run failed at step 1, and with the rule fixed alone the tube bent
// 1.76 times as far as beam theory says. Timoshenko's cantilever under its weight q = ρgA:
// δ = qL⁴/(8EI) + qL²/(2κGA), κ for a thick tube (Cowper 1966). dg k = 2 on the same slice
// gives 0.5% above it; the harmonic basis, linear along edges, 10%.
TEST(HarmonicMethod, SlicedTubeWithNonStarShapedCellsBendsAsTimoshenkosBeam) {
  const Scene scene = load_scene(std::filesystem::path(ALTFEM_SOURCE_DIR) / "tests/verify/events/scenes/tube_cut.json");
  int dofs = 0;
  const double deflection = tip_deflection(scene, make_harmonic_method, dofs);
  const double E = 1e8, nu = 0.3, outer = 0.05, inner = 0.03, length = 1;
  const double area = M_PI * (outer * outer - inner * inner),
               inertia = M_PI * (std::pow(outer, 4) - std::pow(inner, 4)) / 4;
  const double ratio = inner / outer, squared = (1 + ratio * ratio) * (1 + ratio * ratio);
  const double kappa = 6 * (1 + nu) * squared / ((7 + 6 * nu) * squared + (20 + 12 * nu) * ratio * ratio);
  const double load = 1000 * 9.81 * area, shear_modulus = E / (2 * (1 + nu));
  const double timoshenko =
      load * std::pow(length, 4) / (8 * E * inertia) + load * length * length / (2 * kappa * shear_modulus * area);
  std::printf("  sliced tube, harmonic: %d DOFs, tip deflection %.5f m, Timoshenko %.5f m (ratio %.3f)\n", dofs,
              deflection, timoshenko, deflection / timoshenko);
  EXPECT_NEAR(deflection / timoshenko, 1.0, 0.15);
}

// The largest displacement of the embedded surface after the scene's first step.
double first_step_largest_displacement(const Scene& scene, const MethodFactory& factory, const std::string& name) {
  Simulation simulation(scene, load_scene_geometry(scene), name, factory);
  simulation.integrator().step(simulation.state());
  return simulation.method().embedded_displacement(simulation.state().displacement).rowwise().norm().maxCoeff();
}

// The shipped hollow ball on `slice` (its cut cells ring the inner cavity: star-shaped
// about no point, many facet nodes). With 10-point rules and fewer kernels than nodes its
// first step moved the surface 5.6 times as far as fem's, in 16 Newton iterations and
// without an error; fem (Tet10) and dg agree within 1.4%.
TEST(HarmonicMethod, SlicedHollowBallTakesFemsFirstStep) {
  Scene scene = load_scene(std::filesystem::path(ALTFEM_SOURCE_DIR) / "scenes/hollow_ball.json");
  const double fem = first_step_largest_displacement(scene, make_fem_method, "fem");
  scene.resolved["discretization"]["harmonic"]["mesh"] = "slice";
  const double harmonic = first_step_largest_displacement(scene, make_harmonic_method, "harmonic");
  std::printf("  hollow ball, first step: largest displacement harmonic (slice) %.4e m, fem %.4e m\n", harmonic, fem);
  EXPECT_NEAR(harmonic, fem, 0.03 * fem);
}

TEST(HarmonicMethod, MfsBasesArePartitionsOfUnityInterpolatingAndNearlyTrilinear) {
  const PolyhedralMesh mesh = hexahedra();
  std::printf(
      "[ bases    ] samples/edge  offset   max|ΣN−1|   max|N_i(x_j)−δ_ij|   max|N−N_trilinear|   "
      "max|∇N−∇N_trilinear|·diam\n");
  const auto row = [&](int samples, double offset) {
    MfsOptions options;
    options.edge_samples = samples;
    options.offset = offset;
    const BasisErrors errors = mfs_basis_errors(mesh, options);
    std::printf("[ bases    ] %12d  %6.2f   %9.2e   %18.2e   %18.2e   %25.2e\n", samples, offset, errors.unity,
                errors.nodal, errors.trilinear, errors.trilinear_gradient);
    EXPECT_LT(errors.unity, 1e-10);
    EXPECT_LT(errors.nodal, 2e-2);
    return errors;
  };
  // Against samples per edge at the default offset; from 4 samples on the
  // MFS basis is the trilinear one to 1e-3 pointwise.
  const double offset = MfsOptions{}.offset;
  const BasisErrors coarse = row(3, offset);
  for (int samples : {4, 5, 6}) EXPECT_LT(row(samples, offset).trilinear, 1e-3);
  EXPECT_LT(row(8, offset).nodal, 0.1 * coarse.nodal);
  // Against the offset ξ at 4 samples (the paper's 0.1, eq. (12)).
  for (double other : {0.1, 0.15, 0.3, 0.5}) row(4, other);
}

// At every sampling the issue allows (3–5 samples per edge) and 6: the consistency
// correction makes the patch test exact whatever the fit's accuracy.
TEST(HarmonicMethod, PatchTestWithMfsBasesUnderTheMethodsQuadrature) {
  std::printf(
      "[ patch    ] MFS bases, [3,2,2] grid, order 2   samples/edge   interior nodes   max interior force"
      "   rigid translation   affine field on the surface\n");
  for (int samples : {3, 4, 5, 6})
    for (const char* element : {"hex8", "tet4"}) {  // tet4: the six Kuhn tetrahedra of each grid cube
      Scene scene =
          load_scene(std::filesystem::path(ALTFEM_SOURCE_DIR) / "tests/unit/conformance/scenes/free_box.json");
      scene.resolved["discretization"]["harmonic"] = {
          {"convert", {{"mesh", "grid"}, {"element", element}, {"resolution", {3, 2, 2}}}},
          {"basis", "mfs"},
          {"samples_per_edge", samples}};
      const SceneGeometry geometry = load_scene_geometry(scene);
      const auto method = make_harmonic_method(scene, geometry);
      Eigen::Matrix3d strain;
      strain << 0.02, 0.01, -0.005, 0.004, -0.01, 0.006, -0.003, 0.008, 0.015;
      const auto affine = [&](const Eigen::Vector3d& x) -> Eigen::Vector3d { return strain * x; };
      Eigen::VectorXd force, translation_force;
      method->discretization().gradient(method->interpolate(affine), force);
      method->discretization().gradient(method->interpolate([](const Eigen::Vector3d&) -> Eigen::Vector3d {
        return {0.3, -0.2, 0.5};
      }),
                                        translation_force);
      // Interior nodes of the [0,2]×[0,1]×[0,1] box: constant stress puts no force on them.
      const Eigen::VectorXd nodes = method->interpolate([](const Eigen::Vector3d& x) { return x; });
      double interior = 0;
      int interior_nodes = 0;
      for (Eigen::Index node = 0; node < nodes.size() / 3; ++node) {
        const Eigen::Vector3d x = nodes.segment<3>(3 * node);
        if ((x.array() > 1e-9).all() && (x.array() < Eigen::Array3d(2, 1, 1) - 1e-9).all())
          interior = std::max(interior, force.segment<3>(3 * node).cwiseAbs().maxCoeff()), ++interior_nodes;
      }
      const double scale = force.cwiseAbs().maxCoeff();
      // The MFS basis reproduces linear fields exactly (its linear polynomial, eq. (11)),
      // so the embedding carries an affine field to the surface to round-off.
      const Eigen::MatrixXd& vertices = method->embedded_surface().vertices;
      const Eigen::MatrixXd embedded = method->embedded_displacement(method->interpolate(affine));
      const double surface_error = (embedded - vertices * strain.transpose()).cwiseAbs().maxCoeff();
      std::printf("[ patch    ] %-31s %12d   %14d   %18.2e   %17.2e   %27.2e\n", element, samples, interior_nodes,
                  interior / scale, translation_force.cwiseAbs().maxCoeff() / scale, surface_error);
      ASSERT_GT(interior_nodes, 0);
      EXPECT_LT(interior, 1e-10 * scale);
      EXPECT_LT(translation_force.cwiseAbs().maxCoeff(), 1e-12 * scale);
      EXPECT_LT(surface_error, 1e-12);
    }
}

}  // namespace
}  // namespace altfem::harmonic
