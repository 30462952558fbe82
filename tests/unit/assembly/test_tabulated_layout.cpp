// A tabulation laid out first and then filled element by element (TabulatedElements::lay_out,
// slots: what tabulate_lagrange does, from several threads) is the one add() appends: the same
// views bit for bit, offsets, counts and share flags.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <set>
#include <stdexcept>
#include <vector>

#include "shared/assembly/tabulated_elements.hpp"
#include "shared/fem/tabulate_lagrange.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/quadrature/reference_rules.hpp"

namespace altfem {
namespace {

struct Element {
  std::vector<int> basis;
  Eigen::VectorXd weights;
  Eigen::MatrixXd values, gradients;
  int material = 0;
  bool held = true;
};

// Elements of different sizes, one of them held by another rank.
std::vector<Element> elements() {
  std::vector<Element> result;
  std::srand(7);
  const int sizes[][2] = {{4, 3}, {8, 5}, {20, 1}, {4, 7}};
  for (int e = 0; e < 4; ++e) {
    Element element;
    const int basis = sizes[e][0], points = sizes[e][1];
    for (int a = 0; a < basis; ++a) element.basis.push_back(3 * a + e);
    element.weights = Eigen::VectorXd::Random(points).cwiseAbs();
    element.values = Eigen::MatrixXd::Random(points, basis);
    element.gradients = Eigen::MatrixXd::Random(points * basis, 3);
    element.material = e % 2;
    element.held = e != 2;
    result.push_back(element);
  }
  return result;
}

TEST(TabulatedLayout, ALaidOutTabulationFilledBySlotsIsTheAppendedOne) {
  const std::vector<Element> input = elements();
  TabulatedElements appended, laid_out;
  for (const Element& element : input) {
    if (element.held)
      appended.add(element.basis, std::span<const double>(element.weights.data(), element.weights.size()),
                   element.values, element.gradients, element.material);
    else appended.add_held_elsewhere(element.basis, static_cast<int>(element.weights.size()), element.material);
  }
  laid_out.lay_out(static_cast<int>(input.size()), [&](int e) {
    return ElementLayout{input[e].basis, static_cast<int>(input[e].weights.size()), input[e].material, input[e].held};
  });
  for (int e = static_cast<int>(input.size()) - 1; e >= 0; --e) {  // in any order
    if (!input[e].held) continue;
    ElementSlots slots = laid_out.slots(e);
    ASSERT_EQ(slots.weights.size(), static_cast<size_t>(input[e].weights.size()));
    std::copy(input[e].weights.begin(), input[e].weights.end(), slots.weights.begin());
    slots.values = input[e].values;
    slots.gradients = input[e].gradients;
  }
  EXPECT_TRUE(laid_out.is_share());
  EXPECT_EQ(laid_out.size(), appended.size());
  EXPECT_EQ(laid_out.point_count(), appended.point_count());
  EXPECT_EQ(laid_out.whole_point_count(), appended.whole_point_count());
  EXPECT_EQ(laid_out.basis_count(), appended.basis_count());
  EXPECT_EQ(laid_out.max_element_basis(), appended.max_element_basis());
  for (int e = 0; e < appended.size(); ++e) {
    const ElementView a = appended[e], b = laid_out[e];
    EXPECT_EQ(laid_out.holds(e), appended.holds(e)) << e;
    EXPECT_EQ(laid_out.whole_point_count(e), appended.whole_point_count(e)) << e;
    EXPECT_EQ(laid_out.basis_offset(e), appended.basis_offset(e)) << e;
    EXPECT_TRUE(std::equal(a.basis.begin(), a.basis.end(), b.basis.begin(), b.basis.end())) << e;
    EXPECT_TRUE(std::equal(a.weights.begin(), a.weights.end(), b.weights.begin(), b.weights.end())) << e;
    EXPECT_EQ(a.values, b.values) << e;
    EXPECT_TRUE(std::equal(a.gradients, a.gradients + 3 * a.values.size(), b.gradients)) << e;
    EXPECT_EQ(a.material, b.material) << e;
  }
}

// Elements that share an earlier element's points (a grid's equal cells) read its data,
// count their own points, and keep sharing one copy in a rank's share (keep_only).
TEST(TabulatedLayout, ElementsSharingPointsReadTheFirstsDataAndKeepSharingInAShare) {
  const std::vector<Element> input = elements();
  const Element& first = input[0];  // 4 functions, 3 points
  const std::vector<int> other_basis{40, 41, 42, 43};
  TabulatedElements laid_out;
  laid_out.lay_out(4, [&](int e) {
    if (e == 1) return ElementLayout{input[1].basis, static_cast<int>(input[1].weights.size()), 1, true};
    return ElementLayout{e == 0 ? first.basis : other_basis, static_cast<int>(first.weights.size()), e, true,
                         e == 0 ? -1 : 0};
  });
  for (const int e : {0, 1}) {
    ElementSlots slots = laid_out.slots(e);
    std::copy(input[e].weights.begin(), input[e].weights.end(), slots.weights.begin());
    slots.values = input[e].values;
    slots.gradients = input[e].gradients;
  }
  EXPECT_EQ(laid_out.point_count(), 3 * first.weights.size() + input[1].weights.size());
  EXPECT_EQ(laid_out.whole_point_count(), laid_out.point_count());
  for (const int e : {2, 3}) {
    const ElementView view = laid_out[e];
    EXPECT_TRUE(std::equal(view.basis.begin(), view.basis.end(), other_basis.begin(), other_basis.end()));
    EXPECT_EQ(view.material, e);
    EXPECT_EQ(view.weights.data(), laid_out[0].weights.data());
    EXPECT_EQ(view.values, first.values);
    EXPECT_EQ(laid_out.whole_point_offset(e), laid_out.whole_point_offset(e - 1) + laid_out[e - 1].point_count());
  }
  // A share holding two of the three equal elements keeps one copy of their points.
  TabulatedElements share = laid_out;
  share.keep_only(std::vector<char>{0, 1, 1, 1});
  EXPECT_EQ(share.point_count(), 2 * first.weights.size() + input[1].weights.size());
  EXPECT_EQ(share[0].point_count(), 0);
  EXPECT_EQ(share[2].weights.data(), share[3].weights.data());
  EXPECT_EQ(share[3].values, first.values);
  EXPECT_TRUE(std::equal(share[1].weights.begin(), share[1].weights.end(), input[1].weights.begin()));

  TabulatedElements refused;
  EXPECT_THROW(
      refused.lay_out(
          2,
          [&](int e) {
            return ElementLayout{input[e].basis, static_cast<int>(input[e].weights.size()), 0, true, e == 1 ? 0 : -1};
          }),
      std::invalid_argument);  // element 1 has other sizes than element 0
}

// tabulate_lagrange tabulates a grid's equal cells once (TabulatedElements' same_points_as):
// each cell's view is bit for bit the one it gets with a rule of its own, which is never
// shared.
TEST(TabulatedLayout, AGridsEqualCellsShareOneTabulationEqualToTheirOwn) {
  const VolumeMesh mesh =
      structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d(0.1, -0.3, 0.7), Eigen::Vector3d(1.3, 0.5, 1.1)), {4, 3, 2},
                      ElementType::hex20);
  const QuadratureRule rule = hex_rule(4);
  const TabulatedElements shared = tabulate_lagrange(mesh, LagrangeCellRules{rule, {}, {}});
  LagrangeCellRules own{rule, {}, {}};
  for (int cell = 0; cell < mesh.cells.rows(); ++cell) own.custom.emplace(cell, rule);
  const TabulatedElements separate = tabulate_lagrange(mesh, own);
  std::set<const double*> copies;
  ASSERT_EQ(shared.size(), separate.size());
  EXPECT_EQ(shared.point_count(), separate.point_count());
  for (int e = 0; e < shared.size(); ++e) {
    const ElementView a = shared[e], b = separate[e];
    copies.insert(a.weights.data());
    EXPECT_TRUE(std::equal(a.basis.begin(), a.basis.end(), b.basis.begin(), b.basis.end())) << e;
    EXPECT_TRUE(std::equal(a.weights.begin(), a.weights.end(), b.weights.begin(), b.weights.end())) << e;
    EXPECT_EQ(a.values, b.values) << e;
    EXPECT_TRUE(std::equal(a.gradients, a.gradients + 3 * a.values.size(), b.gradients)) << e;
  }
  EXPECT_LT(copies.size(), static_cast<size_t>(shared.size()) / 2);
}

}  // namespace
}  // namespace altfem
