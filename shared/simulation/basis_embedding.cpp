#include "shared/simulation/basis_embedding.hpp"

#include <omp.h>

#include <algorithm>
#include <exception>

#include "shared/mesh/point_locator.hpp"

namespace altfem {

namespace {

// The slack of a point's candidate boxes: a point on an element's face is a candidate of both sides.
double candidate_slack(const Eigen::MatrixXd& points) {
  return points.rows() > 0 ? 1e-9 * (points.colwise().maxCoeff() - points.colwise().minCoeff()).norm() : 0.0;
}

PointLocator element_locator(const ElementBasisEvaluator& evaluator) {
  std::vector<Eigen::AlignedBox3d> boxes(static_cast<size_t>(evaluator.element_count()));
  for (int e = 0; e < evaluator.element_count(); ++e) boxes[e] = evaluator.element_bounds(e);
  return PointLocator(std::move(boxes));
}

// Entries of one thread's block of consecutive points, from `first` on: their basis
// functions and weights, each point's ending at its `ends` entry.
struct EntryBlock {
  Eigen::Index first = -1;
  std::vector<long long> ends;
  std::vector<int> basis;
  std::vector<double> weights;
};

// Appends to `basis` and `weights` the entries of x in the candidates that hold it (in
// order: the first alone, or every one averaged with BoundaryPointRule::average) and their
// places among the candidates to `holders`; returns how many held it.
int append_inside(const ElementBasisEvaluator& evaluator, const Eigen::Vector3d& x, const std::vector<int>& candidates,
                  std::vector<int>& holders, std::vector<int>& basis, std::vector<double>& weights) {
  const bool average = evaluator.boundary_rule() == BoundaryPointRule::average;
  thread_local std::vector<int> element_basis;  // scratch, not allocated again for every point
  thread_local std::vector<double> values;
  const size_t begin = weights.size();
  int containing = 0;
  for (size_t place = 0; place < candidates.size(); ++place) {
    if (!evaluator.evaluate_inside(candidates[place], x, element_basis, values)) continue;
    ++containing;
    holders.push_back(static_cast<int>(place));
    basis.insert(basis.end(), element_basis.begin(), element_basis.end());
    weights.insert(weights.end(), values.begin(), values.end());
    if (!average) break;
  }
  if (containing > 1)
    for (size_t i = begin; i < weights.size(); ++i) weights[i] /= containing;
  return containing;
}

}  // namespace

BasisEmbedding::BasisEmbedding(const ElementBasisEvaluator& evaluator, const Eigen::MatrixXd& points,
                               const std::vector<std::vector<int>>& point_elements) {
  const PointLocator locator = element_locator(evaluator);
  const double slack = candidate_slack(points);
  const Eigen::Index count = points.rows();
  // The points in the elements in parallel, each thread one block of consecutive points
  // with entries of its own, joined in order after; a point no element holds is
  // extrapolated then, one at a time (evaluate_nearest builds its search on first need).
  // A refined grid's transfer locates tens of thousands of new nodes here.
  std::vector<EntryBlock> blocks;
  std::vector<char> held(static_cast<size_t>(count), 0);
  std::exception_ptr failure;  // the first, rethrown after the parallel region
#pragma omp parallel
  {
#pragma omp single
    blocks.resize(static_cast<size_t>(omp_get_num_threads()));
    EntryBlock& block = blocks[static_cast<size_t>(omp_get_thread_num())];
    std::vector<int> candidates, holders;
#pragma omp for schedule(static)
    for (Eigen::Index point = 0; point < count; ++point) {
      if (block.first < 0) block.first = point;
      try {
        const Eigen::Vector3d x = points.row(point).transpose();
        if (point_elements.empty()) locator.candidates(x, slack, candidates);
        else candidates = point_elements[point];
        holders.clear();
        held[point] = append_inside(evaluator, x, candidates, holders, block.basis, block.weights) > 0;
      } catch (...) {
#pragma omp critical(altfem_basis_embedding_failure)
        if (!failure) failure = std::current_exception();
      }
      block.ends.push_back(static_cast<long long>(block.basis.size()));
    }
  }
  if (failure) std::rethrow_exception(failure);
  std::sort(blocks.begin(), blocks.end(), [](const EntryBlock& a, const EntryBlock& b) { return a.first < b.first; });
  std::vector<int> basis;
  std::vector<double> values;
  for (const EntryBlock& block : blocks) {
    long long begin = 0;
    for (size_t i = 0; i < block.ends.size(); ++i) {
      const Eigen::Index point = block.first + static_cast<Eigen::Index>(i);
      if (held[point]) {
        basis_.insert(basis_.end(), block.basis.begin() + begin, block.basis.begin() + block.ends[i]);
        weights_.insert(weights_.end(), block.weights.begin() + begin, block.weights.begin() + block.ends[i]);
      } else {
        append_nearest(evaluator, points.row(point).transpose(), basis, values);
      }
      offsets_.push_back(static_cast<long long>(basis_.size()));
      begin = block.ends[i];
    }
  }
  relocated_count_ = static_cast<int>(count);
}

BasisEmbedding::BasisEmbedding(const ElementBasisEvaluator& evaluator, const Eigen::MatrixXd& points,
                               const BasisEmbedding* previous)
    : memory_(std::make_unique<Memory>()) {
  // Built without what a later embedding needs, or never told its keys.
  if (previous &&
      (!previous->memory_ || previous->memory_->candidate_keys.size() != previous->memory_->candidates.size()))
    previous = nullptr;
  const PointLocator locator = element_locator(evaluator);
  const double slack = candidate_slack(points);
  std::vector<std::uint64_t> keys(static_cast<size_t>(evaluator.element_count()));
  std::vector<char> known(keys.size(), 0);
  std::vector<int> candidates, holders;
  memory_->points = points;
  for (Eigen::Index point = 0; point < points.rows(); ++point) {
    const Eigen::Vector3d x = points.row(point).transpose();
    locator.candidates(x, slack, candidates);
    holders.clear();
    if (!previous || !keep(evaluator, *previous, point, x, candidates, keys, known, holders)) {
      locate(evaluator, x, candidates, holders);
      ++relocated_count_;
    }
    memory_->candidates.insert(memory_->candidates.end(), candidates.begin(), candidates.end());
    memory_->candidate_offsets.push_back(static_cast<long long>(memory_->candidates.size()));
    memory_->holders.insert(memory_->holders.end(), holders.begin(), holders.end());
    memory_->holder_offsets.push_back(static_cast<long long>(memory_->holders.size()));
  }
}

void BasisEmbedding::locate(const ElementBasisEvaluator& evaluator, const Eigen::Vector3d& x,
                            const std::vector<int>& candidates, std::vector<int>& holders) {
  thread_local std::vector<int> basis;  // scratch, not allocated again for every point
  thread_local std::vector<double> values;
  if (append_inside(evaluator, x, candidates, holders, basis_, weights_) == 0)
    append_nearest(evaluator, x, basis, values);
  offsets_.push_back(static_cast<long long>(basis_.size()));
}

void BasisEmbedding::append_nearest(const ElementBasisEvaluator& evaluator, const Eigen::Vector3d& x,
                                    std::vector<int>& basis, std::vector<double>& values) {
  ++outside_count_;
  max_outside_distance_ = std::max(max_outside_distance_, evaluator.evaluate_nearest(x, basis, values));
  basis_.insert(basis_.end(), basis.begin(), basis.end());
  weights_.insert(weights_.end(), values.begin(), values.end());
}

template <typename KeyOf>
bool BasisEmbedding::kept_holders(const ElementBasisEvaluator& evaluator, const BasisEmbedding& previous,
                                  Eigen::Index point, const Eigen::Vector3d& x, const std::vector<int>& candidates,
                                  const KeyOf& key_of, std::vector<int>& holders) const {
  const Memory& before = *previous.memory_;
  const long long holders_begin = before.holder_offsets[point], holders_end = before.holder_offsets[point + 1];
  const long long first = before.candidate_offsets[point];
  const auto before_count = static_cast<size_t>(before.candidate_offsets[point + 1] - first);
  const auto key_before = [&](size_t place) { return before.candidate_keys[first + static_cast<long long>(place)]; };
  if (evaluator.boundary_rule() == BoundaryPointRule::average) {
    // It averages every holder: every candidate must be as it was, in its place.
    if (candidates.size() != before_count) return false;
    for (size_t place = 0; place < before_count; ++place)
      if (key_of(candidates[place]) == 0 || key_of(candidates[place]) != key_before(place)) return false;
    holders.assign(before.holders.begin() + holders_begin, before.holders.begin() + holders_end);
    return true;
  }
  // The first candidate that holds it: its holder, now wherever an element of its key is.
  const auto holder_before = static_cast<size_t>(before.holders[holders_begin]);
  const std::uint64_t holder_key = key_before(holder_before);
  if (holder_key == 0) return false;
  size_t holder = 0;
  while (holder < candidates.size() && key_of(candidates[holder]) != holder_key) ++holder;
  if (holder == candidates.size() || !evaluator.holds_alone(candidates[holder], x)) return false;
  // Each candidate before it is one that rejected the point there (a key before the
  // holder's: it rejects it as it did, holds_alone) or one the event made that rejects it.
  for (size_t place = 0; place < holder; ++place) {
    const std::uint64_t key = key_of(candidates[place]);
    bool rejected = false;
    for (size_t earlier = 0; earlier < holder_before && !rejected; ++earlier)
      rejected = key != 0 && key == key_before(earlier);
    if (!rejected && !evaluator.rejects(candidates[place], candidates[holder], x)) return false;
  }
  holders.assign(1, static_cast<int>(holder));
  return true;
}

bool BasisEmbedding::keep(const ElementBasisEvaluator& evaluator, const BasisEmbedding& previous, Eigen::Index point,
                          const Eigen::Vector3d& x, const std::vector<int>& candidates,
                          std::vector<std::uint64_t>& keys, std::vector<char>& known, std::vector<int>& holders) {
  const Memory& before = *previous.memory_;
  if (point >= before.points.rows() || before.points.row(point) != x.transpose()) return false;
  // Extrapolated points (no holder) are located again: the nearest element may be a new one.
  if (before.holder_offsets[point] == before.holder_offsets[point + 1]) return false;
  const auto key_of = [&](int element) {
    if (!known[element]) keys[element] = evaluator.element_key(element), known[element] = 1;
    return keys[element];
  };
  if (!kept_holders(evaluator, previous, point, x, candidates, key_of, holders)) return false;
  // The same evaluations in the same order: the entries of the holders, one after the
  // other, each on the functions its element lists now.
  thread_local std::vector<int> functions;
  const size_t begin = basis_.size();
  long long entry = previous.offsets_[point];
  for (const int holder : holders) {
    evaluator.element_functions(candidates[holder], functions);
    basis_.insert(basis_.end(), functions.begin(), functions.end());
    entry += static_cast<long long>(functions.size());
  }
  if (entry != previous.offsets_[point + 1]) {  // a key that did not say what it should: locate it
    basis_.resize(begin);
    holders.clear();
    return false;
  }
  weights_.insert(weights_.end(), previous.weights_.begin() + previous.offsets_[point],
                  previous.weights_.begin() + previous.offsets_[point + 1]);
  offsets_.push_back(static_cast<long long>(basis_.size()));
  return true;
}

void BasisEmbedding::remember_keys(const ElementBasisEvaluator& evaluator) const {
  if (!memory_ || memory_->candidate_keys.size() == memory_->candidates.size()) return;
  std::vector<std::uint64_t> keys(static_cast<size_t>(evaluator.element_count()));
  std::vector<char> known(keys.size(), 0);
  memory_->candidate_keys.clear();
  for (const int element : memory_->candidates) {
    if (!known[element]) keys[element] = evaluator.element_key(element), known[element] = 1;
    memory_->candidate_keys.push_back(keys[element]);
  }
}

Eigen::MatrixXd BasisEmbedding::displacement(const Eigen::VectorXd& u) const {
  const auto count = static_cast<Eigen::Index>(offsets_.size() - 1);
  Eigen::MatrixXd result = Eigen::MatrixXd::Zero(count, 3);
  for (Eigen::Index point = 0; point < count; ++point)
    for (long long entry = offsets_[point]; entry < offsets_[point + 1]; ++entry)
      result.row(point) += weights_[entry] * u.segment<3>(3 * static_cast<Eigen::Index>(basis_[entry])).transpose();
  return result;
}

Eigen::VectorXd BasisEmbedding::load(const Eigen::MatrixXd& forces, int dof_count) const {
  Eigen::VectorXd result = Eigen::VectorXd::Zero(dof_count);
  for (Eigen::Index point = 0; point + 1 < static_cast<Eigen::Index>(offsets_.size()); ++point)
    for (long long entry = offsets_[point]; entry < offsets_[point + 1]; ++entry)
      result.segment<3>(3 * static_cast<Eigen::Index>(basis_[entry])) +=
          weights_[entry] * forces.row(point).transpose();
  return result;
}

}  // namespace altfem
