#pragma once
// The face kernel of the ghost penalty (Burman 2010; in the form of deal.II's step-85,
// "The Cut Finite Element Method", after Burman & Hansbo 2012) for FaceAssembler:
//   g_F(u, v) = γ_F Σ_{k=0..p} h_F^{2k−1} / (k!)² ∫_F [∂ₙᵏu]·[∂ₙᵏv] dA,
//   E_F(u) = ½ g_F(u, u),   [∂ₙᵏu] = ∂ₙᵏu⁻ − ∂ₙᵏu⁺,
// with p the basis degree and n the face's unit normal. The k = 0 term vanishes for a
// conforming (continuous) basis, so the kernel sums k = 1..p: [∂ₙu] from the traces'
// gradients and, for p = 2, [∂ₙ²u] = nᵀ[H]n from their Hessians (the faces must carry
// them). Penalising every normal derivative up to p weakly makes the piecewise
// polynomial one polynomial over both cells, which is what bounds the conditioning
// however small a cut (step-85's introduction). Per component of u the same scalar
// form, so the local matrix is G ⊗ I₃. Quadratic in u: its Hessian is constant.
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "shared/assembly/local_matrices.hpp"
#include "shared/assembly/tabulated_faces.hpp"

namespace altfem {

class GhostPenaltyKernel {
public:
  /// Most basis functions a face may couple (two Hex27 cells share 9: 45).
  static constexpr int max_face_basis = 64;

  /// For the faces this kernel is assembled over: penalties, γ_F per face (for
  /// elasticity a modulus times a dimensionless γ, so that g_F scales like the
  /// stiffness); sizes, h_F per face; degree p, 1 or 2. Throws std::invalid_argument
  /// unless there is one penalty and one size per face, no face couples more than
  /// max_face_basis functions, and the faces carry Hessians when p = 2 (unless they are
  /// only listed, TabulatedFaces::add_held_elsewhere) (checked here,
  /// not in the parallel assembly loops, where a throw would terminate).
  GhostPenaltyKernel(const TabulatedFaces& faces, std::vector<double> penalties, std::vector<double> sizes, int degree)
      : penalties_(std::move(penalties)), sizes_(std::move(sizes)), degree_(degree) {
    if (degree < 1 || degree > 2)
      throw std::invalid_argument("GhostPenaltyKernel: degree " + std::to_string(degree) + " (only 1 and 2)");
    if (static_cast<int>(penalties_.size()) != faces.size() || static_cast<int>(sizes_.size()) != faces.size())
      throw std::invalid_argument("GhostPenaltyKernel: one penalty and one size per face");
    if (faces.max_face_basis() > max_face_basis)
      throw std::invalid_argument("GhostPenaltyKernel: a face couples " + std::to_string(faces.max_face_basis()) +
                                  " functions (at most " + std::to_string(max_face_basis) + ")");
    if (degree == 2 && faces.point_count() > 0 && !faces.has_hessians())
      throw std::invalid_argument("GhostPenaltyKernel: degree 2 needs faces tabulated with Hessians");
  }

  bool is_quadratic() const { return true; }
  int degree() const { return degree_; }

  template <int N>
  double energy(const FaceView& face, const kernel::NodeMatrix<N>& u) const {
    double total = 0;
    Jumps jumps;
    for (int q = 0; q < face.point_count(); ++q) {
      normal_derivative_jumps(face, q, jumps);
      for (int k = 1; k <= degree_; ++k) {
        const Eigen::RowVector3d jump = jump_of(face, jumps[k - 1], u);
        total += coefficient(face, k) * face.weights[q] * jump.squaredNorm();
      }
    }
    return 0.5 * total;
  }

  /// f_a = Σ_k c_k Σ_q w_q j_ka(q) Σ_b j_kb(q) u_b, with j_ka = [∂ₙᵏφ_a].
  template <int N>
  void forces(const FaceView& face, const kernel::NodeMatrix<N>& u, kernel::NodeMatrix<N>& forces) const {
    forces.setZero();
    Jumps jumps;
    for (int q = 0; q < face.point_count(); ++q) {
      normal_derivative_jumps(face, q, jumps);
      for (int k = 1; k <= degree_; ++k) {
        const Eigen::RowVector3d scaled = coefficient(face, k) * face.weights[q] * jump_of(face, jumps[k - 1], u);
        for (int a = 0; a < face.basis_count(); ++a) forces.row(a) += jumps[k - 1][a] * scaled;
      }
    }
  }

  /// K_(3a+i)(3b+l) = δ_il Σ_k c_k Σ_q w_q j_ka(q) j_kb(q).
  template <int N>
  void stiffness(const FaceView& face, const kernel::NodeMatrix<N>&, kernel::LocalMatrix<N>& stiffness) const {
    stiffness.setZero();
    const int n = face.basis_count();
    Jumps jumps;
    for (int q = 0; q < face.point_count(); ++q) {
      normal_derivative_jumps(face, q, jumps);
      for (int k = 1; k <= degree_; ++k) {
        const double scale = coefficient(face, k) * face.weights[q];
        for (int b = 0; b < n; ++b)
          for (int a = 0; a < n; ++a) {
            const double entry = scale * jumps[k - 1][a] * jumps[k - 1][b];
            for (int i = 0; i < 3; ++i) stiffness(3 * a + i, 3 * b + i) += entry;
          }
      }
    }
  }

private:
  // jumps[k − 1][a] = [∂ₙᵏφ_a] at one point; on the stack (no allocation per face).
  using Jumps = std::array<std::array<double, max_face_basis>, 2>;

  // c_k = γ_F h_F^{2k−1} / (k!)²: h for k = 1, h³/4 for k = 2 (step-85's g_F).
  double coefficient(const FaceView& face, int k) const {
    const double h = sizes_[face.index];
    return k == 1 ? penalties_[face.index] * h : penalties_[face.index] * h * h * h / 4.0;
  }

  void normal_derivative_jumps(const FaceView& face, int q, Jumps& jumps) const {
    const int n = face.basis_count();
    const Eigen::Vector3d normal = face.normal(q);
    const FaceView::Gradients minus = face.gradients_minus_at(q), plus = face.gradients_plus_at(q);
    for (int a = 0; a < n; ++a) jumps[0][a] = (minus.row(a) - plus.row(a)).dot(normal.transpose());
    if (degree_ < 2) return;
    const FaceView::Hessians hessians_minus = face.hessians_minus_at(q), hessians_plus = face.hessians_plus_at(q);
    for (int a = 0; a < n; ++a) {
      double value = 0;  // nᵀ [H_a] n
      for (int j = 0; j < 3; ++j)
        for (int l = 0; l < 3; ++l)
          value += normal[j] * (hessians_minus(a, 3 * j + l) - hessians_plus(a, 3 * j + l)) * normal[l];
      jumps[1][a] = value;
    }
  }

  // Σ_a j_a u_a, summed by hand (a dynamic-size Eigen product would allocate).
  template <int N>
  static Eigen::RowVector3d jump_of(const FaceView& face, const std::array<double, max_face_basis>& jumps,
                                    const kernel::NodeMatrix<N>& u) {
    Eigen::RowVector3d value = Eigen::RowVector3d::Zero();
    for (int a = 0; a < face.basis_count(); ++a) value += jumps[a] * u.row(a);
    return value;
  }

  std::vector<double> penalties_;
  std::vector<double> sizes_;
  int degree_;
};

}  // namespace altfem
