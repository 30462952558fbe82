#include "shared/cut_cells/tetrahedron_buckets.hpp"

#include <algorithm>
#include <cmath>

namespace altfem {

TetrahedronBuckets::TetrahedronBuckets(const VolumeMesh& mesh) {
  if (element_shape(mesh.element_type) != ElementShape::tetrahedron) {
    throw std::invalid_argument("TetrahedronBuckets: the embedded mesh must be tetrahedral");
  }
  const Eigen::Index count = mesh.cells.rows();
  tetrahedra_.resize(count);
  boxes_.resize(count);
  for (Eigen::Index t = 0; t < count; ++t) {
    for (int c = 0; c < 4; ++c) tetrahedra_[t].row(c) = mesh.nodes.row(mesh.cells(t, c));
    boxes_[t] = Eigen::AlignedBox3d(tetrahedra_[t].colwise().minCoeff().transpose(),
                                    tetrahedra_[t].colwise().maxCoeff().transpose());
    bounds_.extend(boxes_[t]);
  }
  const double per_axis = std::max(1.0, std::cbrt(static_cast<double>(count)));
  const Eigen::Vector3d sizes =
      bounds_.isEmpty() ? Eigen::Vector3d(Eigen::Vector3d::Ones()) : Eigen::Vector3d(bounds_.sizes());
  const double bucket = std::max(sizes.maxCoeff() / per_axis, 1e-300);
  for (int d = 0; d < 3; ++d) {
    resolution_(d) = std::clamp(static_cast<int>(std::ceil(sizes(d) / bucket)), 1, 256);
    bucket_size_(d) = std::max(sizes(d), 1e-300) / resolution_(d);
  }
  buckets_.resize(static_cast<std::size_t>(resolution_.prod()));
  for (Eigen::Index t = 0; t < count; ++t) {
    const Eigen::Vector3i low = bucket_of(boxes_[t].min()), high = bucket_of(boxes_[t].max());
    for (int k = low.z(); k <= high.z(); ++k)
      for (int j = low.y(); j <= high.y(); ++j)
        for (int i = low.x(); i <= high.x(); ++i)
          buckets_[i + resolution_.x() * (j + resolution_.y() * k)].push_back(static_cast<int>(t));
  }
}

Eigen::Vector3i TetrahedronBuckets::bucket_of(const Eigen::Vector3d& x) const {
  Eigen::Vector3i index;
  for (int d = 0; d < 3; ++d) {
    const double position = std::floor((x(d) - bounds_.min()(d)) / bucket_size_(d));
    index(d) = static_cast<int>(std::clamp(position, 0.0, static_cast<double>(resolution_(d) - 1)));
  }
  return index;
}

void TetrahedronBuckets::candidate_indices(const Eigen::AlignedBox3d& box, std::vector<int>& indices) const {
  indices.clear();
  if (tetrahedra_.empty() || !bounds_.intersects(box)) return;
  const Eigen::Vector3i low = bucket_of(box.min()), high = bucket_of(box.max());
  for (int k = low.z(); k <= high.z(); ++k)
    for (int j = low.y(); j <= high.y(); ++j)
      for (int i = low.x(); i <= high.x(); ++i) {
        const auto& bucket = buckets_[i + resolution_.x() * (j + resolution_.y() * k)];
        indices.insert(indices.end(), bucket.begin(), bucket.end());
      }
  std::sort(indices.begin(), indices.end());
  indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
  std::erase_if(indices, [&](int t) { return !boxes_[t].intersects(box); });
}

void TetrahedronBuckets::candidates(const Eigen::AlignedBox3d& box, std::vector<TetrahedronCorners>& candidates) const {
  candidates.clear();
  std::vector<int> indices;
  candidate_indices(box, indices);
  for (const int t : indices) candidates.push_back(tetrahedra_[t]);
}

}  // namespace altfem
