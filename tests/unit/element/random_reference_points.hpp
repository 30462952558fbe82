#pragma once
// Reproducible random points in (or near) an element's reference domain, shared
// by the element tests.
#include <Eigen/Core>
#include <random>
#include <vector>

#include "shared/element/element_type.hpp"

namespace altfem::testing {

inline const std::vector<ElementType> all_element_types{ElementType::tet4, ElementType::tet10, ElementType::tet20,
                                                        ElementType::hex8, ElementType::hex20, ElementType::hex27};

/// `count` points uniformly inside the reference domain of the type's shape,
/// shrunk by `margin` (in reference coordinates) away from its boundary.
inline std::vector<Eigen::Vector3d> random_reference_points(ElementType type, int count, unsigned seed,
                                                            double margin = 0.0) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Eigen::Vector3d> points;
  while (static_cast<int>(points.size()) < count) {
    const Eigen::Vector3d u(unit(generator), unit(generator), unit(generator));
    if (element_shape(type) == ElementShape::hexahedron) {
      points.push_back((1.0 - margin) * (2.0 * u - Eigen::Vector3d::Ones()));
    } else if (u.sum() <= 1.0) {
      // Shrink the unit tet towards its centroid, keeping `margin` from every face.
      const double factor = 1.0 - 4.0 * margin;
      points.push_back(Eigen::Vector3d::Constant(0.25) + factor * (u - Eigen::Vector3d::Constant(0.25)));
    }
  }
  return points;
}

}  // namespace altfem::testing
