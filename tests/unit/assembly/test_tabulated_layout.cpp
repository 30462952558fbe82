// A tabulation laid out first and then filled element by element (TabulatedElements::lay_out,
// slots: what tabulate_lagrange does, from several threads) is the one add() appends: the same
// views bit for bit, offsets, counts and share flags.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <vector>

#include "shared/assembly/tabulated_elements.hpp"

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

}  // namespace
}  // namespace altfem
