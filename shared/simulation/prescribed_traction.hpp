#pragma once
// The traction the scene prescribes on the body's boundary at a time, for the error
// indicator's boundary residual (refine_marking.hpp, issue #34): none where a Dirichlet
// condition holds the point, even in one component (the traction there is, at least in
// part, the unknown reaction), else the sum of
// the surface loads whose region holds it (`loads.traction`, with their ramps), 0 on a free
// boundary.
#include <Eigen/Core>
#include <optional>

#include "shared/scene/scene.hpp"
#include "shared/solve/dirichlet_dofs.hpp"

namespace altfem {

class PrescribedTraction {
public:
  /// `scene`'s conditions (but those `released`, a bit per index into scene.dirichlet) and
  /// loads at `time`; regions hold a point within
  /// `tolerance` (region_tolerance). Keeps a reference to `scene`.
  PrescribedTraction(const Scene& scene, double time, double tolerance, ConditionSet released = 0);

  /// At `point` of the boundary with outward unit `normal`: nullopt where a condition holds
  /// it, else the prescribed traction [Pa].
  std::optional<Eigen::Vector3d> at(const Eigen::Vector3d& point, const Eigen::Vector3d& normal) const;

private:
  const Scene& scene_;
  double time_, tolerance_;
  ConditionSet released_;
};

}  // namespace altfem
