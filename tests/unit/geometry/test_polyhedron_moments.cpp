// polyhedron_moments against the box product formula, sums of boxes for non-convex
// rectilinear shapes (L prism, thin-slotted comb), and simplex quadrature over cones for
// rotated star-shaped polyhedra; plus invariances and input validation.
#include "shared/geometry/polyhedron_moments.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <numeric>
#include <random>
#include <stdexcept>

#include "shared/geometry/monomial_index.hpp"
#include "tests/unit/geometry/moments_reference.hpp"

namespace altfem {
namespace {

using test::box;
using test::box_moments;
using test::expect_moments_near;
using test::extrude;
using test::sum_of;

constexpr double tolerance = 1e-12;
constexpr int degree = 10;

Eigen::MatrixXd polygon(std::initializer_list<std::pair<double, double>> points) {
  Eigen::MatrixXd result(points.size(), 2);
  int row = 0;
  for (const auto& [x, y] : points) result.row(row++) << x, y;
  return result;
}

// L = [0,2]×[0,1] ∪ [0,1]×[1,3]: its top and bottom faces are one non-convex hexagon each.
Polyhedron l_prism() { return extrude(polygon({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 3}, {0, 3}}), -0.5, 0.75); }

test::ReferenceMoments l_prism_reference(int degree) {
  return sum_of({box_moments({0, 0, -0.5}, {2, 1, 0.75}, degree), box_moments({0, 1, -0.5}, {1, 3, 0.75}, degree)});
}

// A comb: spine [0,1]×[0,0.2] and `teeth` teeth up to y = 1, separated by thin slots of
// width `gap`; top and bottom are one non-convex face with 4·teeth vertices each.
struct Comb {
  Polyhedron polyhedron;
  test::ReferenceMoments reference;
};

Comb comb(int teeth, double gap, int degree) {
  const double pitch = 1.0 / teeth;
  std::vector<std::pair<double, double>> outline = {{1.0, 0.0}};
  std::vector<test::ReferenceMoments> pieces = {box_moments({0, 0, 0}, {1, 0.2, 0.3}, degree)};
  for (int t = teeth - 1; t >= 0; --t) {
    const double left = t * pitch, right = t == teeth - 1 ? 1.0 : (t + 1) * pitch - gap;
    if (t < teeth - 1) outline.emplace_back(right, 0.2);
    outline.emplace_back(right, 1.0);
    outline.emplace_back(left, 1.0);
    if (t > 0) outline.emplace_back(left, 0.2);
    pieces.push_back(box_moments({left, 0.2, 0}, {right, 1.0, 0.3}, degree));
  }
  outline.emplace_back(0.0, 0.0);
  Eigen::MatrixXd outline_matrix(outline.size(), 2);
  for (std::size_t i = 0; i < outline.size(); ++i) outline_matrix.row(i) << outline[i].first, outline[i].second;
  return {extrude(outline_matrix, 0.0, 0.3), sum_of(pieces)};
}

TEST(PolyhedronMoments, UnitCubeMatchesProductFormula) {
  const Eigen::Vector3d low(0, 0, 0), high(1, 1, 1);
  expect_moments_near(polyhedron_moments(box(low, high), degree), box_moments(low, high, degree), tolerance);
}

TEST(PolyhedronMoments, OffOriginBoxMatchesProductFormula) {
  const Eigen::Vector3d low(1, -2, 0.25), high(3, 0.5, 0.75);
  expect_moments_near(polyhedron_moments(box(low, high), degree), box_moments(low, high, degree), tolerance);
}

TEST(PolyhedronMoments, SmallBoxFarFromOriginKeepsFullAccuracy) {
  const Eigen::Vector3d centre(1000, -500, 20);
  const double half = 0.005;
  const Eigen::Vector3d low = centre.array() - half, high = centre.array() + half;
  expect_moments_near(polyhedron_moments(box(low, high), degree), box_moments(low, high, degree), tolerance);
  // About its own centre and scale: the box [(low − c)/s, (high − c)/s] ≈ [-1,1]³ times the
  // volume scale (low − c is exact in floating point; 1000.005 is not, so not exactly [-1,1]³).
  test::ReferenceMoments unit = box_moments((low - centre) / half, (high - centre) / half, degree);
  unit.exact *= half * half * half;
  unit.absolute *= half * half * half;
  expect_moments_near(polyhedron_moments(box(low, high), degree, centre, half), unit, tolerance);
}

TEST(PolyhedronMoments, AnyDegree) {
  const Eigen::Vector3d low(-0.3, 0.1, -1), high(0.9, 1.4, 0.2);
  expect_moments_near(polyhedron_moments(box(low, high), 16), box_moments(low, high, 16), tolerance);
  EXPECT_EQ(polyhedron_moments(box(low, high), 0).size(), 1);
  EXPECT_NEAR(polyhedron_moments(box(low, high), 0)(0), 1.2 * 1.3 * 1.2, 1e-15);
}

TEST(PolyhedronMoments, TriangulatedFacesGiveTheSameMoments) {
  Polyhedron triangulated = box({1, -2, 0.25}, {3, 0.5, 0.75});
  std::vector<std::vector<int>> triangles;
  for (const std::vector<int>& quad : triangulated.faces) {
    triangles.push_back({quad[0], quad[1], quad[2]});
    triangles.push_back({quad[0], quad[2], quad[3]});
  }
  triangulated.faces = triangles;
  expect_moments_near(polyhedron_moments(triangulated, degree), box_moments({1, -2, 0.25}, {3, 0.5, 0.75}, degree),
                      tolerance);
}

TEST(PolyhedronMoments, NonConvexLPrismMatchesTwoBoxes) {
  expect_moments_near(polyhedron_moments(l_prism(), degree), l_prism_reference(degree), tolerance);
}

TEST(PolyhedronMoments, CombWithThinSlotsMatchesSumOfBoxes) {
  const Comb thin = comb(8, 1e-4, degree);
  expect_moments_near(polyhedron_moments(thin.polyhedron, degree), thin.reference, tolerance);
}

// A bipyramid over a 5-pointed star: non-convex, star-shaped about the origin, with
// triangular faces in generic orientations once rotated and moved off the origin.
Polyhedron star_bipyramid() {
  Polyhedron result;
  const int points = 5;
  result.vertices.resize(2 * points + 2, 3);
  for (int i = 0; i < 2 * points; ++i) {
    const double angle = M_PI * i / points, radius = i % 2 == 0 ? 1.0 : 0.35;
    result.vertices.row(i) << radius * std::cos(angle), radius * std::sin(angle), 0.0;
  }
  result.vertices.row(2 * points) << 0.1, -0.05, 0.8;
  result.vertices.row(2 * points + 1) << -0.05, 0.1, -0.6;
  for (int i = 0; i < 2 * points; ++i) {
    const int j = (i + 1) % (2 * points);
    result.faces.push_back({i, j, 2 * points});
    result.faces.push_back({j, i, 2 * points + 1});
  }
  return result;
}

TEST(PolyhedronMoments, RotatedStarBipyramidMatchesConeQuadrature) {
  const Eigen::Matrix3d rotation = test::generic_rotation();
  const Eigen::Vector3d translation(0.7, -1.2, 0.4);
  const Polyhedron star = test::transformed(star_bipyramid(), rotation, translation);
  expect_moments_near(polyhedron_moments(star, degree), test::cone_quadrature_moments(star, translation, degree),
                      tolerance);
}

TEST(PolyhedronMoments, RotatedStarPrismWithNonConvexFacesMatchesConeQuadrature) {
  Eigen::MatrixXd star(12, 2);
  for (int i = 0; i < 12; ++i) {
    const double angle = M_PI * i / 6, radius = i % 2 == 0 ? 1.0 : 0.5;
    star.row(i) << radius * std::cos(angle), radius * std::sin(angle);
  }
  const Eigen::Vector3d translation(-0.3, 2.0, 1.1);
  const Polyhedron prism = test::transformed(extrude(star, -0.4, 0.6), test::generic_rotation(), translation);
  const Eigen::Vector3d apex = translation + test::generic_rotation() * Eigen::Vector3d(0, 0, 0.1);
  expect_moments_near(polyhedron_moments(prism, degree), test::cone_quadrature_moments(prism, apex, degree), tolerance);
}

// Volume, centroid and second-moment tensor transform as a rigid motion says: a check of
// the thin-slotted comb with no face parallel to a coordinate plane.
TEST(PolyhedronMoments, RotatedCombTransformsItsLowMomentsRigidly) {
  const Comb thin = comb(8, 1e-4, 2);
  const Eigen::Matrix3d rotation = test::generic_rotation();
  const Eigen::Vector3d translation(3.0, -1.0, 2.0);
  const Eigen::VectorXd moved = polyhedron_moments(test::transformed(thin.polyhedron, rotation, translation), 2);
  const Eigen::VectorXd& original = thin.reference.exact;
  const double volume = original(0);
  const Eigen::Vector3d centroid = original.segment<3>(1) / volume;
  Eigen::Matrix3d second;  // ∫ x xᵀ
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      Eigen::Vector3i power = Eigen::Vector3i::Zero();
      ++power(i);
      ++power(j);
      second(i, j) = original(monomial_index(power(0), power(1), power(2)));
    }
  }
  const Eigen::Vector3d moved_centroid = rotation * centroid + translation;
  const Eigen::Matrix3d moved_second = rotation * second * rotation.transpose() +
                                       volume * (moved_centroid * moved_centroid.transpose() -
                                                 rotation * centroid * centroid.transpose() * rotation.transpose());
  EXPECT_NEAR(moved(0), volume, 1e-14 * volume);
  EXPECT_LE((moved.segment<3>(1) / volume - moved_centroid).norm(), 1e-13 * moved_centroid.norm());
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      Eigen::Vector3i power = Eigen::Vector3i::Zero();
      ++power(i);
      ++power(j);
      EXPECT_NEAR(moved(monomial_index(power(0), power(1), power(2))), moved_second(i, j), 1e-13 * moved_second.norm());
    }
  }
}

