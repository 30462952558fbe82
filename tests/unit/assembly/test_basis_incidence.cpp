// BasisIncidence is the transpose of the element → basis lists; the gradient sums
// each basis function's slots in the order it gives.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <vector>

#include "shared/assembly/basis_incidence.hpp"
#include "tests/unit/assembly/assembly_fixture.hpp"

namespace altfem {
namespace {

// The element whose packed basis list holds `slot`.
int element_of_slot(const TabulatedElements& elements, long long slot) {
  int low = 0, high = elements.size() - 1;
  while (low < high) {
    const int middle = (low + high + 1) / 2;
    if (elements.basis_offset(middle) <= slot) low = middle;
    else high = middle - 1;
  }
  return low;
}

TEST(BasisIncidence, EverySlotOnceUnderItsBasisFunctionInElementOrder) {
  for (ElementType type : {ElementType::tet10, ElementType::hex20}) {
    const test::AssemblyProblem problem(type, {3, 2, 2}, MaterialModel::linear);
    const TabulatedElements& elements = problem.elements;
    const BasisIncidence incidence(elements);
    long long total = 0;
    for (int e = 0; e < elements.size(); ++e) total += elements[e].basis_count();
    ASSERT_EQ(incidence.slot_count(), total);

    std::vector<int> seen(static_cast<std::size_t>(total), 0);
    for (int basis = 0; basis < elements.basis_count(); ++basis) {
      int previous_element = -1;
      for (long long slot : incidence.slots(basis)) {
        const int e = element_of_slot(elements, slot);
        EXPECT_EQ(elements[e].basis[static_cast<std::size_t>(slot - elements.basis_offset(e))], basis);
        EXPECT_GT(e, previous_element) << "slots of basis " << basis << " are not in element order";
        previous_element = e;
        ++seen[static_cast<std::size_t>(slot)];
      }
    }
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int count) { return count == 1; }));
  }
}

TEST(BasisIncidence, GatherOrderIsAPermutationSortedByMeanElement) {
  const test::AssemblyProblem problem(ElementType::tet10, {4, 3, 2}, MaterialModel::linear);
  const BasisIncidence incidence(problem.elements);
  const std::vector<int>& order = incidence.gather_order();
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  std::vector<int> identity(static_cast<std::size_t>(problem.elements.basis_count()));
  std::iota(identity.begin(), identity.end(), 0);
  EXPECT_EQ(sorted, identity);
  const auto mean_element = [&](int basis) {
    double sum = 0;
    for (long long slot : incidence.slots(basis)) sum += element_of_slot(problem.elements, slot);
    return sum / static_cast<double>(incidence.slots(basis).size());
  };
  for (std::size_t k = 1; k < order.size(); ++k) EXPECT_LE(mean_element(order[k - 1]), mean_element(order[k]));
}

}  // namespace
}  // namespace altfem
