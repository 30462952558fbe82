// One rank's share of the assembly (ElasticAssembler::assemble_only, or a share on a
// pattern of its own) and the partition that decides it (partition_elements): the shares
// of disjoint element sets sum to the whole energy, forces and Hessian, and METIS's two
// parts of a grid weigh the same and are each connected, so few basis functions are shared
// across ranks.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <queue>
#include <utility>
#include <vector>

#include "shared/assembly/element_partition.hpp"
#include "shared/solve/graph_partition.hpp"
#include "tests/unit/assembly/assembly_fixture.hpp"

namespace altfem {
namespace {

// Two disjoint shares of `count` elements: the even ones and the odd ones.
std::pair<std::vector<char>, std::vector<char>> even_and_odd_elements(int count) {
  std::vector<char> even(static_cast<size_t>(count)), odd(even.size());
  for (size_t e = 0; e < even.size(); ++e) (e % 2 == 0 ? even : odd)[e] = 1;
  return {even, odd};
}

TEST(AssembleOnly, SharesOfDisjointElementsSumToTheWhole) {
  const test::AssemblyProblem problem(ElementType::hex20, {3, 2, 2}, MaterialModel::neo_hookean);
  const Eigen::VectorXd u = problem.displacement(Eigen::Matrix3d::Identity() * 1.02, 0.05, 3);
  const auto [even, odd] = even_and_odd_elements(problem.elements.size());
  const std::vector<const Material*> materials{problem.material.get()};
  ElasticAssembler first(problem.elements, materials), second(problem.elements, materials);
  first.assemble_only(even);
  second.assemble_only(odd);
  const ElasticAssembler& whole = *problem.assembler;

  EXPECT_NEAR(first.energy(u) + second.energy(u), whole.energy(u), 1e-13 * std::abs(whole.energy(u)));
  Eigen::VectorXd g1, g2, g;
  first.gradient(u, g1);
  second.gradient(u, g2);
  whole.gradient(u, g);
  EXPECT_LE((g1 + g2 - g).lpNorm<Eigen::Infinity>(), 1e-13 * g.lpNorm<Eigen::Infinity>());
  EXPECT_GT(g1.lpNorm<Eigen::Infinity>(), 0.1 * g.lpNorm<Eigen::Infinity>()) << "each share is a real part";
  SparseMatrix h1 = whole.pattern(), h2 = whole.pattern(), h = whole.pattern();
  first.hessian(u, h1);
  second.hessian(u, h2);
  whole.hessian(u, h);
  EXPECT_LE((SparseMatrix(h1 + h2) - h).norm(), 1e-13 * h.norm());
  // The mass stays whole: it is assembled once, on every rank.
  SparseMatrix mass_first, mass_whole;
  first.mass_matrix(mass_first);
  whole.mass_matrix(mass_whole);
  EXPECT_EQ((mass_first - mass_whole).norm(), 0.0);
}

// A share whose matrices a solver sums (ranks::shares_matrices()): each pattern holds only
// its elements' blocks and every function's diagonal block, and the Hessians and masses of
// disjoint shares, on their own patterns, sum to the whole.
TEST(AssembleOnly, ShareMatricesOnTheirOwnPatternsSumToTheWhole) {
  const test::AssemblyProblem problem(ElementType::hex20, {3, 2, 2}, MaterialModel::neo_hookean);
  const Eigen::VectorXd u = problem.displacement(Eigen::Matrix3d::Identity() * 1.02, 0.05, 3);
  const auto [even, odd] = even_and_odd_elements(problem.elements.size());
  const std::vector<const Material*> materials{problem.material.get()};
  const ElasticAssembler first(problem.elements, materials, {}, even), second(problem.elements, materials, {}, odd);
  const ElasticAssembler& whole = *problem.assembler;
  for (const ElasticAssembler* share : {&first, &second}) {
    EXPECT_LT(share->pattern().nonZeros(), whole.pattern().nonZeros());
    EXPECT_EQ(share->pattern().rows(), whole.pattern().rows());
    int diagonals = 0;
    for (Eigen::Index column = 0; column < share->pattern().outerSize(); ++column)
      for (SparseMatrix::InnerIterator entry(share->pattern(), column); entry; ++entry)
        diagonals += entry.row() == column;
    EXPECT_EQ(diagonals, share->pattern().rows());
  }
  SparseMatrix h1 = first.pattern(), h2 = second.pattern(), h = whole.pattern();
  first.hessian(u, h1);
  second.hessian(u, h2);
  whole.hessian(u, h);
  EXPECT_EQ(h1.nonZeros(), first.pattern().nonZeros());
  EXPECT_LE((SparseMatrix(h1 + h2) - h).norm(), 1e-13 * h.norm());
  SparseMatrix m1, m2, m;
  first.mass_matrix(m1);
  second.mass_matrix(m2);
  whole.mass_matrix(m);
  EXPECT_LE((SparseMatrix(m1 + m2) - m).norm(), 1e-14 * m.norm());
}

#ifdef ALTFEM_HAVE_METIS
// Each part of a partition is connected through shared basis functions.
bool connected(const TabulatedElements& elements, const std::vector<int>& part, int which) {
  std::vector<std::vector<int>> holders(static_cast<size_t>(elements.basis_count()));
  for (int e = 0; e < elements.size(); ++e)
    if (part[e] == which)
      for (int basis : elements[e].basis) holders[basis].push_back(e);
  std::vector<char> seen(part.size(), 0);
  const int start = static_cast<int>(std::find(part.begin(), part.end(), which) - part.begin());
  std::queue<int> next;
  next.push(start);
  seen[start] = 1;
  while (!next.empty()) {
    const int e = next.front();
    next.pop();
    for (int basis : elements[e].basis)
      for (int neighbour : holders[basis])
        if (!seen[neighbour]) {
          seen[neighbour] = 1;
          next.push(neighbour);
        }
  }
  for (size_t e = 0; e < part.size(); ++e)
    if (part[e] == which && !seen[e]) return false;
  return true;
}

TEST(PartitionElements, TwoPartsOfAGridWeighTheSameAndAreConnected) {
  const test::AssemblyProblem problem(ElementType::hex8, {8, 4, 4}, MaterialModel::linear);
  const std::vector<int> part = partition_elements(problem.elements, {}, 2);
  ASSERT_EQ(part.size(), 128u);
  const long first = std::count(part.begin(), part.end(), 0);
  // METIS's default imbalance tolerance is 3%; equal elements weigh alike.
  EXPECT_NEAR(static_cast<double>(first), 64.0, 0.03 * 128);
  EXPECT_TRUE(connected(problem.elements, part, 0));
  EXPECT_TRUE(connected(problem.elements, part, 1));
}

// A body a cut has separated: two chains of vertices, no edge between them, partitioned
// into balanced parts (contiguous parts are asked for only of a connected graph).
TEST(PartitionGraph, ADisconnectedGraphIsPartitionedIntoBalancedParts) {
  std::vector<std::vector<int>> adjacent(40);
  for (int v = 0; v + 1 < 40; ++v)
    if (v != 19) adjacent[v].push_back(v + 1), adjacent[v + 1].push_back(v);
  const std::vector<double> work(40, 1.0);
  const std::vector<int> part = partition_graph([&] { return compressed_graph(adjacent); }, work, 2);
  ASSERT_EQ(part.size(), 40u);
  EXPECT_EQ(std::count(part.begin(), part.end(), 0), 20);
}

TEST(PartitionElements, OnePartOrFewElementsNeedNoMetis) {
  const test::AssemblyProblem problem(ElementType::hex8, {2, 1, 1}, MaterialModel::linear);
  EXPECT_EQ(partition_elements(problem.elements, {}, 1), (std::vector<int>{0, 0}));
  EXPECT_EQ(partition_elements(problem.elements, {}, 2), (std::vector<int>{0, 1}));
}
#endif

}  // namespace
}  // namespace altfem