TEST(PolyhedronMoments, CentredMomentsAreTranslationInvariant) {
  const Polyhedron near = l_prism();
  const Eigen::Vector3d shift(2000.0, -700.0, 1e4), centre(1.0, 1.5, 0.1);
  const Eigen::VectorXd expected = polyhedron_moments(near, degree, centre, 1.5);
  const Eigen::VectorXd far =
      polyhedron_moments(test::transformed(near, Eigen::Matrix3d::Identity(), shift), degree, centre + shift, 1.5);
  // The centred moments lose only the digits the translated vertex coordinates themselves lost.
  EXPECT_LE((far - expected).cwiseAbs().maxCoeff(), 1e-11 * expected.cwiseAbs().maxCoeff());
}

TEST(PolyhedronMoments, InvariantUnderRelabellingAndFaceStart) {
  const Comb thin = comb(5, 1e-3, degree);
  const Polyhedron& original = thin.polyhedron;
  std::mt19937 random(7);
  std::vector<int> permutation(original.vertices.rows());  // new index of each old vertex
  std::iota(permutation.begin(), permutation.end(), 0);
  std::shuffle(permutation.begin(), permutation.end(), random);
  Polyhedron relabelled;
  relabelled.vertices.resize(original.vertices.rows(), 3);
  for (std::size_t v = 0; v < permutation.size(); ++v)
    relabelled.vertices.row(permutation[v]) = original.vertices.row(v);
  for (const std::vector<int>& face : original.faces) {
    std::vector<int> renamed;
    for (const int v : face) renamed.push_back(permutation[v]);
    std::rotate(renamed.begin(), renamed.begin() + random() % renamed.size(), renamed.end());
    relabelled.faces.push_back(renamed);
  }
  std::shuffle(relabelled.faces.begin(), relabelled.faces.end(), random);
  expect_moments_near(polyhedron_moments(relabelled, degree), thin.reference, tolerance);
  expect_moments_near(polyhedron_moments(original, degree), thin.reference, tolerance);
}

