#pragma once
// Corotated linear DG, "stiffness warping" (Kaufmann et al. 2009 §6): the linear DG
// stiffness evaluated in each element's rotated frame, so that large rotations give no
// spurious strain.
//
// Blocks S (each a dense symmetric matrix K_S over a list of DOF ranges, warped by the
// rotation R_S of one element):
//   - every element's K_K (eq. (23)), warped with R_K (eq. (29));
//   - on every interior face f and side ± the consistency terms whose strain is that
//     side's, K_f1^± + K_f2^± (§6.1), over both sides' DOFs, warped with R_f^± — the
//     element's rotation, never the face's (§6.1: a face rotation gives ghost forces);
//   - on a Dirichlet face with the IP flux, Nitsche's consistency terms K_f1 + K_f1ᵀ,
//     warped with the boundary element's rotation; there the jump u − g is rotated as
//     R_Kᵀ (u − g), not as R_Kᵀ X − X⁰, which would read the wall's unrotated position
//     as a jump of (R_Kᵀ − I) x. The data part −∫ P R_Kᵀ g · σ(v) n of a moving
//     condition depends on R_K and so on u: gradient() adds it, rotated back by R_K,
//     for the time of the last set_time(); external_force() carries only the
//     penalty's data η_f ∫ P g · v, unwarped like the penalty.
// The penalty terms K_f3 (26) measure jumps only and are not warped (§6.1).
// With X = X⁰ + U the warped internal force is Σ_S R_S K_S (R_Sᵀ X − X⁰) + K_3 U
// (eq. (29), the five contributions of §6.1), X⁰ the coefficients of the identity map
// x ↦ x in the monomial basis (§6.2). R_K is the polar rotation of the element's least-
// squares affine fit: the L2(K) projection of x + u onto affine fields (§6.1).
//
// Warping is a force model, not an energy: the Discretization interface is met with
//   energy(u)   = Σ_S ½ z_Sᵀ K_S z_S + ½ uᵀ K_3 u,  z_S = R_Sᵀ X − X⁰ (R_S from u)
//                 (a Dirichlet face's term: (R_Kᵀ u)ᵀ K_f1 z_S),
//   gradient(u) = the warped force above (the energy's gradient with R frozen),
//   hessian(u)  = Σ_S R_S K_S R_Sᵀ + K_3 (rotations frozen; symmetric).
// The gradient drops ∂R/∂u terms of order |strain|·|rotation change|, so the energy
// serves Newton's line search as a merit function, and Newton with the frozen-rotation
// tangent converges linearly with a small rate; hessian() of the rest state is K, and
// in the semi-implicit step (one Newton iteration) this is Kaufmann et al.'s §6.3
// assembly exactly.
#include <vector>

#include "dg/dg_discretization.hpp"
#include "dg/dg_linear_system.hpp"

namespace altfem::dg {

class WarpedDgDiscretization final : public LinearDgDiscretization {
public:
  /// Re-integrates the system's element and face matrices (exactly, as DgLinearSystem
  /// does) and keeps their warped parts; `system` need not outlive this object.
  /// penalty_data_load: the Dirichlet data's load through the penalty alone at a time
  /// (DgLinearSystem::dirichlet_load with penalty_only); trajectory: the conditions'
  /// data, empty when every condition is fixed (g = 0).
  WarpedDgDiscretization(const DgLinearSystem& system, const DgSettings& settings, Eigen::VectorXd function_integrals,
                         std::vector<std::vector<int>> element_dofs,
                         std::function<Eigen::VectorXd(double)> penalty_data_load, ConditionTrajectory trajectory = {});

  double energy(const Eigen::VectorXd& u) const override;
  void gradient(const Eigen::VectorXd& u, Eigen::VectorXd& gradient) const override;
  void hessian(const Eigen::VectorXd& u, Eigen::SparseMatrix<double>& hessian, bool project_spd) const override;
  bool hessian_is_constant() const override { return false; }
  bool forces_have_potential() const override { return false; }
  /// Evaluates the moving conditions' data on the Dirichlet faces at `time`.
  void set_time(double time) const override;

