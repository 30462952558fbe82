// The cell-by-cell certificate that interior penalty's K is positive definite
// (dg/definiteness_certificate.hpp) is sufficient: wherever it holds, K's smallest
// eigenvalue off the rigid motions is positive. Checked against K's dense spectrum over
// penalties from far too small to far larger than needed, on skewed grids, clamped and
// free, with split penalties, partial conditions and two materials. And it is useful: the
// penalty it certifies is within twice the smallest definite one (1.1 to 1.3 times on these grids).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>

#include "dg/definiteness_certificate.hpp"
#include "tests/unit/dg/hex_grid_cells.hpp"
#include "tests/unit/dg/lame_parameters.hpp"

namespace altfem::dg {
namespace {

struct Variant {
  const char* name;
  int degree = 2;
  bool free = false;               // no condition: K keeps the six rigid motions
  bool partial = false;            // the faces z = 0 and z = 1 prescribe x and z only
  double tangential_fraction = 1;  // < 1: Hansbo & Larson's split penalty
  bool two_materials = false;      // a checkerboard of two Lamé pairs
  PenaltyScaling scaling = PenaltyScaling::cell_surface;
};

// The 2 × 2 × 2 grid of [0,1]³ sheared by a fixed affine map (parallelepipeds, planar faces).
test::GridCells skewed_grid(const Variant& variant) {
  test::GridCells grid = test::hex_grid_cells(2);
  Eigen::Matrix3d map;
  map << 1.0, 0.3, -0.2, 0.1, 0.8, 0.25, 0.0, -0.15, 1.3;
  for (Polyhedron& cell : grid.cells) cell.vertices = cell.vertices * map.transpose();
  for (DgFace& face : grid.faces) {
    if (face.plus < 0 && variant.partial && face.normal.z() != 0) face.components = {true, false, true};
    face.polygon = face.polygon * map.transpose();
    face.normal = (map.inverse().transpose() * face.normal).normalized();
    if (face.plus < 0 && variant.free) face.condition = -1;
  }
  return grid;
}

DgLinearSystem build(const Variant& variant, double penalty) {
  const test::GridCells grid = skewed_grid(variant);
  DgSettings settings{variant.degree, Flux::interior_penalty, penalty, lambda, mu};
  settings.scaling = variant.scaling;
  settings.tangential_fraction = variant.tangential_fraction;
  DgCellMaterials materials;
  if (variant.two_materials) {
    materials.materials = {{lambda, mu, 1, penalty, variant.tangential_fraction},
                           {3 * lambda, 0.5 * mu, 1, 2 * penalty, variant.tangential_fraction}};
    for (std::size_t c = 0; c < grid.cells.size(); ++c) materials.ids.push_back(static_cast<int>(c % 3 == 0));
  }
  return {grid.cells, grid.faces, settings, materials};
}

// K's smallest eigenvalue off the rigid motions (a free body's six zero ones), relative to its largest.
double smallest_relative_eigenvalue(const DgLinearSystem& system, bool free) {
  const Eigen::MatrixXd dense(system.stiffness());
  const Eigen::VectorXd values = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(dense).eigenvalues();
  return values[free ? 6 : 0] / values.tail(1)[0];
}

const Variant variants[] = {
    {"k = 2, clamped"},
    {"k = 1, clamped", 1},
    {"k = 3, clamped", 3},
    {"k = 2, free", 2, true},
    {"k = 2, x and z prescribed at z = 0, 1", 2, false, true},
    {"k = 2, split penalty", 2, false, false, 2 * mu / (lambda + 2 * mu)},
    {"k = 2, two materials", 2, false, false, 1, true},
    {"k = 2, face-area scaling", 2, false, false, 1, false, PenaltyScaling::face_area},
};

TEST(DefinitenessCertificate, HoldsOnlyWhereTheStiffnessIsDefinite) {
  for (const Variant& variant : variants) {
    SCOPED_TRACE(variant.name);
    int certified = 0, indefinite = 0;
    for (double penalty = 1.0 / 64; penalty <= 64 * (lambda + 2 * mu); penalty *= 2) {
      const DgLinearSystem system = build(variant, penalty);
      const DefinitenessCertificate certificate = certify_definiteness(system);
      const double smallest = smallest_relative_eigenvalue(system, variant.free);
      if (smallest < 0) ++indefinite;
      if (!certificate.certified) continue;
      ++certified;
      EXPECT_GT(smallest, 1e-12) << "certified at η = " << penalty << " (ratio " << certificate.largest_ratio << ")";
    }
    // The sweep runs from an indefinite K to a certified one.
    EXPECT_GT(indefinite, 0);
    EXPECT_GT(certified, 0);
  }
}

// Every trace term scales with 1/η, so the ratio does: the certificate at one penalty
// tells the smallest penalty it would certify.
TEST(DefinitenessCertificate, RatioScalesInverselyWithThePenalty) {
  for (const Variant& variant : variants) {
    SCOPED_TRACE(variant.name);
    const double ratio = certify_definiteness(build(variant, 10 * mu)).largest_ratio;
    EXPECT_NEAR(certify_definiteness(build(variant, 40 * mu)).largest_ratio, ratio / 4, 1e-12 * ratio);
  }
}

// The smallest definite penalty η* by bisection of K's spectrum, and the smallest
// certified one η_c = η · ratio(η): η* ≤ η_c (soundness, again) and η_c ≤ 2 η*, so the
// default penalties, several times η*, are certified and skip the factorisation.
TEST(DefinitenessCertificate, CertifiesWithinTwiceTheSmallestDefinitePenalty) {
  std::printf("  %-40s %12s %12s %8s\n", "variant", "η*/μ", "η_c/μ", "η_c/η*");
  for (const Variant& variant : variants) {
    SCOPED_TRACE(variant.name);
    double low = 1e-3 * mu, high = 1e3 * mu;  // indefinite, definite
    ASSERT_LT(smallest_relative_eigenvalue(build(variant, low), variant.free), 0);
    ASSERT_GT(smallest_relative_eigenvalue(build(variant, high), variant.free), 0);
    while (high / low > 1.001) {
      const double middle = std::sqrt(low * high);
      (smallest_relative_eigenvalue(build(variant, middle), variant.free) > 0 ? high : low) = middle;
    }
    const double certified = mu * certify_definiteness(build(variant, mu)).largest_ratio;
    std::printf("  %-40s %12.4g %12.4g %8.2f\n", variant.name, high / mu, certified / mu, certified / high);
    EXPECT_GE(certified, low);
    EXPECT_LE(certified, 2 * high);
  }
}

}  // namespace
}  // namespace altfem::dg
