#include "shared/simulation/body_force_load.hpp"

#include "shared/common/error.hpp"

namespace altfem {

Eigen::VectorXd integrate_against_basis(const FieldQuadrature& quadrature, const Eigen::MatrixXd& forces,
                                        int dof_count) {
  Eigen::VectorXd load = Eigen::VectorXd::Zero(dof_count);
  const TabulatedElements& elements = *quadrature.elements;
  Eigen::Index row = 0;
  for (int e = 0; e < elements.size(); ++e) {
    const ElementView element = elements[e];
    for (int q = 0; q < element.point_count(); ++q, ++row) {
      const Eigen::Vector3d weighted = element.weights[q] * forces.row(row).transpose();
      for (int a = 0; a < element.basis_count(); ++a)
        load.segment<3>(3 * static_cast<Eigen::Index>(element.basis[a])) += element.values(q, a) * weighted;
    }
  }
  elements.sum_over_ranks(std::span<double>(load.data(), static_cast<size_t>(load.size())));
  return load;
}

BodyForceLoad::BodyForceLoad(FieldQuadrature quadrature, VectorExpression force, int dof_count)
    : quadrature_(std::move(quadrature)), force_(std::move(force)), dof_count_(dof_count) {
  if (!force_.depends_on_time()) constant_ = (*this)(0.0);
}

Eigen::VectorXd BodyForceLoad::operator()(double time) const {
  if (constant_.size() > 0) return constant_;
  return integrate_against_basis(quadrature_, evaluate_at_points(force_, quadrature_.points, time), dof_count_);
}

std::function<Eigen::VectorXd(double)> body_force_load(const Scene& scene, const MethodInstance& method,
                                                       const std::string& method_name) {
  if (!scene.body_force.has_value()) return {};
  std::optional<FieldQuadrature> quadrature = method.field_quadrature(0);
  if (!quadrature)
    throw InputError(input_message(scene.file.string(), "/loads/body_force",
                                   "method '" + method_name + "' cannot integrate a body-force expression"));
  return BodyForceLoad(std::move(*quadrature), scene.body_force, method.discretization().dof_count());
}

}  // namespace altfem
