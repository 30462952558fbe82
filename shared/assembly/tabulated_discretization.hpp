#pragma once
// A Discretization built from parts (docs/architecture.md, "Adding a method"):
// tabulated volume elements with their materials, any energy terms a method adds
// (face fluxes, ghost penalties, weak conditions), strongly constrained DOFs if any,
// and the explicit mass that fits the basis. `fem` and `fcm` build one from Lagrange
// tabulations (the FCM with its own cells and cut-cell rules); DG and harmonic bases
// from their own. The mass, the Hessian and the load vectors all come from the same
// tabulated elements, so any basis gets the right ones.
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "shared/assembly/elastic_assembler.hpp"
#include "shared/assembly/energy_term.hpp"
#include "shared/assembly/tabulated_elements.hpp"
#include "shared/material/material.hpp"
#include "shared/solve/dirichlet_dofs.hpp"
#include "shared/solve/discretization.hpp"

namespace altfem {

enum class ExplicitMassKind {
  /// HRZ-lumped diagonal, for Lagrange (partition-of-unity) bases.
  lumped,
  /// The consistent mass of each element, inverted block by block: for bases whose
  /// elements share no basis function (DG).
  block_per_element,
};

/// Tabulates a method's elements: those `here` holds, the others held elsewhere
/// (TabulatedElements::add_held_elsewhere: their basis lists and point counts only).
/// `listed`, when not null, is the call before's result, which holds every element's point
/// count: an element held elsewhere may take its count from it instead of making its rule.
using ElementTabulator = std::function<TabulatedElements(const TabulatedHere& here, const TabulatedElements* listed)>;

struct DiscretizationParts {
  TabulatedElements elements;
  /// Instead of `elements`, for a method that can tabulate some elements without the
  /// others: over several ranks each then tabulates only its own (docs/scaling.md), the
  /// partition made from every element's basis list and point count. Called during
  /// construction only.
  ElementTabulator tabulate;
  /// The elements' masses (one entry per element, in order) from the rules the mass
  /// matrix, the lumped mass and the body-force loads use, when they differ from the
  /// stiffness rules: the FCM integrates mass at a higher order than stiffness and
  /// never simplifies it (Longva et al. 2020 §6). Empty: from `elements`.
  std::optional<ElementMasses> element_masses;
  /// materials[m] serves the elements of material id m (not owned).
  std::vector<const Material*> materials;
  std::vector<std::unique_ptr<EnergyTerm>> terms;
  DirichletDofs dirichlet;         ///< empty for none
  bool conditions_weakly = false;  ///< the terms impose the Dirichlet conditions
  ExplicitMassKind explicit_mass = ExplicitMassKind::lumped;
  /// The DOF blocks of a block_per_element mass (disjoint, covering every DOF) when the
  /// elements' function lists overlap although their masses do not (DG with lifted
  /// gradients: a cell's element lists its neighbours' functions too). Empty: each
  /// element's DOFs.
  std::vector<std::vector<int>> mass_blocks;
  /// Tractions and weak boundary data at a time (#dofs); none if empty.
  std::function<Eigen::VectorXd(double time)> external_force;
  /// A constant shift of F at every quadrature point at a time (writes 9 values per
  /// point, column-major, into its span; ElasticAssembler::set_deformation_shifts): boundary
  /// data inside the energy (DG's lifted Dirichlet data). Read at set_time; none if empty.
  std::function<void(double time, std::span<double> shifts)> deformation_shifts;
  PreconditionerFactory preconditioner;
  /// A coarser space for multigrid (Discretization::coarse_space); empty for none.
  CoarseSpace coarse_space;
};

class TabulatedDiscretization final : public Discretization {
public:
  explicit TabulatedDiscretization(DiscretizationParts parts);
  ~TabulatedDiscretization() override;

  int dof_count() const override { return assembler_->dof_count(); }
  double energy(const Eigen::VectorXd& u) const override;
  void gradient(const Eigen::VectorXd& u, Eigen::VectorXd& gradient) const override;
  void hessian(const Eigen::VectorXd& u, Eigen::SparseMatrix<double>& hessian, bool project_spd) const override;
  const Eigen::SparseMatrix<double>& hessian_pattern() const override { return assembler_->pattern(); }
  bool hessian_is_constant() const override { return constant_hessian_; }
  /// Assembled on first use: the integrators take the mass element by element
  /// (mass_times, add_mass), so a run holds no matrix of it as large as the Hessian.
  const Eigen::SparseMatrix<double>& mass_matrix() const override;
  Eigen::VectorXd mass_times(const Eigen::VectorXd& vector) const override;
  /// matrix (with hessian_pattern()) += factor · M.
  void add_mass(double factor, Eigen::SparseMatrix<double>& matrix) const override;
  const ExplicitMass& explicit_mass() const override;
  Eigen::VectorXd body_force(const Eigen::Vector3d& acceleration) const override;
  Eigen::VectorXd explicit_body_force(const Eigen::Vector3d& acceleration) const override;
  Eigen::VectorXd external_force(double time) const override;
  /// Evaluates parts.deformation_shifts at `time` (from time 0 at construction).
  void set_time(double time) const override;
  const std::vector<int>& matrix_share_owners() const override { return share_row_owners_; }
  const std::vector<int>& constrained_dofs() const override { return parts_.dirichlet.dofs; }
  const std::vector<ConstraintHolders>& constraint_holders() const override { return parts_.dirichlet.holders; }
  Eigen::VectorXd prescribed_displacement(double time) const override;
  bool imposes_conditions_weakly() const override { return parts_.conditions_weakly; }
  PreconditionerFactory preconditioner_factory() const override { return parts_.preconditioner; }
  const CoarseSpace& coarse_space() const override { return parts_.coarse_space; }
  Eigen::MatrixXd element_cauchy_stress(const Eigen::VectorXd& displacement) const override;

  /// Over several ranks, this rank's share (TabulatedElements::keep_only): its elements'
  /// points only.
  const TabulatedElements& elements() const { return parts_.elements; }
  const ElasticAssembler& assembler() const { return *assembler_; }

private:
  struct RankDivision {
    std::vector<char> groups;       // per element, then per term's coupling list: this rank's
    std::vector<int> basis_owners;  // per basis function, the rank owning its rows
  };
  /// This rank's elements and term couplings, in a run over several processes.
  RankDivision divide_among_ranks(const BasisGroups& couplings);
  /// Whether this rank evaluates term t (its share, or the whole on rank 0).
  bool assembles_term(size_t term) const;

  DiscretizationParts parts_;
  std::unique_ptr<ElasticAssembler> assembler_;
  ElementMasses masses_;                                     // parts_.element_masses, or those of parts_.elements
  mutable std::optional<Eigen::SparseMatrix<double>> mass_;  // mass_matrix(), once asked for
  Eigen::VectorXd lumped_mass_;
  mutable std::unique_ptr<ExplicitMass> explicit_mass_;  // the lumped one at once, a block one once asked for
  bool constant_hessian_ = false;
  // masses_ of this rank's elements only: the lumped mass, M v and body forces summed over the ranks.
  bool masses_of_share_ = false;
  std::vector<char> term_here_;         // per term, over several ranks: whether this rank evaluates it
  std::vector<int> share_row_owners_;   // with ranks::shares_matrices(): each basis function's rank
  mutable std::vector<double> shifts_;  // parts_.deformation_shifts at the last set_time (9 per point)
};

}  // namespace altfem
