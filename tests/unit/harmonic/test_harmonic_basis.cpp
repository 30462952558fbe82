// Harmonic basis functions by MFS (Martin et al. 2008 §4-5) on single elements: the
// properties the method relies on — partition of unity and exact linear reproduction
// (no ghost forces), the linear basis of a tet and the trilinear basis of a hex
// recovered, kernel centres outside non-convex elements, gradients that differentiate
// the values, more kernels than nodes on a cell of many close nodes — and the C0
// mismatch across a shared face shrinking with more samples.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <Eigen/LU>
#include <algorithm>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "polyhedral/element_harmonic_basis.hpp"
#include "polyhedral/face_harmonic_coordinates.hpp"
#include "polyhedral/harmonic_element_bases.hpp"
#include "shared/mesh/slice_into_polyhedra.hpp"
#include "shared/mesh/surface_mesh.hpp"
#include "shared/quadrature/polyhedron_rule.hpp"
#include "tests/unit/polyhedra.hpp"

namespace altfem::harmonic {
namespace {

using test::l_prism;

Polyhedron unit_cube() { return test::box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()); }

Polyhedron tetrahedron() {
  Polyhedron tet;
  tet.vertices.resize(4, 3);
  tet.vertices << 0, 0, 0, 1.2, 0.1, 0, 0.2, 0.9, 0.1, 0.3, 0.2, 1.1;
  tet.faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  return tet;
}

// Random points with winding number ≈ 1 (#points × 3).
Eigen::MatrixXd interior_points(const Polyhedron& polyhedron, int count, unsigned seed) {
  std::mt19937 random(seed);
  const Eigen::Vector3d low = polyhedron.vertices.colwise().minCoeff(), high = polyhedron.vertices.colwise().maxCoeff();
  std::uniform_real_distribution<double> uniform(0, 1);
  Eigen::MatrixXd points(count, 3);
  for (int p = 0; p < count;) {
    const Eigen::Vector3d x =
        low + (high - low).cwiseProduct(Eigen::Vector3d(uniform(random), uniform(random), uniform(random)));
    if (winding_number(polyhedron, x) > 0.5) points.row(p++) = x.transpose();
  }
  return points;
}

class EveryShape : public ::testing::TestWithParam<int> {
protected:
  static Polyhedron shape() { return GetParam() == 0 ? unit_cube() : GetParam() == 1 ? tetrahedron() : l_prism(); }
};

TEST_P(EveryShape, PartitionOfUnityAndLinearReproductionToRoundOff) {
  const Polyhedron element = shape();
  const ElementHarmonicBasis basis(element, {});
  const Eigen::MatrixXd points = interior_points(element, 200, 3);
  const Eigen::MatrixXd values = basis.values(points);
  EXPECT_LT((values.rowwise().sum().array() - 1.0).abs().maxCoeff(), 1e-10);
  EXPECT_LT((values * element.vertices - points).cwiseAbs().maxCoeff(), 1e-10);
}

// The partition of unity ≤ 1e-10 on the cut cells of the bunny sliced at 16³,
// many-faceted and non-convex, at their rule points. Both it and linear reproduction are
// exact in the coefficients (restored after the solve) but evaluated through large kernel
// weights that cancel, so what is left is the evaluation's round-off, which depends on
// the order of the products' sums and so on the instruction set of a -march=native
// build: on a Zen 4 EPYC 1.4e-10 (linear 1.4e-9 of the cell size), and 9.4e-11 (9.5e-10)
// with element_harmonic_basis.cpp alone compiled again with -mno-avx512f (by hand). So the
// bound is 2e-10, and 1e-8 for linear reproduction (the patch test does not depend on
// either: the consistency correction makes it exact).
TEST(HarmonicBasis, CutCellsReproduceAffineFieldsToRoundOff) {
  SlicingOptions slicing;
  slicing.resolution = 16;
  const PolyhedralMesh mesh =
      slice_into_polyhedra(read_surface(std::string(ALTFEM_SOURCE_DIR) + "/data/surface/bunny_npm.off"), slicing).mesh;
  const HarmonicElementBases bases(mesh, HarmonicBasisKind::automatic, {});
  int cut_cells = 0;
  double unity = 0, linear = 0;
  for (int cell = 0; cell < mesh.cell_count(); ++cell) {
    const ElementHarmonicBasis* basis = bases.mfs_basis(cell);
    if (!basis) continue;
    ++cut_cells;
    const Polyhedron element = cell_polyhedron(mesh, cell);
    const Eigen::MatrixXd points = polyhedron_rule(element, 2).points;
    const Eigen::MatrixXd values = basis->values(points);
    const double size = (element.vertices.colwise().maxCoeff() - element.vertices.colwise().minCoeff()).norm();
    unity = std::max(unity, (values.rowwise().sum().array() - 1.0).abs().maxCoeff());
    linear = std::max(linear, (values * element.vertices - points).cwiseAbs().maxCoeff() / size);
  }
  std::printf("[ affine   ] %d cut cells: max |ΣN − 1| %.2e, max |Σ x_i N_i − x| / size %.2e\n", cut_cells, unity,
              linear);
  EXPECT_GT(cut_cells, 500);
  EXPECT_LT(unity, 2e-10);
  EXPECT_LT(linear, 1e-8);
}

TEST_P(EveryShape, KernelCentresLieOutside) {
  const Polyhedron element = shape();
  const ElementHarmonicBasis basis(element, {});
  const Eigen::MatrixXd centres = basis.centres();
  ASSERT_GT(centres.rows(), element.vertices.rows());
  for (Eigen::Index j = 0; j < centres.rows(); ++j) EXPECT_LT(winding_number(element, centres.row(j).transpose()), 0.5);
}

TEST_P(EveryShape, GradientsDifferentiateTheValues) {
  const Polyhedron element = shape();
  const ElementHarmonicBasis basis(element, {});
  const Eigen::MatrixXd points = interior_points(element, 20, 5);
  Eigen::VectorXd values, plus, minus;
  Eigen::MatrixXd gradients, unused;
  const double h = 1e-6;
  for (Eigen::Index p = 0; p < points.rows(); ++p) {
    const Eigen::Vector3d x = points.row(p).transpose();
    basis.evaluate(x, values, gradients);
    for (int d = 0; d < 3; ++d) {
      basis.evaluate(x + h * Eigen::Vector3d::Unit(d), plus, unused);
      basis.evaluate(x - h * Eigen::Vector3d::Unit(d), minus, unused);
      EXPECT_LT(((plus - minus) / (2 * h) - gradients.col(d)).cwiseAbs().maxCoeff(), 1e-6);
    }
  }
}

// The values alone (one product of the kernel row with the coefficients) are the values
// evaluated with the gradients (a sum over the kernels), and those of the batched form.
TEST_P(EveryShape, ValuesAloneAreTheValuesWithGradients) {
  const Polyhedron element = shape();
  const ElementHarmonicBasis basis(element, {});
  const Eigen::MatrixXd points = interior_points(element, 20, 5);
  const Eigen::MatrixXd batched = basis.values(points);
  Eigen::VectorXd alone, with_gradients;
  Eigen::MatrixXd gradients;
  for (Eigen::Index p = 0; p < points.rows(); ++p) {
    basis.evaluate(points.row(p).transpose(), alone);
    basis.evaluate(points.row(p).transpose(), with_gradients, gradients);
    EXPECT_LT((alone - with_gradients).cwiseAbs().maxCoeff(), 1e-13);
    EXPECT_LT((alone - batched.row(p).transpose()).cwiseAbs().maxCoeff(), 1e-13);
  }
}

// N_i(x_j) = δ_ij holds to the fit's accuracy: tightly on convex elements, and on the
// non-convex L-prism (whose re-entrant edge makes the exact functions singular there)
// improving with more samples. The sample spacing comes from the element's area, which
// for the L-prism is 1.24 times coarser than from its mean edge length (the spacing
// before): its 10 samples per edge sample about as finely as 8 did then.
TEST_P(EveryShape, InterpolatesTheNodesToTheFitsAccuracy) {
  const Polyhedron element = shape();
  const Eigen::Index n = element.vertices.rows();
  std::vector<double> errors;
  for (int samples : {3, 4, 5, 6, 10}) {
    MfsOptions options;
    options.edge_samples = samples;
    const ElementHarmonicBasis basis(element, options);
    errors.push_back((basis.values(element.vertices) - Eigen::MatrixXd::Identity(n, n)).cwiseAbs().maxCoeff());
    std::printf("  %d edge samples: max |N_i(x_j) - delta_ij| %.2e (boundary RMS misfit %.2e)\n", samples,
                errors.back(), basis.boundary_residual());
  }
  if (GetParam() == 2) {
    EXPECT_LT(errors[4], errors[0]);
    EXPECT_LT(errors[4], 0.1);
  } else {
    EXPECT_LT(errors[1], 1e-3);  // 4 samples per edge, the default (5.7e-4 on the cube)
  }
}

INSTANTIATE_TEST_SUITE_P(HarmonicBasis, EveryShape, ::testing::Values(0, 1, 2), [](const auto& info) {
  return std::string(info.param == 0 ? "cube" : info.param == 1 ? "tet" : "l_prism");
});

// A cell with more nodes than its area's spacing gives kernels (a cut cell of a detailed
// surface: facet vertices close together), here a prism over a 120-gon with fanned caps
// (242 nodes). Kernels merged within half a spacing left such a cell fewer kernels than
// nodes, so its functions spanned fewer dimensions than it has nodes: the sliced tube's
// cells gave combinations of nodal values without energy (tests/verify/harmonic,
// SlicedTube). The spacing shrinks until the kernels outnumber the nodes, and the basis
// keeps its partition of unity and linear reproduction: exact in its coefficients, and
// evaluated through kernel weights that cancel over 402 nodes: measured 1.5e-9. (Hats
// narrower than the kernels' offset still fit poorly: more kernels at the same offset do
// not resolve them.)
TEST(HarmonicBasis, ACellOfManyCloseNodesGetsMoreKernelsThanNodes) {
  const int sides = 200;
  std::vector<Eigen::Vector2d> circle;
  for (int k = 0; k < sides; ++k) circle.emplace_back(std::cos(2 * M_PI * k / sides), std::sin(2 * M_PI * k / sides));
  Polyhedron element = test::prism(circle, 0.3);
  element.vertices.conservativeResize(2 * sides + 2, 3);
  element.vertices.row(2 * sides) << 0, 0, 0;
  element.vertices.row(2 * sides + 1) << 0, 0, 0.3;
  element.faces.erase(element.faces.begin(), element.faces.begin() + 2);  // the caps, fanned instead
  for (int k = 0; k < sides; ++k) {
    element.faces.push_back({2 * sides, (k + 1) % sides, k});
    element.faces.push_back({2 * sides + 1, sides + k, sides + (k + 1) % sides});
  }
  const Eigen::Index n = element.vertices.rows();
  const ElementHarmonicBasis basis(element, MfsOptions{});
  EXPECT_GE(basis.centres().rows() + 4, n);
  const Eigen::MatrixXd points = interior_points(element, 200, 5);
  const Eigen::MatrixXd values = basis.values(points);
  EXPECT_LT((values.rowwise().sum().array() - 1.0).abs().maxCoeff(), 3e-9);
  EXPECT_LT((values * element.vertices - points).cwiseAbs().maxCoeff(), 3e-9);
}

TEST(HarmonicBasis, IsTheBarycentricBasisOnATetrahedron) {
  const Polyhedron tet = tetrahedron();
  const ElementHarmonicBasis basis(tet, {});
  const Eigen::MatrixXd points = interior_points(tet, 100, 7);
  // Barycentric coordinates: solve [x_1 - x_0, x_2 - x_0, x_3 - x_0] λ = x - x_0.
  Eigen::Matrix3d edges;
  for (int k = 0; k < 3; ++k) edges.col(k) = (tet.vertices.row(k + 1) - tet.vertices.row(0)).transpose();
  const Eigen::MatrixXd values = basis.values(points);
  for (Eigen::Index p = 0; p < points.rows(); ++p) {
    const Eigen::Vector3d lambda = edges.inverse() * (points.row(p) - tet.vertices.row(0)).transpose();
    Eigen::Vector4d expected(1 - lambda.sum(), lambda.x(), lambda.y(), lambda.z());
    EXPECT_LT((values.row(p).transpose() - expected).cwiseAbs().maxCoeff(), 1e-9);
  }
}

TEST(HarmonicBasis, MatchesTheTrilinearBasisOnAHexahedron) {
  const Polyhedron cube = unit_cube();
  const ElementHarmonicBasis basis(cube, {});
  const Eigen::MatrixXd points = interior_points(cube, 300, 9);
  const Eigen::MatrixXd values = basis.values(points);
  double worst = 0;
  for (Eigen::Index p = 0; p < points.rows(); ++p)
    for (int v = 0; v < 8; ++v) {
      const Eigen::Vector3d x = points.row(p).transpose();
      const double trilinear =
          (v & 1 ? x.x() : 1 - x.x()) * ((v >> 1) & 1 ? x.y() : 1 - x.y()) * ((v >> 2) & 1 ? x.z() : 1 - x.z());
      worst = std::max(worst, std::abs(values(p, v) - trilinear));
    }
  std::printf("  max |N - trilinear| on the unit cube: %.2e\n", worst);
  EXPECT_LT(worst, 1e-3);
}

TEST(HarmonicBasis, FaceCoordinatesReproduceLinearFieldsOnANonConvexPolygon) {
  const Polyhedron prism = l_prism();
  Eigen::MatrixXd polygon(6, 3);
  for (int k = 0; k < 6; ++k) polygon.row(k) = prism.vertices.row(k);
  const FaceHarmonicCoordinates face(polygon, {});
  Eigen::MatrixXd points(3, 3);
  points << 0.5, 0.5, 0, 1.5, 0.5, 0, 0.5, 1.5, 0;
  const Eigen::MatrixXd values = face.evaluate(points);
  EXPECT_LT((values.rowwise().sum().array() - 1.0).abs().maxCoeff(), 1e-10);
  EXPECT_LT((values * polygon - points).cwiseAbs().maxCoeff(), 1e-10);
}

// gradients() against central differences of evaluate(), on a tilted non-convex polygon
// (so the plane's frame and scale matter), and Σ_i x_i ⊗ ∇N_i is the in-plane projector.
TEST(HarmonicBasis, FaceCoordinateGradientsMatchFiniteDifferences) {
  const Polyhedron prism = l_prism();
  const Eigen::Matrix3d tilt = Eigen::AngleAxisd(0.6, Eigen::Vector3d(1, 2, 0.3).normalized()).toRotationMatrix();
  Eigen::MatrixXd polygon(6, 3);
  for (int k = 0; k < 6; ++k) polygon.row(k) = 1.7 * prism.vertices.row(k) * tilt.transpose();
  const FaceHarmonicCoordinates face(polygon, {});
  const Eigen::Vector3d point = tilt * Eigen::Vector3d(1.7 * 0.6, 1.7 * 1.3, 0);
  const Eigen::Vector3d along[2] = {tilt.col(0), tilt.col(1)};
  const Eigen::MatrixX3d gradients = face.gradients(point);
  const double step = 1e-6;
  for (const Eigen::Vector3d& direction : along) {
    const Eigen::VectorXd difference =
        (face.evaluate((point + step * direction).transpose()) - face.evaluate((point - step * direction).transpose()))
            .transpose() /
        (2 * step);
    EXPECT_LT((gradients * direction - difference).cwiseAbs().maxCoeff(), 1e-7);
  }
  const Eigen::Vector3d normal = tilt.col(2);
  const Eigen::Matrix3d projector = Eigen::Matrix3d::Identity() - normal * normal.transpose();
  EXPECT_LT((polygon.transpose() * gradients - projector).cwiseAbs().maxCoeff(), 1e-9);
}

// Two wedges sharing the diagonal face of a sheared cube: the C0 mismatch on that face
// is the L2 difference of the two sides' traces (Martin et al. §5: about 2-3% with 5
// samples per edge), and it shrinks with more samples.
TEST(HarmonicBasis, MismatchAcrossASharedFaceShrinksWithMoreSamples) {
  Polyhedron first, second;
  Eigen::MatrixXd vertices(6, 3);
  vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1.2;
  first.vertices = vertices;  // wedge 0-1-2 / 3-4-5
  first.faces = {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {0, 3, 5, 2}, {1, 2, 5, 4}};
  second.vertices.resize(6, 3);
  second.vertices << 1, 0, 0, 1, 1, 0, 0, 1, 0, 1, 0, 1, 1, 1, 1.1, 0, 1, 1.2;  // wedge 1-b-2 / 4-e-5
  second.faces = {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {0, 3, 5, 2}};
  // The shared quad 1-2-5-4 of the first is 0-2-5-3 of the second: nodes 1, 2, 4, 5 ↔ 0, 2, 3, 5.
  const int shared_first[4] = {1, 2, 4, 5}, shared_second[4] = {0, 2, 3, 5};
  std::printf("  %12s %18s\n", "edge samples", "rel. L2 mismatch");
  double previous = INFINITY, first_mismatch = 0;
  for (int samples : {3, 5, 8}) {
    MfsOptions options;
    options.edge_samples = samples;
    const ElementHarmonicBasis left(first, options), right(second, options);
    // Points of the shared quad, bilinear in its corners 1, 2, 5, 4.
    Eigen::MatrixXd points(0, 3);
    for (int i = 1; i < 20; ++i)
      for (int j = 1; j < 20; ++j) {
        const double s = i / 20.0, t = j / 20.0;
        const Eigen::RowVector3d x = (1 - s) * (1 - t) * vertices.row(1) + s * (1 - t) * vertices.row(2) +
                                     s * t * vertices.row(5) + (1 - s) * t * vertices.row(4);
        points.conservativeResize(points.rows() + 1, 3);
        points.row(points.rows() - 1) = x;
      }
    const Eigen::MatrixXd a = left.values(points), b = right.values(points);
    double difference = 0, norm = 0;
    for (int k = 0; k < 4; ++k) {
      difference += (a.col(shared_first[k]) - b.col(shared_second[k])).squaredNorm();
      norm += a.col(shared_first[k]).squaredNorm();
    }
    const double mismatch = std::sqrt(difference / norm);
    std::printf("  %12d %18.3e\n", samples, mismatch);
    if (samples == 3) first_mismatch = mismatch;
    previous = mismatch;
  }
  EXPECT_LT(previous, first_mismatch);
  EXPECT_LT(previous, 0.03);
}

}  // namespace
}  // namespace altfem::harmonic
