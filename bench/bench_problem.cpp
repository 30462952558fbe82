#include "bench/bench_problem.hpp"

#include <cmath>

#include "shared/fem/tabulate_lagrange.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/solve/dirichlet_elimination.hpp"

namespace altfem::bench {

CubeProblem::CubeProblem(ElementType type, int resolution, int quadrature_strength, MaterialModel model)
    : type_(type),
      resolution_(resolution),
      quadrature_strength_(quadrature_strength),
      mesh_(structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()),
                            Eigen::Vector3i::Constant(resolution), type)),
      elements_(tabulate_lagrange(mesh_, quadrature_strength)),
      material_(make_material(model, 1e6, 0.4, 1000)),
      assembler_(std::make_unique<ElasticAssembler>(elements_, std::vector<const Material*>{material_.get()})) {}

std::string CubeProblem::description() const {
  return std::string(element_name(type_)) + " " + std::to_string(resolution_) + "^3 (" +
         std::to_string(mesh_.cells.rows()) + " cells), strength " + std::to_string(quadrature_strength_) + ", " +
         std::to_string(elements_.point_count()) + " points, " + std::to_string(dof_count()) + " DOFs";
}

Eigen::VectorXd CubeProblem::smooth_displacement() const {
  Eigen::VectorXd u(dof_count());
  for (Eigen::Index node = 0; node < mesh_.nodes.rows(); ++node) {
    const Eigen::Vector3d x = mesh_.nodes.row(node).transpose();
    const double angle = 0.3 * x.x();  // twist about the x axis, growing along it
    const double c = std::cos(angle), s = std::sin(angle);
    const Eigen::Vector3d centred(x.x(), x.y() - 0.5, x.z() - 0.5);
    const Eigen::Vector3d twisted(1.1 * x.x(), c * centred.y() - s * centred.z(), s * centred.y() + c * centred.z());
    u.segment<3>(3 * node) = twisted - centred;
  }
  return u;
}

std::vector<int> CubeProblem::clamped_dofs() const {
  std::vector<int> dofs;
  for (Eigen::Index node = 0; node < mesh_.nodes.rows(); ++node)
    if (std::abs(mesh_.nodes(node, 0)) < 1e-12)
      for (int k = 0; k < 3; ++k) dofs.push_back(3 * static_cast<int>(node) + k);
  return dofs;
}

ClampedSystem clamped_system(const CubeProblem& problem) {
  ClampedSystem system;
  const ElasticAssembler& assembler = problem.assembler();
  system.matrix = assembler.pattern();
  assembler.hessian(Eigen::VectorXd::Zero(problem.dof_count()), system.matrix);
  Eigen::SparseMatrix<double> mass;
  assembler.mass_matrix(mass);
  Eigen::VectorXd gravity = Eigen::VectorXd::Zero(problem.dof_count());
  for (int node = 0; node < problem.dof_count() / 3; ++node) gravity[3 * node + 2] = -9.81;
  system.rhs = mass * gravity;
  const std::vector<int> clamped = problem.clamped_dofs();
  const DirichletElimination elimination(system.matrix, clamped);
  elimination.apply(system.matrix, system.rhs, Eigen::VectorXd::Zero(static_cast<Eigen::Index>(clamped.size())));
  system.free_dofs = problem.dof_count() - static_cast<int>(clamped.size());
  return system;
}

}  // namespace altfem::bench
