#pragma once
// A FaceAssembler bound to a pattern of its own faces only (no volume elements), and a
// non-quadratic face kernel: what the face-assembler tests differentiate, compare
// across thread counts and count allocations of.
#include <memory>

#include "shared/assembly/face_assembler.hpp"
#include "shared/assembly/jump_penalty_kernel.hpp"

namespace altfem::test {

/// E_f = Σ_q w_q |[[u]]_q|⁴ / 4 (not quadratic, so the stiffness depends on u):
///   ∂E/∂u_ai = Σ_q w_q |J|² J_i j_a,   ∂²E/∂u_ai∂u_bk = Σ_q w_q j_a j_b (|J|² δ_ik + 2 J_i J_k),
/// with J = [[u]]_q and j_a = φ_a⁻ − φ_a⁺ at point q.
class QuarticJumpKernel {
public:
  bool is_quadratic() const { return false; }

  template <int N>
  double energy(const FaceView& face, const kernel::NodeMatrix<N>& u) const {
    double total = 0;
    for (int q = 0; q < face.point_count(); ++q)
      total += face.weights[q] * std::pow(jump(face, u, q).squaredNorm(), 2) / 4;
    return total;
  }
  template <int N>
  void forces(const FaceView& face, const kernel::NodeMatrix<N>& u, kernel::NodeMatrix<N>& forces) const {
    forces.setZero();
    for (int q = 0; q < face.point_count(); ++q) {
      const Eigen::RowVector3d j = jump(face, u, q);
      for (int a = 0; a < face.basis_count(); ++a)
        forces.row(a) += face.weights[q] * j.squaredNorm() * trace_jump(face, q, a) * j;
    }
  }
  template <int N>
  void stiffness(const FaceView& face, const kernel::NodeMatrix<N>& u, kernel::LocalMatrix<N>& stiffness) const {
    stiffness.setZero();
    for (int q = 0; q < face.point_count(); ++q) {
      const Eigen::RowVector3d j = jump(face, u, q);
      const Eigen::Matrix3d block =
          face.weights[q] * (j.squaredNorm() * Eigen::Matrix3d::Identity() + 2 * j.transpose() * j);
      for (int b = 0; b < face.basis_count(); ++b)
        for (int a = 0; a < face.basis_count(); ++a)
          stiffness.template block<3, 3>(3 * a, 3 * b) += trace_jump(face, q, a) * trace_jump(face, q, b) * block;
    }
  }

private:
  static double trace_jump(const FaceView& face, int q, int a) {
    return face.values_minus(q, a) - face.values_plus(q, a);
  }
  template <int N>
  static Eigen::RowVector3d jump(const FaceView& face, const kernel::NodeMatrix<N>& u, int q) {
    Eigen::RowVector3d value = Eigen::RowVector3d::Zero();
    for (int a = 0; a < face.basis_count(); ++a) value += trace_jump(face, q, a) * u.row(a);
    return value;
  }
};

/// A face term over `faces` with the pattern of those faces alone.
template <typename Kernel>
struct FaceTerm {
  TabulatedElements no_elements;
  BlockSparsity sparsity;
  FaceAssembler<Kernel> assembler;

  FaceTerm(const TabulatedFaces& faces, Kernel kernel)
      : sparsity(no_elements, faces.basis_groups()), assembler(faces, std::move(kernel)) {
    assembler.bind(sparsity, 0);
  }
  int dof_count() const { return static_cast<int>(sparsity.pattern().rows()); }
  Eigen::VectorXd gradient(const Eigen::VectorXd& u) const {
    Eigen::VectorXd result = Eigen::VectorXd::Zero(dof_count());
    assembler.add_gradient(u, result);
    return result;
  }
  SparseMatrix hessian(const Eigen::VectorXd& u) const {
    SparseMatrix result = sparsity.pattern();
    assembler.add_hessian(u, result);
    return result;
  }
};

}  // namespace altfem::test