  /// R_K of every element for coefficients u (#cells).
  std::vector<Eigen::Matrix3d> rotations(const Eigen::VectorXd& u) const;
  /// X⁰ of §6.2 (#dofs).
  const Eigen::VectorXd& rest_state() const { return rest_state_; }

private:
  struct Parts;
  // One thread's work vectors, each as long as the largest block (blocks use their head).
  struct Scratch {
    Eigen::VectorXd rest, z, jump, force;
  };
  // The element and face terms of DgLinearSystem, integrated again and kept apart.
  static Parts warped_parts(const DgLinearSystem& system, const DgSettings& settings);
  WarpedDgDiscretization(Parts parts, const DgLinearSystem& system, Eigen::VectorXd function_integrals,
                         std::vector<std::vector<int>> element_dofs,
                         std::function<Eigen::VectorXd(double)> penalty_data_load, ConditionTrajectory trajectory);

public:
  struct DofRange {
    int first, count;
  };
  struct Block {
    std::vector<DofRange> ranges;  // the DOFs of the local rows/columns, in order
    int element;                   // whose rotation warps it
    Eigen::MatrixXd matrix;        // K_S, symmetric, Σ counts square (K_f1 on a Dirichlet face)
    bool dirichlet = false;        // a Dirichlet face's K_f1: rows the jump u − g, columns the strain
    Eigen::MatrixXd symmetric;     // on a Dirichlet face K_f1 + K_f1ᵀ, its tangent before rotation; else empty
    std::vector<int> value_index;  // per local column and range: the position in the pattern's values of its first row
  };
  // A Dirichlet face with the IP flux, for the data part of its Nitsche terms.
  struct DirichletFace {
    int element, condition, first_dof;  // first_dof: the element's first DOF
    Eigen::Vector3d normal;
    std::array<bool, 3> components;
    double lambda, mu;
    Eigen::MatrixXd points;     // #points × 3, a rule exact for g of degree ≤ k + 3 times ∇φ
    Eigen::VectorXd weights;    // #points
    Eigen::MatrixXd gradients;  // (#points · n) × 3: ∇φ_a at point q in row q·n + a
  };

private:
  // Adds −R_K c_a(P R_Kᵀ G_a) of every moving Dirichlet face to `gradient` (G_a = ∫ g ⊗ ∇φ_a
  // at the set time) and returns −Σ u_a · R_K c_a, its energy with R frozen.
  double add_data_forces(const std::vector<Eigen::Matrix3d>& rotation, const Eigen::VectorXd& u,
                         Eigen::VectorXd* gradient) const;
  // K_S z_S into scratch.force.head(n) (a Dirichlet face: K_f1 z_S + K_f1ᵀ R_Sᵀ u_S), with
  // z_S = R_Sᵀ (X⁰ + u)_S − X⁰_S; returns the block's energy.
  double block_force(const Block& block, const Eigen::Matrix3d& rotation, const Eigen::VectorXd& u,
                     Scratch& scratch) const;

  // The threads of the parallel loops: OpenMP's, at most as many as there is scratch for.
  int threads() const;

  // Over several ranks each holds the blocks of its cells and of the faces it owns
  // (DgLinearSystem::owns_cell, owns_face) and the energy and forces are summed; the
  // Hessian stays each rank's share where the solver sums shares (PETSc), else it is summed.
  bool divided_ = false;
  std::vector<Block> blocks_;
  std::vector<DirichletFace> dirichlet_faces_;  // empty unless some condition moves
  ConditionTrajectory trajectory_;
  mutable std::vector<Eigen::MatrixXd> data_moments_;  // per Dirichlet face 3 × 3n: G_a side by side
  // Parallel without locks, and the same sums on any number of threads: each element
  // owns its rows and columns and gathers what its blocks put there, in block order.
  struct BlockSide {
    int block, range;  // blocks_[block].ranges[range] is the element's
    int position;      // where that range starts among the block's rows
  };
  std::vector<std::vector<BlockSide>> element_blocks_;  // per element
  std::vector<int> force_offsets_;                      // per block + 1: its rows in block_forces_
  mutable std::vector<Scratch> scratch_;                // per thread
  mutable std::vector<double> block_energies_;          // per block, summed in block order
  mutable Eigen::VectorXd block_forces_;                // each block's R_S K_S z_S
  Eigen::SparseMatrix<double> penalty_;                 // K_3, the unwarped jump terms, on hessian_pattern()
  Eigen::VectorXd rest_state_;
  std::vector<int> cell_offsets_;            // #cells + 1: first basis function of each cell
  std::vector<Eigen::MatrixXd> affine_fit_;  // per cell 3 × #functions: ∇ of the L2 affine fit of φ_a
};

}  // namespace altfem::dg
