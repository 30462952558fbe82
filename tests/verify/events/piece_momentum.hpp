#pragma once
// The mass and vertical momentum of what lies beyond a blade, by the method's volume
// rule: a piece's interior points lie strictly on its side, so the points beyond the
// plane (or within a bent blade's wedge) are the cut-off piece's. What the free-fall checks of the cut tests compare.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <optional>

#include "shared/simulation/simulation.hpp"

namespace altfem {

struct PieceMomentum {
  double mass = 0;        ///< ∫ρ dV beyond the blade [kg]
  double momentum_z = 0;  ///< ∫ρ v_z dV beyond the blade [kg m/s]
};

/// Over the volume rule's points where `inside` holds.
template <typename Inside>
PieceMomentum momentum_where(const Simulation& simulation, const Inside& inside, double density) {
  const std::optional<FieldQuadrature> quadrature = simulation.method().field_quadrature(0);
  const TabulatedElements& elements = *quadrature->elements;
  const Eigen::VectorXd& velocity = simulation.state().velocity;
  PieceMomentum piece;
  Eigen::Index row = 0;
  for (int e = 0; e < elements.size(); ++e) {
    const ElementView element = elements[e];
    for (int q = 0; q < element.point_count(); ++q, ++row) {
      if (!inside(Eigen::Vector3d(quadrature->points.row(row).transpose()))) continue;
      double v_z = 0;
      for (int a = 0; a < element.basis_count(); ++a)
        v_z += element.values(q, a) * velocity[3 * static_cast<Eigen::Index>(element.basis[a]) + 2];
      piece.mass += density * element.weights[q];
      piece.momentum_z += density * element.weights[q] * v_z;
    }
  }
  return piece;
}

/// Over the volume rule's points on the side of the plane (point, normal) that `normal` points to.
inline PieceMomentum momentum_beyond(const Simulation& simulation, const Eigen::Vector3d& point,
                                     const Eigen::Vector3d& normal, double density) {
  return momentum_where(
      simulation, [&](const Eigen::Vector3d& x) { return (x - point).dot(normal) > 0; }, density);
}

/// Steps `simulation` `steps` times, expecting each backward-Euler step of `dt` to add
/// m g dt to the vertical momentum of what `inside` holds (g = −9.81 m/s² along z), to
/// 1e-6 of it: a piece that nothing holds falls freely.
template <typename Inside>
void expect_free_fall(Simulation& simulation, const Inside& inside, double density, double dt, int steps) {
  const double g = -9.81;
  PieceMomentum before = momentum_where(simulation, inside, density);
  for (int step = 0; step < steps; ++step) {
    simulation.integrator().step(simulation.state());
    const PieceMomentum after = momentum_where(simulation, inside, density);
    EXPECT_NEAR(after.momentum_z - before.momentum_z, before.mass * g * dt, 1e-6 * before.mass * std::abs(g) * dt)
        << "step " << step;
    before = after;
  }
}

}  // namespace altfem
