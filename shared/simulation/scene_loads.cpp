#include "shared/simulation/scene_loads.hpp"

#include <memory>
#include <vector>

#include "shared/common/error.hpp"
#include "shared/simulation/body_force_load.hpp"

namespace altfem {

std::function<Eigen::VectorXd(double)> scene_external_load(const Scene& scene, const MethodInstance& method,
                                                           const std::string& method_name) {
  std::vector<std::function<Eigen::VectorXd(double)>> loads;
  if (scene.body_force.has_value()) {
    std::optional<FieldQuadrature> quadrature = method.field_quadrature(0);
    if (!quadrature)
      throw InputError(input_message(scene.file.string(), "/loads/body_force",
                                     "method '" + method_name + "' cannot integrate a body-force expression"));
    loads.push_back(BodyForceLoad(std::move(*quadrature), scene.body_force, method.discretization().dof_count()));
  }
  if (loads.empty()) return {};
  return [loads = std::move(loads)](double time) {
    Eigen::VectorXd total = loads.front()(time);
    for (std::size_t i = 1; i < loads.size(); ++i) total += loads[i](time);
    return total;
  };
}

}  // namespace altfem
