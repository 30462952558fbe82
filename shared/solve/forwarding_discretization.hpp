#pragma once
// A Discretization that forwards every call to another: the base of the layers the run
// driver puts over a method's discretization (timing and scene loads, released
// conditions) and of a discretization that changes part of another's behaviour. A
// layer overrides only what it changes, so a function added to Discretization is
// forwarded by adding it here once.
#include "shared/solve/discretization.hpp"

namespace altfem {

class ForwardingDiscretization : public Discretization {
public:
  explicit ForwardingDiscretization(const Discretization& inner) : inner_(&inner) {}

  const Discretization& inner() const { return *inner_; }

  int dof_count() const override { return inner_->dof_count(); }
  double energy(const Eigen::VectorXd& u) const override { return inner_->energy(u); }
  void gradient(const Eigen::VectorXd& u, Eigen::VectorXd& gradient) const override { inner_->gradient(u, gradient); }
  void hessian(const Eigen::VectorXd& u, Eigen::SparseMatrix<double>& hessian, bool project_spd) const override {
    inner_->hessian(u, hessian, project_spd);
  }
  const Eigen::SparseMatrix<double>& hessian_pattern() const override { return inner_->hessian_pattern(); }
  bool hessian_is_constant() const override { return inner_->hessian_is_constant(); }
  const std::vector<int>& matrix_share_owners() const override { return inner_->matrix_share_owners(); }
  bool forces_have_potential() const override { return inner_->forces_have_potential(); }
  const Eigen::SparseMatrix<double>& mass_matrix() const override { return inner_->mass_matrix(); }
  Eigen::VectorXd mass_times(const Eigen::VectorXd& vector) const override { return inner_->mass_times(vector); }
  void add_mass(double factor, Eigen::SparseMatrix<double>& matrix) const override { inner_->add_mass(factor, matrix); }
  const ExplicitMass& explicit_mass() const override { return inner_->explicit_mass(); }
  Eigen::VectorXd body_force(const Eigen::Vector3d& acceleration) const override {
    return inner_->body_force(acceleration);
  }
  Eigen::VectorXd explicit_body_force(const Eigen::Vector3d& acceleration) const override {
    return inner_->explicit_body_force(acceleration);
  }
  void set_time(double time) const override { inner_->set_time(time); }
  Eigen::VectorXd external_force(double time) const override { return inner_->external_force(time); }
  const std::vector<int>& constrained_dofs() const override { return inner_->constrained_dofs(); }
  Eigen::VectorXd prescribed_displacement(double time) const override { return inner_->prescribed_displacement(time); }
  const std::vector<ConstraintHolders>& constraint_holders() const override { return inner_->constraint_holders(); }
  bool imposes_conditions_weakly() const override { return inner_->imposes_conditions_weakly(); }
  PreconditionerFactory preconditioner_factory() const override { return inner_->preconditioner_factory(); }
  const CoarseSpace& coarse_space() const override { return inner_->coarse_space(); }
  Eigen::MatrixXd element_cauchy_stress(const Eigen::VectorXd& u) const override {
    return inner_->element_cauchy_stress(u);
  }

private:
  const Discretization* inner_;
};

}  // namespace altfem
