#include "shared/mesh/point_locator.hpp"

#include <algorithm>
#include <cmath>

namespace altfem {

PointLocator::PointLocator(std::vector<Eigen::AlignedBox3d> boxes) : boxes_(std::move(boxes)) {
  Eigen::AlignedBox3d all;
  double size = 0;
  for (const auto& box : boxes_) {
    all.extend(box);
    size += box.diagonal().norm();
  }
  if (boxes_.empty()) return;
  size = std::max(size / static_cast<double>(boxes_.size()), 1e-300);
  origin_ = all.min();
  spacing_ = size;
  for (int d = 0; d < 3; ++d) counts_[d] = std::clamp(static_cast<int>(std::ceil(all.sizes()[d] / size)), 1, 256);
  buckets_.resize(static_cast<size_t>(counts_[0]) * counts_[1] * counts_[2]);
  for (size_t element = 0; element < boxes_.size(); ++element) {
    const Eigen::Vector3i low = bucket(boxes_[element].min()), high = bucket(boxes_[element].max());
    for (int k = low.z(); k <= high.z(); ++k)
      for (int j = low.y(); j <= high.y(); ++j)
        for (int i = low.x(); i <= high.x(); ++i) buckets_[index({i, j, k})].push_back(static_cast<int>(element));
  }
}

void PointLocator::candidates(const Eigen::Vector3d& x, double slack, std::vector<int>& elements) const {
  elements.clear();
  if (boxes_.empty()) return;
  // A point within `slack` of a bucket border may belong to a box of the next bucket.
  const Eigen::Vector3i low = bucket((x.array() - slack).matrix()), high = bucket((x.array() + slack).matrix());
  for (int k = low.z(); k <= high.z(); ++k)
    for (int j = low.y(); j <= high.y(); ++j)
      for (int i = low.x(); i <= high.x(); ++i)
        for (int element : buckets_[index({i, j, k})]) {
          const auto& box = boxes_[element];
          if ((x.array() >= box.min().array() - slack).all() && (x.array() <= box.max().array() + slack).all())
            elements.push_back(element);
        }
  std::sort(elements.begin(), elements.end());
  elements.erase(std::unique(elements.begin(), elements.end()), elements.end());
}

Eigen::Vector3i PointLocator::bucket(const Eigen::Vector3d& x) const {
  Eigen::Vector3i b;
  for (int d = 0; d < 3; ++d)
    b[d] = std::clamp(static_cast<int>(std::floor((x[d] - origin_[d]) / spacing_)), 0, counts_[d] - 1);
  return b;
}

size_t PointLocator::index(const Eigen::Vector3i& b) const {
  return static_cast<size_t>(b.x()) + counts_[0] * (b.y() + static_cast<size_t>(counts_[1]) * b.z());
}

}  // namespace altfem
