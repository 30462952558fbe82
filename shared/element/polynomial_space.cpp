#include "shared/element/polynomial_space.hpp"

namespace altfem {

namespace {
/// Total degree of the monomial once every variable that appears linearly is
/// ignored (Arnold & Awanou 2011, §2): the serendipity space S_r is all
/// monomials of superlinear degree ≤ r.
int superlinear_degree(const Eigen::Vector3i& exponent) {
  int degree = 0;
  for (int d = 0; d < 3; ++d)
    if (exponent[d] >= 2) degree += exponent[d];
  return degree;
}

bool in_space(ElementType type, const Eigen::Vector3i& exponent) {
  const int k = element_degree(type);
  switch (type) {
    case ElementType::tet4:
    case ElementType::tet10:
    case ElementType::tet20: return exponent.sum() <= k;
    case ElementType::hex8:
    case ElementType::hex27: return exponent.maxCoeff() <= k;
    case ElementType::hex20: return exponent.maxCoeff() <= k && superlinear_degree(exponent) <= k;
  }
  return false;
}
}  // namespace

std::vector<Eigen::Vector3i> polynomial_space_exponents(ElementType type) {
  const int k = element_degree(type);
  std::vector<Eigen::Vector3i> exponents;
  for (int a = 0; a <= k; ++a)
    for (int b = 0; b <= k; ++b)
      for (int c = 0; c <= k; ++c)
        if (const Eigen::Vector3i exponent(a, b, c); in_space(type, exponent)) exponents.push_back(exponent);
  return exponents;
}

}  // namespace altfem
