// The patch test under the quadrature actually used: eight harmonic box elements around
// one interior node, a constant stress, a low-strength rule. Without the consistency
// correction the interior node feels a ghost force (the quadrature of ∇N_i misses the
// shared boundary data); with it the force vanishes to round-off. Prints both.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>

#include "polyhedral/harmonic_tabulation.hpp"
#include "tests/unit/polyhedra.hpp"

namespace altfem::harmonic {
namespace {

// The largest force on the centre node of a 2 × 2 × 2 grid of unequal boxes under the
// constant stress σ, relative to the largest force on any node.
double centre_ghost_force(bool consistent, int strength) {
  Eigen::Matrix3d stress;
  stress << 1.0, 0.3, -0.2, 0.3, 2.0, 0.1, -0.2, 0.1, 1.5;
  std::map<int, Eigen::Vector3d> forces;  // global node (i + 3j + 9k) → force
  // Unequal boxes: on eight equal cubes the quadrature errors of the neighbours cancel
  // by symmetry and hide the ghost force.
  const double lines[3][3] = {{0, 0.7, 2}, {0, 1.2, 2}, {0, 0.8, 2}};
  for (int cell = 0; cell < 8; ++cell) {
    const Eigen::Vector3i origin(cell & 1, (cell >> 1) & 1, (cell >> 2) & 1);
    const Eigen::Vector3i end = origin + Eigen::Vector3i::Ones();
    const Polyhedron cube = test::box(Eigen::Vector3d(lines[0][origin.x()], lines[1][origin.y()], lines[2][origin.z()]),
                                      Eigen::Vector3d(lines[0][end.x()], lines[1][end.y()], lines[2][end.z()]));
    std::vector<int> global(8);
    for (int v = 0; v < 8; ++v) {
      const Eigen::Vector3i corner = origin + Eigen::Vector3i(v & 1, (v >> 1) & 1, (v >> 2) & 1);
      global[v] = corner.x() + 3 * corner.y() + 9 * corner.z();
    }
    const ElementHarmonicBasis basis(cube, {});
    const HarmonicTabulation tabulation = tabulate_harmonic_element(basis, polyhedron_rule(cube, strength), consistent);
    for (Eigen::Index q = 0; q < tabulation.weights.size(); ++q)
      for (int v = 0; v < 8; ++v) {
        const Eigen::Vector3d gradient = tabulation.gradients.row(q * 8 + v).transpose();
        forces.try_emplace(global[v], Eigen::Vector3d::Zero()).first->second +=
            tabulation.weights[q] * stress * gradient;
      }
  }
  double largest = 0;
  for (const auto& [node, force] : forces) largest = std::max(largest, force.norm());
  return forces.at(1 + 3 + 9).norm() / largest;
}

TEST(HarmonicPatchTest, ConsistencyCorrectionRemovesGhostForces) {
  std::printf("  %9s %22s %22s\n", "strength", "uncorrected ghost", "corrected ghost");
  for (int strength : {2, 4}) {
    const double uncorrected = centre_ghost_force(false, strength);
    const double corrected = centre_ghost_force(true, strength);
    std::printf("  %9d %22.3e %22.3e\n", strength, uncorrected, corrected);
    EXPECT_GT(uncorrected, 1e-8);
    EXPECT_LT(corrected, 1e-12);
  }
}

TEST(HarmonicPatchTest, CorrectedGradientsStillReproduceLinearFields) {
  // Σ_i x_i ⊗ (∇N_i + c_i) = I at every point of a non-convex L-prism.
  const Polyhedron prism = test::l_prism();
  const ElementHarmonicBasis basis(prism, {});
  const HarmonicTabulation tabulation = tabulate_harmonic_element(basis, polyhedron_rule(prism, 3), true);
  for (Eigen::Index q = 0; q < tabulation.weights.size(); ++q) {
    const Eigen::Matrix3d identity = prism.vertices.transpose() * tabulation.gradients.middleRows(q * 12, 12);
    EXPECT_LT((identity - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-10);
  }
}

}  // namespace
}  // namespace altfem::harmonic
