#pragma once
// The face kernel of a penalty on displacement jumps,
//   E_f(u) = η_f / 2 ∫_f |[[u]]|² dA,   [[u]] = u⁻ − u⁺,
// for FaceAssembler. It is the whole face term of the Babuška–Zlámal DG flux
// (Kaufmann et al. 2009 eq. (19), with η_f of eq. (20)), the penalty part of the
// interior-penalty flux (eq. (21)), and, on a boundary face (u⁺ = 0), the quadratic
// part of a weakly imposed homogeneous Dirichlet condition; its data part
// η_f ∫_f g·v dA is a load (Discretization::external_force). A condition on some
// components only penalises those: E_f = η_f / 2 ∫_f |P [[u]]|² with P = diag(mask_f).
// In general the penalty is a symmetric 3 × 3 tensor per face, E_f = ½ ∫_f [[u]]ᵀ T_f [[u]]
// (DG's penalty split into normal and tangential parts, dg/face_matrices.hpp JumpPenalty);
// η_f with a mask is T_f = η_f P.
#include <vector>

#include "shared/assembly/local_matrices.hpp"
#include "shared/assembly/tabulated_faces.hpp"

namespace altfem {

class JumpPenaltyKernel {
public:
  /// tensors: T_f per face of the TabulatedFaces this kernel is assembled over (symmetric).
  explicit JumpPenaltyKernel(std::vector<Eigen::Matrix3d> tensors) : tensors_(std::move(tensors)) {}

  /// penalties: η_f per face; masks: per face, 1 for each penalised component and 0 for
  /// the others (empty: all 1).
  explicit JumpPenaltyKernel(const std::vector<double>& penalties, const std::vector<Eigen::RowVector3d>& masks = {}) {
    for (size_t f = 0; f < penalties.size(); ++f)
      tensors_.push_back(penalties[f] *
                         (masks.empty() ? Eigen::Matrix3d::Identity() : Eigen::Matrix3d(masks[f].asDiagonal())));
  }

  bool is_quadratic() const { return true; }

  template <int N>
  double energy(const FaceView& face, const kernel::NodeMatrix<N>& u) const {
    double total = 0;
    const Eigen::Matrix3d& tensor = tensors_[face.index];
    for (int q = 0; q < face.point_count(); ++q) {
      const Eigen::RowVector3d j = jump(face, u, q);
      total += face.weights[q] * j.dot(j * tensor);
    }
    return 0.5 * total;
  }

  /// f_a = Σ_q w_q j_a(q) T_f [[u]]_q with j_a = φ_a⁻ − φ_a⁺.
  template <int N>
  void forces(const FaceView& face, const kernel::NodeMatrix<N>& u, kernel::NodeMatrix<N>& forces) const {
    forces.setZero();
    const Eigen::Matrix3d& tensor = tensors_[face.index];
    for (int q = 0; q < face.point_count(); ++q) {
      const Eigen::RowVector3d scaled = face.weights[q] * (jump(face, u, q) * tensor);
      for (int a = 0; a < face.basis_count(); ++a)
        forces.row(a) += (face.values_minus(q, a) - face.values_plus(q, a)) * scaled;
    }
  }

  /// K_(3a+i)(3b+k) = Σ_q w_q j_a(q) j_b(q) (T_f)_ik.
  template <int N>
  void stiffness(const FaceView& face, const kernel::NodeMatrix<N>&, kernel::LocalMatrix<N>& stiffness) const {
    stiffness.setZero();
    const int n = face.basis_count();
    const Eigen::Matrix3d& tensor = tensors_[face.index];
    for (int q = 0; q < face.point_count(); ++q) {
      const double scale = face.weights[q];
      for (int b = 0; b < n; ++b) {
        const double jump_b = face.values_minus(q, b) - face.values_plus(q, b);
        for (int a = 0; a < n; ++a) {
          const double entry = scale * (face.values_minus(q, a) - face.values_plus(q, a)) * jump_b;
          stiffness.template block<3, 3>(3 * a, 3 * b) += entry * tensor;
        }
      }
    }
  }

private:
  // [[u]] at point q, summed by hand: an Eigen row-times-matrix product of dynamic
  // size would allocate a temporary.
  template <int N>
  static Eigen::RowVector3d jump(const FaceView& face, const kernel::NodeMatrix<N>& u, int q) {
    Eigen::RowVector3d value = Eigen::RowVector3d::Zero();
    for (int a = 0; a < face.basis_count(); ++a) value += (face.values_minus(q, a) - face.values_plus(q, a)) * u.row(a);
    return value;
  }

  std::vector<Eigen::Matrix3d> tensors_;
};

}  // namespace altfem
