#pragma once
#include <chrono>
#include <functional>
#include <vector>

#include "shared/solve/discretization.hpp"

namespace altfem {

/// A load vector (#dofs) at a time.
using TimeDependentLoad = std::function<Eigen::VectorXd(double time)>;

/// The run driver's view of a method's discretization: it forwards to it, adds the wall
/// time of energy, gradient and Hessian evaluations to `assembly_seconds`
/// (summary.json's timings_s.assembly), so no method has to time itself, and adds the
/// scene's loads that are the same for every method (surface tractions) to the
/// method's own external_force (which may hold weak boundary data: added, not replaced).
class TimedDiscretization final : public Discretization {
public:
  explicit TimedDiscretization(const Discretization& inner, std::vector<TimeDependentLoad> scene_loads = {})
      : inner_(inner), scene_loads_(std::move(scene_loads)) {}

  double assembly_seconds() const { return seconds_; }
  int dof_count() const override { return inner_.dof_count(); }
  double energy(const Eigen::VectorXd& u) const override {
    Timer timer(seconds_);
    return inner_.energy(u);
  }
  void gradient(const Eigen::VectorXd& u, Eigen::VectorXd& gradient) const override {
    Timer timer(seconds_);
    inner_.gradient(u, gradient);
  }
  void hessian(const Eigen::VectorXd& u, Eigen::SparseMatrix<double>& hessian, bool project_spd) const override {
    Timer timer(seconds_);
    inner_.hessian(u, hessian, project_spd);
  }
  const Eigen::SparseMatrix<double>& hessian_pattern() const override { return inner_.hessian_pattern(); }
  bool hessian_is_constant() const override { return inner_.hessian_is_constant(); }
  bool forces_have_potential() const override { return inner_.forces_have_potential(); }
  const Eigen::SparseMatrix<double>& mass_matrix() const override { return inner_.mass_matrix(); }
  const ExplicitMass& explicit_mass() const override { return inner_.explicit_mass(); }
  Eigen::VectorXd body_force(const Eigen::Vector3d& acceleration) const override {
    return inner_.body_force(acceleration);
  }
  Eigen::VectorXd explicit_body_force(const Eigen::Vector3d& acceleration) const override {
    return inner_.explicit_body_force(acceleration);
  }
  void set_time(double time) const override { inner_.set_time(time); }
  Eigen::VectorXd external_force(double time) const override {
    Eigen::VectorXd force = inner_.external_force(time);
    for (const TimeDependentLoad& load : scene_loads_) force += load(time);
    return force;
  }
  const std::vector<int>& constrained_dofs() const override { return inner_.constrained_dofs(); }
  Eigen::VectorXd prescribed_displacement(double time) const override { return inner_.prescribed_displacement(time); }
  bool imposes_conditions_weakly() const override { return inner_.imposes_conditions_weakly(); }
  PreconditionerFactory preconditioner_factory() const override { return inner_.preconditioner_factory(); }

private:
  class Timer {
  public:
    explicit Timer(double& total) : total_(total), start_(std::chrono::steady_clock::now()) {}
    ~Timer() { total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

  private:
    double& total_;
    std::chrono::steady_clock::time_point start_;
  };
  const Discretization& inner_;
  std::vector<TimeDependentLoad> scene_loads_;
  mutable double seconds_ = 0;
};

}  // namespace altfem
