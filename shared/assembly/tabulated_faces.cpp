#include "shared/assembly/tabulated_faces.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace altfem {

namespace {

void append_row_major(const Eigen::Ref<const Eigen::MatrixXd>& matrix, std::vector<double>& packed) {
  for (Eigen::Index row = 0; row < matrix.rows(); ++row)
    for (Eigen::Index column = 0; column < matrix.cols(); ++column) packed.push_back(matrix(row, column));
}

}  // namespace

void TabulatedFaces::add(std::span<const int> basis, std::span<const double> weights,
                         const Eigen::Ref<const Eigen::MatrixXd>& normals,
                         const Eigen::Ref<const Eigen::MatrixXd>& values_minus,
                         const Eigen::Ref<const Eigen::MatrixXd>& values_plus,
                         const Eigen::Ref<const Eigen::MatrixXd>& gradients_minus,
                         const Eigen::Ref<const Eigen::MatrixXd>& gradients_plus, int minus, int plus,
                         const Eigen::Ref<const Eigen::MatrixXd>& hessians_minus,
                         const Eigen::Ref<const Eigen::MatrixXd>& hessians_plus) {
  const auto n = static_cast<Eigen::Index>(basis.size());
  const auto points = static_cast<Eigen::Index>(weights.size());
  const auto values_fit = [&](const auto& values) { return values.rows() == points && values.cols() == n; };
  const auto gradients_fit = [&](const auto& gradients) {
    return gradients.rows() == points * n && gradients.cols() == 3;
  };
  if (normals.rows() != points || normals.cols() != 3 || !values_fit(values_minus) || !values_fit(values_plus) ||
      !gradients_fit(gradients_minus) || !gradients_fit(gradients_plus))
    throw std::invalid_argument(
        "TabulatedFaces::add: normals must be #points × 3, values #points × #basis and "
        "gradients (#points·#basis) × 3");
  const bool with_hessians = hessians_minus.rows() > 0 || hessians_plus.rows() > 0;
  const auto hessians_fit = [&](const auto& hessians) { return hessians.rows() == points * n && hessians.cols() == 9; };
  if (with_hessians && (!hessians_fit(hessians_minus) || !hessians_fit(hessians_plus)))
    throw std::invalid_argument("TabulatedFaces::add: Hessians must be (#points·#basis) × 9");
  if (!weights_.empty() && with_hessians != !hessians_minus_.empty())
    throw std::invalid_argument("TabulatedFaces::add: either every face has Hessians or none has");
  for (Eigen::Index q = 0; q < points; ++q)
    if (std::abs(normals.row(q).norm() - 1.0) > 1e-12)
      throw std::invalid_argument("TabulatedFaces::add: the normal at point " + std::to_string(q) +
                                  " is not a unit vector");
  basis_.add(basis);
  weights_.insert(weights_.end(), weights.begin(), weights.end());
  point_offsets_.push_back(static_cast<long long>(weights_.size()));
  append_row_major(normals, normals_);
  append_row_major(values_minus, values_minus_);
  append_row_major(values_plus, values_plus_);
  append_row_major(gradients_minus, gradients_minus_);
  append_row_major(gradients_plus, gradients_plus_);
  append_row_major(hessians_minus, hessians_minus_);
  append_row_major(hessians_plus, hessians_plus_);
  value_offsets_.push_back(static_cast<long long>(values_minus_.size()));
  minus_.push_back(minus);
  plus_.push_back(plus);
  max_face_basis_ = std::max(max_face_basis_, static_cast<int>(n));
}

void TabulatedFaces::add_held_elsewhere(std::span<const int> basis, int minus, int plus) {
  basis_.add(basis);
  point_offsets_.push_back(point_offsets_.back());
  value_offsets_.push_back(value_offsets_.back());
  minus_.push_back(minus);
  plus_.push_back(plus);
  max_face_basis_ = std::max(max_face_basis_, static_cast<int>(basis.size()));
}

FaceView TabulatedFaces::operator[](int face) const {
  const long long point_begin = point_offsets_[face];
  const auto points = static_cast<Eigen::Index>(point_offsets_[face + 1] - point_begin);
  const long long value_begin = value_offsets_[face];
  const std::span<const int> basis = basis_[face];
  const auto n = static_cast<Eigen::Index>(basis.size());
  return FaceView{basis,
                  std::span<const double>(weights_.data() + point_begin, static_cast<size_t>(points)),
                  normals_.data() + 3 * point_begin,
                  {values_minus_.data() + value_begin, points, n},
                  {values_plus_.data() + value_begin, points, n},
                  gradients_minus_.data() + 3 * value_begin,
                  gradients_plus_.data() + 3 * value_begin,
                  hessians_minus_.empty() ? nullptr : hessians_minus_.data() + 9 * value_begin,
                  hessians_plus_.empty() ? nullptr : hessians_plus_.data() + 9 * value_begin,
                  face,
                  minus_[face],
                  plus_[face]};
}

}  // namespace altfem
