#include "shared/assembly/tabulated_elements.hpp"

#include <algorithm>
#include <stdexcept>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "shared/solve/process_ranks.hpp"

namespace altfem {

// Element e's points, held here or not.
long long TabulatedElements::points_of(int element) const {
  return whole_point_offsets_[element + 1] - whole_point_offsets_[element];
}

void TabulatedElements::append(std::span<const int> basis, long long points, int material, bool held,
                               long long point_begin, long long value_begin) {
  basis_.insert(basis_.end(), basis.begin(), basis.end());
  basis_offsets_.push_back(static_cast<long long>(basis_.size()));
  point_begin_.push_back(point_begin);
  value_begin_.push_back(value_begin);
  material_.push_back(material);
  held_.push_back(held ? 1 : 0);
  share_ = share_ || !held;
  whole_point_offsets_.push_back(whole_point_offsets_.back() + points);
  if (held) held_points_ += points;
  for (const int index : basis) basis_count_ = std::max(basis_count_, index + 1);
  max_element_basis_ = std::max(max_element_basis_, static_cast<int>(basis.size()));
}

void TabulatedElements::add(std::span<const int> basis, std::span<const double> weights,
                            const Eigen::Ref<const Eigen::MatrixXd>& values,
                            const Eigen::Ref<const Eigen::MatrixXd>& gradients, int material) {
  const auto basis_size = static_cast<Eigen::Index>(basis.size());
  const auto points = static_cast<Eigen::Index>(weights.size());
  if (values.rows() != points || values.cols() != basis_size || gradients.rows() != points * basis_size ||
      gradients.cols() != 3)
    throw std::invalid_argument(
        "TabulatedElements::add: values must be #points × #basis and gradients (#points·#basis) × 3");
  const auto point_begin = static_cast<long long>(weights_.size());
  weights_.insert(weights_.end(), weights.begin(), weights.end());
  // Row-major copies by whole blocks (an entry at a time, these were most of the time a
  // tabulation of fcm's refined grid spent outside its parallel loop).
  const auto value_begin = static_cast<Eigen::Index>(values_.size());
  values_.resize(value_begin + points * basis_size);
  gradients_.resize(3 * values_.size());
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(values_.data() + value_begin,
                                                                                     points, basis_size) = values;
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(gradients_.data() + 3 * value_begin,
                                                                        points * basis_size, 3) = gradients;
  append(basis, points, material, true, point_begin, value_begin);
}

void TabulatedElements::add_held_elsewhere(std::span<const int> basis, int points, int material) {
  if (points < 0) throw std::invalid_argument("TabulatedElements::add_held_elsewhere: a negative point count");
  append(basis, points, material, false, 0, 0);
}

void TabulatedElements::reserve(int elements, long long basis_entries, long long point_entries,
                                long long value_entries) {
  basis_offsets_.reserve(elements + 1);
  point_begin_.reserve(elements);
  value_begin_.reserve(elements);
  material_.reserve(elements);
  held_.reserve(elements);
  whole_point_offsets_.reserve(elements + 1);
  basis_.reserve(basis_entries);
  weights_.reserve(point_entries);
  values_.reserve(value_entries);
  gradients_.reserve(3 * value_entries);
}

void TabulatedElements::lay_out(int elements, const std::function<ElementLayout(int)>& layout) {
  const int first = size();
  auto points = static_cast<long long>(weights_.size()), values = static_cast<long long>(values_.size());
  for (int e = 0; e < elements; ++e) {
    const ElementLayout element = layout(e);
    if (element.points < 0) throw std::invalid_argument("TabulatedElements::lay_out: a negative point count");
    const auto basis_size = static_cast<long long>(element.basis.size());
    if (element.held && element.same_points_as >= 0) {
      const int other = first + element.same_points_as;
      if (element.same_points_as >= e || !held_[other] || points_of(other) != element.points ||
          basis_offsets_[other + 1] - basis_offsets_[other] != basis_size)
        throw std::invalid_argument(
            "TabulatedElements::lay_out: an element shares the points of an earlier held element of its sizes only");
      append(element.basis, element.points, element.material, true, point_begin_[other], value_begin_[other]);
      continue;
    }
    append(element.basis, element.points, element.material, element.held, element.held ? points : 0,
           element.held ? values : 0);
    if (!element.held) continue;
    points += element.points;
    values += element.points * basis_size;
  }
  weights_.resize(static_cast<size_t>(points));
  values_.resize(static_cast<size_t>(values));
  gradients_.resize(3 * static_cast<size_t>(values));
}

ElementSlots TabulatedElements::slots(int element) {
  const auto basis_size = static_cast<Eigen::Index>(basis_offsets_[element + 1] - basis_offsets_[element]);
  const long long point_begin = point_begin_[element];
  const auto points = static_cast<Eigen::Index>(held_[element] ? points_of(element) : 0);
  const long long value_begin = value_begin_[element];
  return ElementSlots{std::span<double>(weights_.data() + point_begin, static_cast<size_t>(points)),
                      {values_.data() + value_begin, points, basis_size},
                      {gradients_.data() + 3 * value_begin, points * basis_size, 3}};
}

void TabulatedElements::keep_only(std::span<const char> keep) {
  if (static_cast<int>(keep.size()) != size())
    throw std::invalid_argument("TabulatedElements::keep_only: one entry per element expected");
  if (share_) throw std::logic_error("TabulatedElements::keep_only: already a share");
  // Elements that shared their points keep sharing the one copy.
  std::unordered_map<long long, std::pair<long long, long long>> moved;  // old point begin → new (point, value) begins
  std::vector<long long> point_begin(point_begin_.size(), 0), value_begin(value_begin_.size(), 0);
  Doubles weights, values, gradients;
  held_points_ = 0;
  for (int e = 0; e < size(); ++e) {
    if (!keep[e]) continue;
    const long long points = points_of(e);
    held_points_ += points;
    if (const auto found = moved.find(point_begin_[e]); found != moved.end()) {
      std::tie(point_begin[e], value_begin[e]) = found->second;
      continue;
    }
    const long long value_count = points * (basis_offsets_[e + 1] - basis_offsets_[e]);
    point_begin[e] = static_cast<long long>(weights.size());
    value_begin[e] = static_cast<long long>(values.size());
    moved.emplace(point_begin_[e], std::pair(point_begin[e], value_begin[e]));
    weights.insert(weights.end(), weights_.begin() + point_begin_[e], weights_.begin() + point_begin_[e] + points);
    values.insert(values.end(), values_.begin() + value_begin_[e], values_.begin() + value_begin_[e] + value_count);
    gradients.insert(gradients.end(), gradients_.begin() + 3 * value_begin_[e],
                     gradients_.begin() + 3 * (value_begin_[e] + value_count));
  }
  share_ = true;
  held_.assign(keep.begin(), keep.end());
  point_begin_ = std::move(point_begin);
  value_begin_ = std::move(value_begin);
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
  const long long point_begin = point_begin_[element];
  const long long points = held_[element] ? points_of(element) : 0;
  const long long value_begin = value_begin_[element];
  return ElementView{
      std::span<const int>(basis_.data() + basis_begin, basis_size),
      std::span<const double>(weights_.data() + point_begin, points),
      {values_.data() + value_begin, static_cast<Eigen::Index>(points), static_cast<Eigen::Index>(basis_size)},
      gradients_.data() + 3 * value_begin,
      material_[element]};
}

}  // namespace altfem
