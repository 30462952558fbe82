#pragma once
// The problems the benchmarks share: an elastic unit cube (structured grid of one
// element type, tabulated with one quadrature strength) and what they need to build
// a linear system from it.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <string>
#include <vector>

#include "shared/assembly/elastic_assembler.hpp"
#include "shared/assembly/tabulated_elements.hpp"
#include "shared/element/element_type.hpp"
#include "shared/material/material.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem::bench {

/// The unit cube [0,1]³ as a `resolution`³ structured grid of `type` (tets: six per
/// grid cube), tabulated with `quadrature_strength`, of one material (E = 1e6 Pa,
/// ν = 0.4, ρ = 1000 kg/m³), with its assembler. Not movable: the assembler keeps
/// references to the elements and the material.
class CubeProblem {
public:
  CubeProblem(ElementType type, int resolution, int quadrature_strength, MaterialModel model);
  CubeProblem(const CubeProblem&) = delete;
  CubeProblem& operator=(const CubeProblem&) = delete;

  const VolumeMesh& mesh() const { return mesh_; }
  const TabulatedElements& elements() const { return elements_; }
  const ElasticAssembler& assembler() const { return *assembler_; }
  int dof_count() const { return assembler_->dof_count(); }
  /// "tet10 8^3 (3072 cells), strength 4, 24576 points, 14739 DOFs"
  std::string description() const;

  /// A smooth, moderately large displacement (#dofs): a twist and a stretch of
  /// about 10 %, so that nonlinear materials run away from F = I, where some
  /// closed forms take shortcuts.
  Eigen::VectorXd smooth_displacement() const;
  /// The DOFs of the nodes on the face x = 0 (sorted), the clamped face of the
  /// factorisation problems.
  std::vector<int> clamped_dofs() const;

private:
  ElementType type_;
  int resolution_;
  int quadrature_strength_;
  VolumeMesh mesh_;
  TabulatedElements elements_;
  std::unique_ptr<Material> material_;
  std::unique_ptr<ElasticAssembler> assembler_;
};

/// The linear system of a clamped cube under gravity: the (linear-elastic) stiffness
/// with the x = 0 DOFs eliminated by DirichletElimination (the pattern the time
/// integrators factorise), and the right-hand side M g with g = (0, 0, −9.81).
struct ClampedSystem {
  Eigen::SparseMatrix<double> matrix;  ///< #dofs × #dofs, both triangles
  Eigen::VectorXd rhs;                 ///< #dofs
  int free_dofs = 0;
};
ClampedSystem clamped_system(const CubeProblem& problem);

}  // namespace altfem::bench
