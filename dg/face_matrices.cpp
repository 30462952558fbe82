#include "dg/face_matrices.hpp"

#include "dg/face_polynomials.hpp"

namespace altfem::dg {

FaceMatrixParts exact_face_matrix_parts(const Eigen::MatrixXd& polygon, const Eigen::Vector3d& normal,
                                        const MonomialBasis& minus, const MonomialBasis* plus,
                                        const LameParameters& minus_lame, const LameParameters& plus_lame,
                                        const JumpPenalty& penalty, Flux flux, const std::array<bool, 3>& components) {
  const int degree = std::max(minus.degree(), plus ? plus->degree() : 0);
  const Eigen::Vector3d centre = minus.centre();
  const double scale = minus.scale();
  const FaceIntegrals face(polygon, degree, centre, scale);  // in the minus element's frame

  // The face's functions: the minus element's, then the plus element's (columns), with the
  // sign of their jump (+1 minus, −1 plus) and the weight of their stress in the average.
  const int n = minus.size() + (plus ? plus->size() : 0);
  const Eigen::Index count = monomial_count(degree);
  Eigen::MatrixXd values(count, n);
  std::array<Eigen::MatrixXd, 3> gradients{Eigen::MatrixXd(count, n), Eigen::MatrixXd(count, n),
                                           Eigen::MatrixXd(count, n)};
  std::vector<double> jump_sign;
  std::vector<LameParameters> lame;  // of each function's side
  const double average = plus ? 0.5 : 1.0;
  for (const MonomialBasis* side : {&minus, plus}) {
    if (side == nullptr) continue;
    const FunctionsInFrame functions = in_frame(*side, centre, scale, degree);
    const auto first = static_cast<Eigen::Index>(jump_sign.size()), size = functions.values.cols();
    values.middleCols(first, size) = functions.values;
    for (int d = 0; d < 3; ++d) gradients[d].middleCols(first, size) = functions.gradients[d];
    jump_sign.insert(jump_sign.end(), size, side == &minus ? 1.0 : -1.0);
    lame.insert(lame.end(), size, side == &minus ? minus_lame : plus_lame);
  }
  // ∫ φ_a φ_b and ∫ φ_a ∂_d φ_b of every pair (n × n each).
  const Eigen::MatrixXd value_products = face.products(values, values);
  std::array<Eigen::MatrixXd, 3> gradient_products;
  if (flux == Flux::interior_penalty)
    for (int d = 0; d < 3; ++d) gradient_products[d] = face.products(values, gradients[d]);
  Eigen::Matrix3d jump_tensor = penalty.tensor(normal);  // P T P
  for (int i = 0; i < 3; ++i)
    if (!components[i]) jump_tensor.row(i).setZero(), jump_tensor.col(i).setZero();
  FaceMatrixParts parts;
  parts.penalty = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  parts.consistency = {parts.penalty, parts.penalty};
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      // Penalty (26): η_f ∫ [[φ_a e_i]]ᵀ T [[φ_b e_k]] = s_a s_b T_ik ∫ φ_a φ_b (T = η_f I unsplit).
      const double jumps = jump_sign[a] * jump_sign[b] * value_products(a, b);
      parts.penalty.block<3, 3>(3 * a, 3 * b) += jumps * jump_tensor;
      if (flux != Flux::interior_penalty) continue;
      // Consistency (24): −∫ [[v]]·{σ(u)}n with v = φ_a e_i, u = φ_b e_k:
      //   (σ(u)n)_i = μ(δ_ik ∇φ_b·n + n_k ∂_iφ_b) + λ n_i ∂_kφ_b, with u's side's λ, μ.
      Eigen::Vector3d value_times_gradient;  // ∫ φ_a ∂_d φ_b
      for (int d = 0; d < 3; ++d) value_times_gradient[d] = gradient_products[d](a, b);
      const double factor = -jump_sign[a] * average;
      const double lambda = lame[b].lambda, mu = lame[b].mu;
      Eigen::MatrixXd& consistency = parts.consistency[jump_sign[b] > 0 ? 0 : 1];  // σ(u) of b's side
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) {
          if (!components[i]) continue;  // P v = 0 for an unprescribed test component
          const double traction = (i == k ? mu * value_times_gradient.dot(normal) : 0.0) +
                                  mu * normal[k] * value_times_gradient[i] +
                                  lambda * normal[i] * value_times_gradient[k];
          consistency(3 * a + i, 3 * b + k) += factor * traction;  // (24); (25) is its transpose
        }
    }
  return parts;
}

Eigen::MatrixXd exact_face_matrix(const Eigen::MatrixXd& polygon, const Eigen::Vector3d& normal,
                                  const MonomialBasis& minus, const MonomialBasis* plus,
                                  const LameParameters& minus_lame, const LameParameters& plus_lame,
                                  const JumpPenalty& penalty, Flux flux, const std::array<bool, 3>& components) {
  const FaceMatrixParts parts =
      exact_face_matrix_parts(polygon, normal, minus, plus, minus_lame, plus_lame, penalty, flux, components);
  return parts.penalty + parts.consistency[0] + parts.consistency[0].transpose() + parts.consistency[1] +
         parts.consistency[1].transpose();
}

}  // namespace altfem::dg