TEST(PolyhedronMoments, InsideOutGivesNegatedMoments) {
  Polyhedron inverted = l_prism();
  for (std::vector<int>& face : inverted.faces) std::reverse(face.begin(), face.end());
  test::ReferenceMoments negated = l_prism_reference(4);
  negated.exact = -negated.exact;
  expect_moments_near(polyhedron_moments(inverted, 4), negated, tolerance);
}

TEST(PolyhedronMoments, RejectsBadInput) {
  Polyhedron cube = box({0, 0, 0}, {1, 1, 1});
  EXPECT_THROW(polyhedron_moments(cube, -1), std::invalid_argument);
  EXPECT_THROW(polyhedron_moments(cube, 2, Eigen::Vector3d::Zero(), 0.0), std::invalid_argument);
  Polyhedron out_of_range = cube;
  out_of_range.faces[2][1] = 8;
  EXPECT_THROW(polyhedron_moments(out_of_range, 2), std::invalid_argument);
  Polyhedron negative = cube;
  negative.faces[0][0] = -1;
  EXPECT_THROW(polyhedron_moments(negative, 2), std::invalid_argument);
  Polyhedron too_small = cube;
  too_small.faces[3] = {1, 2};
  EXPECT_THROW(polyhedron_moments(too_small, 2), std::invalid_argument);
  Polyhedron flat = cube;
  flat.vertices = Eigen::MatrixXd::Zero(8, 2);
  EXPECT_THROW(polyhedron_moments(flat, 2), std::invalid_argument);
  Polyhedron not_finite = cube;
  not_finite.vertices(3, 1) = std::nan("");
  EXPECT_THROW(polyhedron_moments(not_finite, 2), std::invalid_argument);
}

}  // namespace
}  // namespace altfem
