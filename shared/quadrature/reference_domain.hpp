#pragma once
// The reference domains altfem integrates on. Hexahedra and quadrilaterals are
// [-1,1]^d; simplices are the UNIT simplices {x_i >= 0, Σ x_i <= 1}, which is how
// altfem's Lagrange tets are parametrised (barycentric-friendly, VTK-style).
#include <Eigen/Core>

#include <string_view>

namespace altfem {

enum class ReferenceDomain { quadrilateral, triangle, hexahedron, tetrahedron };

constexpr int reference_dimension(ReferenceDomain domain) {
  return domain == ReferenceDomain::quadrilateral || domain == ReferenceDomain::triangle ? 2 : 3;
}

/// Area or volume: 4, 1/2, 8, 1/6.
constexpr double reference_measure(ReferenceDomain domain) {
  switch (domain) {
    case ReferenceDomain::quadrilateral: return 4.0;
    case ReferenceDomain::triangle: return 1.0 / 2.0;
    case ReferenceDomain::hexahedron: return 8.0;
    case ReferenceDomain::tetrahedron: return 1.0 / 6.0;
  }
  return 0.0;
}

/// "quad", "tri", "hex", "tet": the domain's folder under data/quadrature/.
constexpr std::string_view reference_domain_name(ReferenceDomain domain) {
  switch (domain) {
    case ReferenceDomain::quadrilateral: return "quad";
    case ReferenceDomain::triangle: return "tri";
    case ReferenceDomain::hexahedron: return "hex";
    case ReferenceDomain::tetrahedron: return "tet";
  }
  return "";
}

/// True if every row of `points` (#points × reference_dimension(domain)) lies strictly
/// inside the domain (not on its boundary).
bool strictly_inside(ReferenceDomain domain, const Eigen::MatrixXd& points);

}  // namespace altfem
