#pragma once
// The curved surface a method's flat triangles stand for (a curved Lagrange mesh's
// isoparametric faces), for integrating surface loads on it (surface_traction.hpp).
#include <Eigen/Core>
#include <functional>

namespace altfem {

/// For triangle t of a surface and barycentric coordinates λ (λ0 = 1 − λ1 − λ2): the
/// point x(λ) of the curved surface the triangle approximates, and its area vector
/// a = ∂x/∂λ1 × ∂x/∂λ2 (outward; |a| dλ1 dλ2 is the area element). An empty lift means
/// the triangles are the surface.
using SurfaceLift = std::function<void(int triangle, const Eigen::Vector3d& barycentric, Eigen::Vector3d& point,
                                       Eigen::Vector3d& area_vector)>;

}  // namespace altfem
