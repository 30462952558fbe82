#pragma once
// The mass that explicit integration multiplies and inverts. Lagrange bases lump it
// to a positive diagonal (HRZ); a DG basis has no nodes to lump to, but its consistent
// mass is block-diagonal (one block per element), so it is inverted exactly block by
// block (Kaufmann et al. 2009 §4.3).
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

namespace altfem {

class ExplicitMass {
public:
  virtual ~ExplicitMass() = default;
  /// M v (#dofs).
  virtual Eigen::VectorXd multiply(const Eigen::VectorXd& v) const = 0;
  /// M⁻¹ f (#dofs).
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& f) const = 0;
  /// ½ vᵀ M v.
  double kinetic_energy(const Eigen::VectorXd& v) const { return 0.5 * v.dot(multiply(v)); }
};

/// A positive diagonal mass (#dofs entries, all > 0).
class DiagonalMass final : public ExplicitMass {
public:
  explicit DiagonalMass(Eigen::VectorXd diagonal);
  Eigen::VectorXd multiply(const Eigen::VectorXd& v) const override { return diagonal_.cwiseProduct(v); }
  Eigen::VectorXd solve(const Eigen::VectorXd& f) const override { return f.cwiseQuotient(diagonal_); }
  const Eigen::VectorXd& diagonal() const { return diagonal_; }

private:
  Eigen::VectorXd diagonal_;
};

/// The consistent mass restricted to disjoint groups of DOFs (e.g. each DG element's
/// DOFs), each block factorised once by Cholesky. Entries coupling two groups must be
/// zero; the constructor checks it.
class BlockDiagonalMass final : public ExplicitMass {
public:
  /// mass: #dofs × #dofs; groups: disjoint DOF lists covering every DOF once.
  /// Throws std::invalid_argument when a group overlaps another, a DOF is missing, mass
  /// couples two groups, or a block is not positive definite.
  BlockDiagonalMass(const Eigen::SparseMatrix<double>& mass, const std::vector<std::vector<int>>& groups);
  Eigen::VectorXd multiply(const Eigen::VectorXd& v) const override;
  Eigen::VectorXd solve(const Eigen::VectorXd& f) const override;

private:
  // result restricted to group g = operation(g, v restricted to group g), for every group.
  template <typename BlockOperation>
  Eigen::VectorXd per_block(const Eigen::VectorXd& v, BlockOperation&& operation) const;

  std::vector<std::vector<int>> groups_;
  std::vector<Eigen::MatrixXd> blocks_;
  std::vector<Eigen::LLT<Eigen::MatrixXd>> factors_;
};

}  // namespace altfem
