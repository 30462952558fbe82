#pragma once
#include <chrono>
#include <functional>
#include <vector>

#include "shared/solve/forwarding_discretization.hpp"

namespace altfem {

/// A load vector (#dofs) at a time.
using TimeDependentLoad = std::function<Eigen::VectorXd(double time)>;

/// The run driver's view of a method's discretization: it adds the wall time of
/// energy, gradient and Hessian evaluations to a counter (summary.json's
/// timings_s.assembly; the run's, so it carries across events), so no method has to
/// time itself, and adds the scene's loads that are the same for every method (surface
/// tractions) to the method's own external_force (which may hold weak boundary data:
/// added, not replaced).
class TimedDiscretization final : public ForwardingDiscretization {
public:
  TimedDiscretization(const Discretization& inner, std::vector<TimeDependentLoad> scene_loads, double& seconds)
      : ForwardingDiscretization(inner), scene_loads_(std::move(scene_loads)), seconds_(seconds) {}

  double energy(const Eigen::VectorXd& u) const override {
    Timer timer(seconds_);
    return inner().energy(u);
  }
  void gradient(const Eigen::VectorXd& u, Eigen::VectorXd& gradient) const override {
    Timer timer(seconds_);
    inner().gradient(u, gradient);
  }
  void hessian(const Eigen::VectorXd& u, Eigen::SparseMatrix<double>& hessian, bool project_spd) const override {
    Timer timer(seconds_);
    inner().hessian(u, hessian, project_spd);
  }
  Eigen::VectorXd external_force(double time) const override {
    Eigen::VectorXd force = inner().external_force(time);
    for (const TimeDependentLoad& load : scene_loads_) force += load(time);
    return force;
  }

private:
  class Timer {
  public:
    explicit Timer(double& total) : total_(total), start_(std::chrono::steady_clock::now()) {}
    ~Timer() { total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

  private:
    double& total_;
    std::chrono::steady_clock::time_point start_;
  };
  std::vector<TimeDependentLoad> scene_loads_;
  double& seconds_;
};

}  // namespace altfem
