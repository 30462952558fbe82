// One rank's share of a tabulation (docs/scaling.md): the elements it tabulates
// (tabulate_lagrange with `here`) or keeps (TabulatedElements::keep_only) are the whole
// tabulation's bit for bit, the others keep their basis lists and point counts without
// their points, and what the masses give — the lumped mass, M v, the body-force load —
// sums over disjoint shares to the whole's.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "shared/assembly/element_masses.hpp"
#include "shared/quadrature/reference_rules.hpp"
#include "tests/unit/assembly/assembly_fixture.hpp"

namespace altfem {
namespace {

bool same_element(const ElementView& a, const ElementView& b) {
  return std::equal(a.basis.begin(), a.basis.end(), b.basis.begin(), b.basis.end()) &&
         std::equal(a.weights.begin(), a.weights.end(), b.weights.begin(), b.weights.end()) && a.values == b.values &&
         std::equal(a.gradients, a.gradients + 3 * a.values.size(), b.gradients) && a.material == b.material;
}

TEST(TabulatedShare, HeldElementsAreTheWholesAndTheOthersKeepTheirBasisAndPointCount) {
  const test::AssemblyProblem problem(ElementType::hex20, {3, 2, 2}, MaterialModel::linear);
  const TabulatedElements& whole = problem.elements;
  const auto even = [](int e) { return e % 2 == 0; };
  const TabulatedElements tabulated = tabulate_lagrange(problem.mesh, LagrangeCellRules{hex_rule(4), {}, {}}, even);
  TabulatedElements kept = whole;
  std::vector<char> keep(static_cast<size_t>(whole.size()));
  for (int e = 0; e < whole.size(); ++e) keep[e] = even(e);
  kept.keep_only(keep);
  EXPECT_FALSE(whole.is_share());
  for (const TabulatedElements* share : std::vector<const TabulatedElements*>{&tabulated, &kept}) {
    EXPECT_TRUE(share->is_share());
    ASSERT_EQ(share->size(), whole.size());
    EXPECT_EQ(share->whole_point_count(), whole.point_count());
    EXPECT_LT(share->point_count(), whole.point_count());
    EXPECT_EQ(share->basis_count(), whole.basis_count());
    for (int e = 0; e < whole.size(); ++e) {
      EXPECT_EQ(share->holds(e), even(e)) << e;
      EXPECT_EQ(share->whole_point_count(e), whole[e].point_count()) << e;
      EXPECT_EQ(share->whole_point_offset(e), whole.whole_point_offset(e)) << e;
      const ElementView element = (*share)[e];
      EXPECT_TRUE(std::equal(element.basis.begin(), element.basis.end(), whole[e].basis.begin(), whole[e].basis.end()));
      if (even(e)) {
        EXPECT_TRUE(same_element(element, whole[e])) << e;
      } else {
        EXPECT_EQ(element.point_count(), 0) << e;
      }
    }
  }
}

TEST(TabulatedShare, MassesOfDisjointSharesSumToTheWholes) {
  const test::AssemblyProblem problem(ElementType::hex20, {3, 2, 2}, MaterialModel::linear);
  const LagrangeCellRules rules{hex_rule(4), {}, {}};
  const TabulatedElements even = tabulate_lagrange(problem.mesh, rules, [](int e) { return e % 2 == 0; });
  const TabulatedElements odd = tabulate_lagrange(problem.mesh, rules, [](int e) { return e % 2 == 1; });
  const std::vector<const Material*> materials{problem.material.get()};
  const ElasticAssembler even_assembler(even, materials), odd_assembler(odd, materials);
  const ElementMasses even_masses = element_masses(even), odd_masses = element_masses(odd);
  const ElementMasses whole_masses = element_masses(problem.elements);
  const ElasticAssembler& whole = *problem.assembler;
  const Eigen::VectorXd v = problem.displacement(Eigen::Matrix3d::Identity() * 1.1, 0.3, 5);
  const Eigen::Vector3d gravity(0.5, -9.81, 2.0);
  const auto near = [](const Eigen::VectorXd& sum, const Eigen::VectorXd& expected) {
    return (sum - expected).lpNorm<Eigen::Infinity>() <= 1e-13 * expected.lpNorm<Eigen::Infinity>();
  };
  EXPECT_TRUE(near(even_assembler.lumped_mass(even_masses) + odd_assembler.lumped_mass(odd_masses),
                   whole.lumped_mass(whole_masses)));
  EXPECT_TRUE(near(even_assembler.mass_times(even_masses, v) + odd_assembler.mass_times(odd_masses, v),
                   whole.mass_times(whole_masses, v)));
  EXPECT_TRUE(near(even_assembler.body_force(even_masses, gravity) + odd_assembler.body_force(odd_masses, gravity),
                   whole.body_force(whole_masses, gravity)));
  EXPECT_GT(even_assembler.lumped_mass(even_masses).lpNorm<Eigen::Infinity>(), 0) << "each share is a real part";
}

}  // namespace
}  // namespace altfem
