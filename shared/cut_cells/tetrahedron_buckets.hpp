#pragma once
// A uniform bucket grid over the tetrahedra of an embedded mesh: which tetrahedra may
// meet a box (a background cell's bounding box). Each tetrahedron is listed in every
// bucket its bounding box overlaps. Read-only after construction: safe to query from
// many threads.
#include <Eigen/Geometry>
#include <vector>

#include "shared/geometry/clip_convex.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

class TetrahedronBuckets {
public:
  /// mesh: any tetrahedral mesh (corner nodes are used); about one tetrahedron per bucket.
  explicit TetrahedronBuckets(const VolumeMesh& mesh);

  /// The corners (4 × 3) of every tetrahedron whose bounding box meets `box`, each once,
  /// in increasing index order, written into `candidates` (cleared first).
  void candidates(const Eigen::AlignedBox3d& box, std::vector<TetrahedronCorners>& candidates) const;
  /// The same as indices into the mesh's cells (ascending), written into `indices` (cleared first).
  void candidate_indices(const Eigen::AlignedBox3d& box, std::vector<int>& indices) const;
  /// The corners (4 × 3) of tetrahedron t.
  const TetrahedronCorners& corners(int t) const { return tetrahedra_[t]; }

  Eigen::Index size() const { return static_cast<Eigen::Index>(tetrahedra_.size()); }

private:
  std::vector<TetrahedronCorners> tetrahedra_;
  std::vector<Eigen::AlignedBox3d> boxes_;
  Eigen::AlignedBox3d bounds_;
  Eigen::Vector3i resolution_;
  Eigen::Vector3d bucket_size_;
  std::vector<std::vector<int>> buckets_;  ///< resolution product, tetrahedron indices ascending

  Eigen::Vector3i bucket_of(const Eigen::Vector3d& x) const;
};

}  // namespace altfem
