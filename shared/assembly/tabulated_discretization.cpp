#include "shared/assembly/tabulated_discretization.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "shared/assembly/element_partition.hpp"
#include "shared/common/error.hpp"
#include "shared/solve/process_ranks.hpp"

namespace altfem {

namespace {

// The pattern's extra groups: every term's couplings, in term order.
BasisGroups collect_couplings(const std::vector<std::unique_ptr<EnergyTerm>>& terms) {
  BasisGroups all;
  for (const auto& term : terms)
    for (int g = 0; g < term->couplings().size(); ++g) all.add(term->couplings()[g]);
  return all;
}

std::vector<std::vector<int>> element_dof_groups(const TabulatedElements& elements) {
  std::vector<std::vector<int>> groups(static_cast<size_t>(elements.size()));
  for (int e = 0; e < elements.size(); ++e)
    for (int basis : elements[e].basis)
      for (int k = 0; k < 3; ++k) groups[e].push_back(3 * basis + k);
  return groups;
}

// A lumped mass that is not positive would give a division by zero or an unstable
// explicit step: NumericalError naming the basis function and its elements.
void check_lumped_mass_positive(const Eigen::VectorXd& lumped_mass, const TabulatedElements& elements) {
  Eigen::Index dof = 0;
  if (lumped_mass.size() == 0 || lumped_mass.minCoeff(&dof) > 0) return;
  // HRZ lumping scales the consistent mass' diagonal Σ_q w_q φ_a(x_q)², which only a
  // negative quadrature weight (a rule on a cell that is not star-shaped) makes ≤ 0.
  const int basis = static_cast<int>(dof / 3);
  std::string holders;
  for (int e = 0; e < elements.size(); ++e) {
    const ElementView element = elements[e];
    if (std::find(element.basis.begin(), element.basis.end(), basis) == element.basis.end()) continue;
    const bool negative = std::any_of(element.weights.begin(), element.weights.end(), [](double w) { return w < 0; });
    holders += (holders.empty() ? "" : ", ") + std::to_string(e) + (negative ? " (a negative weight)" : "");
  }
  std::ostringstream mass;  // std::to_string's fixed six decimals would print 1e-20 as 0.000000
  mass << lumped_mass[dof];
  throw NumericalError("lumped mass of basis function " + std::to_string(basis) + " is " + mass.str() +
                       ", not positive; its elements: " + (holders.empty() ? "none" : holders));
}

}  // namespace

// Each rank assembles the elements METIS gives it, and of each term the lists of
// couplings (faces) whose lowest-ranked basis function is its: a function belongs to the
// lowest part among its elements, so a face between two parts goes to the lower one. A
// term that cannot divide itself stays with rank 0. The sums in energy() and gradient()
// make the whole, and in hessian() unless the solver sums the shares (ranks::shares_matrices()).
// Returns, per element and then per term's coupling list (the pattern's groups), whether
// this rank assembles it, and each basis function's rank.
TabulatedDiscretization::RankDivision TabulatedDiscretization::divide_among_ranks(const BasisGroups& couplings) {
  const std::vector<int> part = partition_elements(parts_.elements, couplings, ranks::count());
  std::vector<char> mine(part.size());
  for (size_t e = 0; e < part.size(); ++e) mine[e] = part[e] == ranks::index();
  int basis_count = parts_.elements.basis_count();
  for (int g = 0; g < couplings.size(); ++g)
    for (int basis : couplings[g]) basis_count = std::max(basis_count, basis + 1);
  // A function no element holds (none do today) belongs to rank 0.
  std::vector<int> basis_part(static_cast<size_t>(basis_count), ranks::count());
  for (int e = 0; e < parts_.elements.size(); ++e)
    for (int basis : parts_.elements[e].basis) basis_part[basis] = std::min(basis_part[basis], part[e]);
  for (int& owner : basis_part) owner = owner == ranks::count() ? 0 : owner;
  term_here_.assign(parts_.terms.size(), 1);
  for (size_t t = 0; t < parts_.terms.size(); ++t) {
    const BasisGroups& groups = parts_.terms[t]->couplings();
    std::vector<char> term_mine(static_cast<size_t>(groups.size()));
    for (int g = 0; g < groups.size(); ++g) {
      int owner = ranks::count();
      for (int basis : groups[g]) owner = std::min(owner, basis_part[basis]);
      term_mine[g] = owner == ranks::index();
    }
    if (!parts_.terms[t]->assemble_only(term_mine)) {
      term_here_[t] = ranks::index() == 0;
      std::fill(term_mine.begin(), term_mine.end(), term_here_[t]);
    }
    mine.insert(mine.end(), term_mine.begin(), term_mine.end());
  }
  return {std::move(mine), std::move(basis_part)};
}

bool TabulatedDiscretization::assembles_term(size_t term) const { return term_here_.empty() || term_here_[term]; }

TabulatedDiscretization::TabulatedDiscretization(DiscretizationParts parts) : parts_(std::move(parts)) {
  const BasisGroups couplings = collect_couplings(parts_.terms);
  // Over several ranks a method that can tabulate some elements without the others first
  // lists every element's basis and point count, from which METIS divides them.
  if (parts_.tabulate)
    parts_.elements =
        parts_.tabulate(ranks::distributed() ? TabulatedHere([](int) { return false; }) : nullptr, nullptr);
  RankDivision division;
  if (ranks::distributed()) division = divide_among_ranks(couplings);
  const std::vector<char>& mine = division.groups;
  const bool share = ranks::shares_matrices();
  if (share) share_row_owners_ = std::move(division.basis_owners);
  // Each rank then tabulates its own elements when the solver sums the matrices' shares,
  // and sums the lumped mass, M v and the body-force loads from its elements' masses.
  // Otherwise every rank adds the whole mass to the summed Hessian: the elements are
  // tabulated whole, reduced to their masses, and then each rank keeps its own.
  if (parts_.tabulate && ranks::distributed())
    parts_.elements =
        parts_.tabulate(share ? TabulatedHere([&mine](int e) { return mine[e] != 0; }) : nullptr, &parts_.elements);
  parts_.tabulate = nullptr;
  masses_of_share_ = parts_.elements.is_share() && !parts_.element_masses;
  masses_ = parts_.element_masses ? std::move(*parts_.element_masses) : element_masses(parts_.elements);
  parts_.element_masses.reset();
  if (ranks::distributed() && !parts_.elements.is_share())
    parts_.elements.keep_only(std::span<const char>(mine.data(), static_cast<size_t>(parts_.elements.size())));
  assembler_ = std::make_unique<ElasticAssembler>(parts_.elements, parts_.materials, couplings,
                                                  share ? std::span<const char>(mine) : std::span<const char>{});
  if (ranks::distributed() && !share)
    assembler_->assemble_only(std::vector<char>(mine.begin(), mine.begin() + parts_.elements.size()));
  int first_group = 0;
  for (const auto& term : parts_.terms) {
    term->bind(assembler_->sparsity(), first_group);
    first_group += term->couplings().size();
  }
  lumped_mass_ = assembler_->lumped_mass(masses_);
  if (masses_of_share_) ranks::sum(std::span<double>(lumped_mass_.data(), static_cast<size_t>(lumped_mass_.size())));
  if (parts_.explicit_mass == ExplicitMassKind::lumped) {
    check_lumped_mass_positive(lumped_mass_, parts_.elements);
    explicit_mass_ = std::make_unique<DiagonalMass>(lumped_mass_);
  }
  constant_hessian_ = assembler_->is_linear();
  for (const auto& term : parts_.terms) constant_hessian_ = constant_hessian_ && term->is_quadratic();
  if (parts_.deformation_shifts) {
    shifts_.assign(static_cast<size_t>(9 * parts_.elements.whole_point_count()), 0.0);
    assembler_->set_deformation_shifts(shifts_);
    set_time(0);
  }
}

const Eigen::SparseMatrix<double>& TabulatedDiscretization::mass_matrix() const {
  if (!mass_) {
    mass_.emplace();
    assembler_->mass_matrix(masses_, *mass_);
  }
  return *mass_;
}

void TabulatedDiscretization::add_mass(double factor, Eigen::SparseMatrix<double>& matrix) const {
  // The sizes and column starts: comparing every row index would read the whole
  // pattern at each Newton iteration, for what the element scatter writes anyway.
  const Eigen::SparseMatrix<double>& pattern = assembler_->pattern();
  if (matrix.rows() != pattern.rows() || matrix.nonZeros() != pattern.nonZeros() ||
      !std::equal(pattern.outerIndexPtr(), pattern.outerIndexPtr() + pattern.outerSize() + 1, matrix.outerIndexPtr()))
    throw std::logic_error("TabulatedDiscretization::add_mass: the matrix does not have the Hessian's pattern");
  assembler_->add_mass(masses_, factor, matrix);
}

const ExplicitMass& TabulatedDiscretization::explicit_mass() const {
  if (!explicit_mass_ && !share_row_owners_.empty())
    throw std::logic_error("TabulatedDiscretization: a block mass from a rank's share of the mass matrix");
  if (!explicit_mass_)
    explicit_mass_ = std::make_unique<BlockDiagonalMass>(
        mass_matrix(), parts_.mass_blocks.empty() ? element_dof_groups(parts_.elements) : parts_.mass_blocks);
  return *explicit_mass_;
}

void TabulatedDiscretization::set_time(double time) const {
  if (parts_.deformation_shifts) parts_.deformation_shifts(time, shifts_);
}

TabulatedDiscretization::~TabulatedDiscretization() = default;

// Over several ranks each assembles its own elements and faces (divide_among_ranks); the
// sums make every rank's result the whole, so that the integrators run the same on every
// rank. The Hessian is left this rank's share when the solver sums the shares.
double TabulatedDiscretization::energy(const Eigen::VectorXd& u) const {
  double total = 0;
  ranks::collectively([&] {
    total = assembler_->energy(u);
    for (size_t t = 0; t < parts_.terms.size() && std::isfinite(total); ++t)
      if (assembles_term(t)) total += parts_.terms[t]->energy(u);
  });
  return ranks::sum(total);
}

void TabulatedDiscretization::gradient(const Eigen::VectorXd& u, Eigen::VectorXd& gradient) const {
  ranks::collectively([&] {
    assembler_->gradient(u, gradient);
    for (size_t t = 0; t < parts_.terms.size(); ++t)
      if (assembles_term(t)) parts_.terms[t]->add_gradient(u, gradient);
  });
  ranks::sum(std::span<double>(gradient.data(), static_cast<size_t>(gradient.size())));
}

void TabulatedDiscretization::hessian(const Eigen::VectorXd& u, Eigen::SparseMatrix<double>& hessian,
                                      bool project_spd) const {
  ranks::collectively([&] {
    assembler_->hessian(u, hessian, project_spd);
    for (size_t t = 0; t < parts_.terms.size(); ++t)
      if (assembles_term(t)) parts_.terms[t]->add_hessian(u, hessian);
  });
  if (share_row_owners_.empty())
    ranks::sum(std::span<double>(hessian.valuePtr(), static_cast<size_t>(hessian.nonZeros())));
}

Eigen::VectorXd TabulatedDiscretization::mass_times(const Eigen::VectorXd& vector) const {
  Eigen::VectorXd product = assembler_->mass_times(masses_, vector);
  if (masses_of_share_) ranks::sum(std::span<double>(product.data(), static_cast<size_t>(product.size())));
  return product;
}

Eigen::VectorXd TabulatedDiscretization::body_force(const Eigen::Vector3d& acceleration) const {
  Eigen::VectorXd force = assembler_->body_force(masses_, acceleration);
  if (masses_of_share_) ranks::sum(std::span<double>(force.data(), static_cast<size_t>(force.size())));
  return force;
}

Eigen::MatrixXd TabulatedDiscretization::element_cauchy_stress(const Eigen::VectorXd& displacement) const {
  Eigen::MatrixXd stresses;
  ranks::collectively([&] { stresses = assembler_->mean_cauchy_stress(displacement); });
  parts_.elements.sum_over_ranks(std::span<double>(stresses.data(), static_cast<size_t>(stresses.size())));
  return stresses;
}

Eigen::VectorXd TabulatedDiscretization::explicit_body_force(const Eigen::Vector3d& acceleration) const {
  if (parts_.explicit_mass == ExplicitMassKind::block_per_element) return body_force(acceleration);
  Eigen::VectorXd force(lumped_mass_.size());
  for (Eigen::Index dof = 0; dof < force.size(); ++dof) force[dof] = lumped_mass_[dof] * acceleration[dof % 3];
  return force;
}

Eigen::VectorXd TabulatedDiscretization::external_force(double time) const {
  if (parts_.external_force) return parts_.external_force(time);
  return Eigen::VectorXd::Zero(dof_count());
}

Eigen::VectorXd TabulatedDiscretization::prescribed_displacement(double time) const {
  if (parts_.dirichlet.dofs.empty()) return Eigen::VectorXd();
  return parts_.dirichlet.prescribed(time);
}

}  // namespace altfem
