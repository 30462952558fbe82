#include "shared/geometry/monomial_index.hpp"

#include <stdexcept>
#include <string>

namespace altfem {
namespace {

void require_degree(int degree) {
  if (degree < 0) {
    throw std::invalid_argument("monomial degree: expected >= 0, got " + std::to_string(degree));
  }
}

}  // namespace

Eigen::Matrix<int, Eigen::Dynamic, 3> monomial_exponents(int degree) {
  require_degree(degree);
  Eigen::Matrix<int, Eigen::Dynamic, 3> exponents(monomial_count(degree), 3);
  int row = 0;
  for (int q = 0; q <= degree; ++q) {
    for (int a = q; a >= 0; --a) {
      for (int b = q - a; b >= 0; --b) {
        exponents.row(row++) << a, b, q - a - b;
      }
    }
  }
  return exponents;
}

Eigen::Matrix<int, Eigen::Dynamic, 2> monomial_exponents_2d(int degree) {
  require_degree(degree);
  Eigen::Matrix<int, Eigen::Dynamic, 2> exponents(monomial_count_2d(degree), 2);
  int row = 0;
  for (int q = 0; q <= degree; ++q) {
    for (int a = q; a >= 0; --a) {
      exponents.row(row++) << a, q - a;
    }
  }
  return exponents;
}

}  // namespace altfem
