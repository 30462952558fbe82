#pragma once
// The loads of a scene's `loads` block beyond gravity (which the integrators take as a
// uniform acceleration), integrated against a method's basis, as one load function of
// time for IntegratorOptions::external_load. Each kind of load adds its term in
// scene_loads.cpp.
#include <Eigen/Core>
#include <functional>

#include "shared/scene/scene.hpp"
#include "shared/simulation/method_instance.hpp"

namespace altfem {

/// The sum of the scene's loads at a time (#dofs): `body_force` so far. Empty when the
/// scene has none. Throws InputError naming the key when the method cannot integrate it.
std::function<Eigen::VectorXd(double time)> scene_external_load(const Scene& scene, const MethodInstance& method,
                                                                const std::string& method_name);

}  // namespace altfem
