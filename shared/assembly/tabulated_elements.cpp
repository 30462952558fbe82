#include "shared/assembly/tabulated_elements.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "shared/solve/process_ranks.hpp"

namespace altfem {

void TabulatedElements::add(std::span<const int> basis, std::span<const double> weights,
                            const Eigen::Ref<const Eigen::MatrixXd>& values,
                            const Eigen::Ref<const Eigen::MatrixXd>& gradients, int material) {
  const auto basis_size = static_cast<Eigen::Index>(basis.size());
  const auto points = static_cast<Eigen::Index>(weights.size());
  if (values.rows() != points || values.cols() != basis_size || gradients.rows() != points * basis_size ||
      gradients.cols() != 3)
    throw std::invalid_argument(
        "TabulatedElements::add: values must be #points × #basis and gradients (#points·#basis) × 3");
  basis_.insert(basis_.end(), basis.begin(), basis.end());
  basis_offsets_.push_back(static_cast<long long>(basis_.size()));
  weights_.insert(weights_.end(), weights.begin(), weights.end());
  point_offsets_.push_back(static_cast<long long>(weights_.size()));
  // Row-major copies by whole blocks (an entry at a time, these were most of the time a
  // tabulation of fcm's refined grid spent outside its parallel loop).
  const auto value_begin = static_cast<Eigen::Index>(values_.size());
  values_.resize(value_begin + points * basis_size);
  gradients_.resize(3 * values_.size());
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(values_.data() + value_begin,
                                                                                     points, basis_size) = values;
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(gradients_.data() + 3 * value_begin,
                                                                        points * basis_size, 3) = gradients;
  value_offsets_.push_back(static_cast<long long>(values_.size()));
  material_.push_back(material);
  held_.push_back(1);
  whole_point_offsets_.push_back(whole_point_offsets_.back() + points);
  for (int index : basis) basis_count_ = std::max(basis_count_, index + 1);
  max_element_basis_ = std::max(max_element_basis_, static_cast<int>(basis_size));
}

void TabulatedElements::add_held_elsewhere(std::span<const int> basis, int points, int material) {
  if (points < 0) throw std::invalid_argument("TabulatedElements::add_held_elsewhere: a negative point count");
  basis_.insert(basis_.end(), basis.begin(), basis.end());
  basis_offsets_.push_back(static_cast<long long>(basis_.size()));
  point_offsets_.push_back(point_offsets_.back());
  value_offsets_.push_back(value_offsets_.back());
  material_.push_back(material);
  held_.push_back(0);
  whole_point_offsets_.push_back(whole_point_offsets_.back() + points);
  share_ = true;
  for (int index : basis) basis_count_ = std::max(basis_count_, index + 1);
  max_element_basis_ = std::max(max_element_basis_, static_cast<int>(basis.size()));
}

void TabulatedElements::reserve(int elements, long long basis_entries, long long point_entries,
                                long long value_entries) {
  basis_offsets_.reserve(elements + 1);
  point_offsets_.reserve(elements + 1);
  value_offsets_.reserve(elements + 1);
  material_.reserve(elements);
  held_.reserve(elements);
  whole_point_offsets_.reserve(elements + 1);
  basis_.reserve(basis_entries);
  weights_.reserve(point_entries);
  values_.reserve(value_entries);
  gradients_.reserve(3 * value_entries);
}

void TabulatedElements::lay_out(int elements, const std::function<ElementLayout(int)>& layout) {
  long long points = static_cast<long long>(weights_.size()), values = static_cast<long long>(values_.size());
  for (int e = 0; e < elements; ++e) {
    const ElementLayout element = layout(e);
    if (element.points < 0) throw std::invalid_argument("TabulatedElements::lay_out: a negative point count");
    basis_.insert(basis_.end(), element.basis.begin(), element.basis.end());
    basis_offsets_.push_back(static_cast<long long>(basis_.size()));
    const long long held_points = element.held ? element.points : 0;
    points += held_points;
    values += held_points * static_cast<long long>(element.basis.size());
    point_offsets_.push_back(points);
    value_offsets_.push_back(values);
    material_.push_back(element.material);
    held_.push_back(element.held ? 1 : 0);
    share_ = share_ || !element.held;
    whole_point_offsets_.push_back(whole_point_offsets_.back() + element.points);
    for (const int index : element.basis) basis_count_ = std::max(basis_count_, index + 1);
    max_element_basis_ = std::max(max_element_basis_, static_cast<int>(element.basis.size()));
  }
  weights_.resize(static_cast<size_t>(points));
  values_.resize(static_cast<size_t>(values));
  gradients_.resize(3 * static_cast<size_t>(values));
}

ElementSlots TabulatedElements::slots(int element) {
  const auto basis_size = static_cast<Eigen::Index>(basis_offsets_[element + 1] - basis_offsets_[element]);
  const long long point_begin = point_offsets_[element];
  const auto points = static_cast<Eigen::Index>(point_offsets_[element + 1] - point_begin);
  const long long value_begin = value_offsets_[element];
  return ElementSlots{std::span<double>(weights_.data() + point_begin, static_cast<size_t>(points)),
                      {values_.data() + value_begin, points, basis_size},
                      {gradients_.data() + 3 * value_begin, points * basis_size, 3}};
}

void TabulatedElements::keep_only(std::span<const char> keep) {
  if (static_cast<int>(keep.size()) != size())
    throw std::invalid_argument("TabulatedElements::keep_only: one entry per element expected");
  if (share_) throw std::logic_error("TabulatedElements::keep_only: already a share");
  std::vector<long long> point_offsets{0}, value_offsets{0};
  Doubles weights, values, gradients;
  for (int e = 0; e < size(); ++e) {
    if (keep[e]) {
      weights.insert(weights.end(), weights_.begin() + point_offsets_[e], weights_.begin() + point_offsets_[e + 1]);
      values.insert(values.end(), values_.begin() + value_offsets_[e], values_.begin() + value_offsets_[e + 1]);
      gradients.insert(gradients.end(), gradients_.begin() + 3 * value_offsets_[e],
                       gradients_.begin() + 3 * value_offsets_[e + 1]);
    }
    point_offsets.push_back(static_cast<long long>(weights.size()));
    value_offsets.push_back(static_cast<long long>(values.size()));
  }
  share_ = true;
  held_.assign(keep.begin(), keep.end());
  point_offsets_ = std::move(point_offsets);
  value_offsets_ = std::move(value_offsets);
  weights_ = std::move(weights);
  values_ = std::move(values);
  gradients_ = std::move(gradients);
}

void TabulatedElements::sum_over_ranks(std::span<double> values) const {
  if (share_) ranks::sum(values);
}

double TabulatedElements::sum_over_ranks(double value) const { return share_ ? ranks::sum(value) : value; }

ElementView TabulatedElements::operator[](int element) const {
  const long long basis_begin = basis_offsets_[element];
  const long long basis_size = basis_offsets_[element + 1] - basis_begin;
  const long long point_begin = point_offsets_[element];
  const long long points = point_offsets_[element + 1] - point_begin;
  const long long value_begin = value_offsets_[element];
  return ElementView{
      std::span<const int>(basis_.data() + basis_begin, basis_size),
      std::span<const double>(weights_.data() + point_begin, points),
      {values_.data() + value_begin, static_cast<Eigen::Index>(points), static_cast<Eigen::Index>(basis_size)},
      gradients_.data() + 3 * value_begin,
      material_[element]};
}

}  // namespace altfem
