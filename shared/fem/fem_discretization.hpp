#pragma once
// The conforming Lagrange discretization: the `fem` method, and the base the finite
// cell method will extend with cut cells (DESIGN.md, shared/fem).
#include <memory>
#include <vector>

#include "shared/assembly/elastic_assembler.hpp"
#include "shared/assembly/tabulated_elements.hpp"
#include "shared/material/material.hpp"
#include "shared/mesh/volume_mesh.hpp"
#include "shared/scene/scene.hpp"
#include "shared/solve/discretization.hpp"

namespace altfem {

class FemDiscretization final : public Discretization {
public:
  /// Tabulates `mesh` with the given quadrature strength, and constrains the DOFs of
  /// the nodes each Dirichlet condition's region selects (its components only).
  /// Throws InputError naming the condition when a region selects no node.
  FemDiscretization(VolumeMesh mesh, const Material& material, const std::vector<DirichletCondition>& dirichlet,
                    int quadrature_strength, const std::string& scene_file = "scene");

  int dof_count() const override { return 3 * static_cast<int>(mesh_.nodes.rows()); }
  double energy(const Eigen::VectorXd& u) const override { return assembler_->energy(u); }
  void gradient(const Eigen::VectorXd& u, Eigen::VectorXd& gradient) const override { assembler_->gradient(u, gradient); }
  void hessian(const Eigen::VectorXd& u, Eigen::SparseMatrix<double>& hessian, bool project_spd) const override {
    assembler_->hessian(u, hessian, project_spd);
  }
  const Eigen::SparseMatrix<double>& hessian_pattern() const override { return assembler_->pattern(); }
  bool hessian_is_constant() const override { return assembler_->is_linear(); }
  const Eigen::SparseMatrix<double>& mass_matrix() const override { return mass_; }
  const Eigen::VectorXd& lumped_mass() const override { return lumped_mass_; }
  const std::vector<int>& constrained_dofs() const override { return constrained_; }
  Eigen::VectorXd prescribed_displacement(double time) const override;

  const VolumeMesh& mesh() const { return mesh_; }
  const TabulatedElements& elements() const { return elements_; }
  const ElasticAssembler& assembler() const { return *assembler_; }
  /// Centre of mass of the mesh (for initial angular velocities).
  Eigen::Vector3d centre_of_mass() const;

private:
  VolumeMesh mesh_;
  TabulatedElements elements_;
  std::unique_ptr<ElasticAssembler> assembler_;
  Eigen::SparseMatrix<double> mass_;
  Eigen::VectorXd lumped_mass_;
  std::vector<DirichletCondition> dirichlet_;
  std::vector<int> constrained_;
  std::vector<int> constrained_condition_;  // which condition prescribes each constrained DOF
};

}  // namespace altfem
