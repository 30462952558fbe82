#pragma once
// The lifted DG gradient of Ten Eyck & Lew 2006 (Kaufmann et al. 2009 §9.1 points to it),
// tabulated for the shared assembly kernel: every material model gets the consistent
// interior-penalty DG from the discrete energy
//   I_h(u) = Σ_K ∫_K ψ(I + ∇u_h − R(u)) dV + Σ_f η_f/2 ∫_f |[[u]]|² dA,
// whose lifting R(u)|_K ∈ P^k(K)^{3×3} (K's own monomials) is defined by
//   ∫_K R : τ dV = Σ_{f ⊂ ∂K} α_f ∫_f ([[u]] ⊗ n_K) : τ dA   for every τ ∈ P^k(K)^{3×3},
// [[u]] = u_K − u_(neighbour across f) (u_K − g on a Dirichlet face), α_f = ½ on an
// interior face (the average {τ} of the global lifting), 1 on a Dirichlet face, 0 on a
// free one. Its Euler–Lagrange equation holds −Σ_f ∫_f {Π P(F_DG)} : [[v]] ⊗ n, the
// average first Piola–Kirchhoff stress (Π: the L2 projection onto P^k), so the method is
// consistent (for P ∈ P^k exactly: an affine deformation passes the patch test), and its
// Hessian is exact and symmetric from ψ's second derivative alone. At rest the energy's
// Hessian is ∫ (∇v − R(v)) : C : (∇v − R(v)) + penalty ≥ 0, definite for any η_f > 0 once a
// condition holds the body (unlike Kaufmann et al.'s eq. (21), which needs η large enough).
// The lifting space is the cell's own P^k (not P^(k−1)): it holds the projection of a
// constant stress, so the patch test passes, and its mass matrix is the cell's.
//
// R is linear in u, so F_DG = I + Σ_a u_a ⊗ G_a at every volume point of K, with
// G_a = ∇φ_a − r_a over K's functions and G_a = −r_a over its face neighbours' (the
// vector lifting r_a of function a's jump): each cell becomes one element of the shared
// kernel whose function list holds its own and its neighbours' functions. Dirichlet data
// g enter through [[u]] = u − g as +R(g), a shift of F at every point that changes with
// the data (ElasticAssembler::set_deformation_shifts), and through the penalty's load
// η_f ∫ g·v (DgLinearSystem::dirichlet_load with penalty_only).
#include <span>

#include "dg/dg_linear_system.hpp"
#include "shared/assembly/tabulated_elements.hpp"

namespace altfem::dg {

/// The Dirichlet data's share of the lifted gradient: R(g) at every volume point of the
/// lifted cells, R(g)(x_q) = Σ_p c_qp g(x_p) ⊗ n_p over the points p of the cell's Dirichlet
/// faces (c_qp = Σ_mm' φ_m(x_q) (M⁻¹)_mm' α_f w_p φ_m'(x_p), fixed: only g changes).
class LiftedDirichletData {
public:
  struct Cell {
    long long first_point = 0;     ///< the cell's first volume point in the whole tabulation's order
    Eigen::MatrixXd face_points;   ///< #face points × 3
    Eigen::MatrixXd normals;       ///< #face points × 3, out of the cell
    std::vector<int> conditions;   ///< #face points: the face's condition
    Eigen::MatrixXd coefficients;  ///< #volume points × #face points: c_qp
  };

  void add(Cell cell) { cells_.push_back(std::move(cell)); }
  bool empty() const { return cells_.empty(); }
  /// R(g) for data g(condition, x) into `shifts` (9 per volume point, column-major, every
  /// point's; points of cells without Dirichlet faces are set to zero).
  void shifts(const ConditionData& data, std::span<double> shifts) const;

private:
  std::vector<Cell> cells_;  // the cells with Dirichlet faces
};

struct LiftedDgCells {
  TabulatedElements elements;
  LiftedDirichletData dirichlet;
};

/// Every cell as an element over its own functions (first, in order) followed by its face
/// neighbours' (each neighbour once, in the order of system.faces()), at the points of
/// system.cell_rule(cell, strength): values φ_a (0 for a neighbour's function, so masses
/// and body loads are the cell's own) and the lifted gradients G_a (#points·#functions × 3).
/// The lifting's face integrals use polygon rules of strength 2k (exact for the
/// functions' jumps; the data's share is exact for g of degree ≤ k). Throws
/// std::invalid_argument for a Dirichlet face that prescribes some components only (their
/// lifting would differ per component, which one scalar gradient per function cannot carry).
/// A cell `here` does not hold is added with its functions and point count only
/// (TabulatedElements::add_held_elsewhere), not lifted; the count is taken from `listed`
/// (every cell's, ElementTabulator) when it is given, else from the cell's rule.
LiftedDgCells tabulate_lifted_dg_cells(const DgLinearSystem& system, int strength, const TabulatedHere& here = nullptr,
                                       const TabulatedElements* listed = nullptr);

}  // namespace altfem::dg
