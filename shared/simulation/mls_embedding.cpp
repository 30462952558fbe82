#include "shared/simulation/mls_embedding.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <exception>
#include <string>
#include <unordered_map>

#include "shared/common/error.hpp"

namespace altfem {

namespace {

// Samples bucketed in a uniform grid of cubes of side `cell`.
class SampleGrid {
public:
  SampleGrid(const Eigen::MatrixXd& samples, double cell) : cell_(cell), origin_(samples.colwise().minCoeff()) {
    for (Eigen::Index i = 0; i < samples.rows(); ++i) buckets_[key(cell_of(samples.row(i)))].push_back(static_cast<int>(i));
  }
  /// Every sample within `radius` cells' reach of x (a superset of those within radius).
  template <typename Visit>
  void for_each_near(const Eigen::Vector3d& x, double radius, Visit&& visit) const {
    const Eigen::Vector3i low = cell_of((x.array() - radius).matrix().transpose());
    const Eigen::Vector3i high = cell_of((x.array() + radius).matrix().transpose());
    for (int i = low.x(); i <= high.x(); ++i)
      for (int j = low.y(); j <= high.y(); ++j)
        for (int k = low.z(); k <= high.z(); ++k) {
          const auto found = buckets_.find(key({i, j, k}));
          if (found == buckets_.end()) continue;
          for (int sample : found->second) visit(sample);
        }
  }

private:
  Eigen::Vector3i cell_of(const Eigen::RowVector3d& x) const {
    return ((x - origin_) / cell_).array().floor().cast<int>().transpose();
  }
  static long long key(const Eigen::Vector3i& cell) {
    return (static_cast<long long>(cell.x()) * 2097152 + cell.y()) * 2097152 + cell.z();
  }
  double cell_;
  Eigen::RowVector3d origin_;
  std::unordered_map<long long, std::vector<int>> buckets_;
};

// Samples listed under every cube of a uniform grid that their own support ball reaches
// (its bounding box): a point's candidates are those of its cube. On a sliced mesh the
// spacings range from a grid cell's edge to a surface facet's, and a query reaching as far
// as the largest support visited every surface node near a point; the cube's side is the
// median support, so a point sees few candidates and a large ball is listed in few cubes.
class SupportGrid {
public:
  SupportGrid(const Eigen::MatrixXd& samples, const Eigen::VectorXd& radii) {
    std::vector<double> sorted(radii.data(), radii.data() + radii.size());
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
    cell_ = std::max(sorted[sorted.size() / 2], 1e-12 * radii.maxCoeff());
    origin_ = samples.colwise().minCoeff();
    for (Eigen::Index i = 0; i < samples.rows(); ++i) {
      const Eigen::Vector3i low = cell_of(samples.row(i).array() - radii[i]);
      const Eigen::Vector3i high = cell_of(samples.row(i).array() + radii[i]);
      for (int a = low.x(); a <= high.x(); ++a)
        for (int b = low.y(); b <= high.y(); ++b)
          for (int c = low.z(); c <= high.z(); ++c) buckets_[key({a, b, c})].push_back(static_cast<int>(i));
    }
  }
  /// The samples whose support may hold x (a superset of those that do).
  const std::vector<int>& at(const Eigen::Vector3d& x) const {
    static const std::vector<int> none;
    const auto found = buckets_.find(key(cell_of(x.transpose())));
    return found == buckets_.end() ? none : found->second;
  }

private:
  Eigen::Vector3i cell_of(const Eigen::RowVector3d& x) const {
    return ((x - origin_) / cell_).array().floor().cast<int>().transpose();
  }
  static long long key(const Eigen::Vector3i& cell) {
    return (static_cast<long long>(cell.x()) * 2097152 + cell.y()) * 2097152 + cell.z();
  }
  double cell_;
  Eigen::RowVector3d origin_;
  std::unordered_map<long long, std::vector<int>> buckets_;
};

// One embedded point's samples and weights w_i(x) (eq. (32)).
struct PointWeights {
  std::vector<int> samples;
  std::vector<double> weights;
};

}  // namespace

MlsEmbedding::MlsEmbedding(const ElementBasisEvaluator& basis, const Eigen::MatrixXd& samples,
                           const Eigen::VectorXd& spacing, const Eigen::MatrixXd& points, const MlsOptions& options)
    : stitched_(basis, samples) {
  const double largest_radius = options.support * spacing.maxCoeff();
  const SupportGrid supports(samples, options.support * spacing);
  const SampleGrid grid(samples, largest_radius);  // for enlarged supports (rare)
  std::vector<PointWeights> found(static_cast<size_t>(points.rows()));
  std::exception_ptr failure;  // an exception must not leave the OpenMP region
#pragma omp parallel for schedule(dynamic, 256)
  for (Eigen::Index point = 0; point < points.rows(); ++point) {
    try {
      const Eigen::Vector3d x = points.row(point).transpose();
      std::vector<int> near;
      std::vector<double> theta;
      // Eq. (31) around x: p_i = (1, (x_i − x)/ℓ) with ℓ the reach, so the 4 × 4 moment
      // matrix A = Σ θ_i p_i p_iᵀ is O(1); ũ(x) = e₀ᵀ A⁻¹ Σ θ_i p_i ũ_iᵀ, i.e.
      // w_i(x) = θ_i e₀ᵀ A⁻¹ p_i (eq. (32)).
      bool solved = false;
      for (double enlarge = 1.0; enlarge <= 8.0 && !solved; enlarge *= 1.5) {
        near.clear();
        theta.clear();
        Eigen::Matrix4d moments = Eigen::Matrix4d::Zero();
        const double reach = enlarge * largest_radius;
        const auto add = [&](int sample) {
          const double sigma = enlarge * spacing[sample], radius = options.support * sigma;
          const double distance = (samples.row(sample).transpose() - x).norm();
          if (distance >= radius) return;
          const double weight = std::exp(-distance * distance / (sigma * sigma)) -
                                std::exp(-radius * radius / (sigma * sigma));
          Eigen::Vector4d p;
          p << 1.0, (samples.row(sample).transpose() - x) / reach;
          moments += weight * p * p.transpose();
          near.push_back(sample);
          theta.push_back(weight);
        };
        if (enlarge == 1.0)
          for (int sample : supports.at(x)) add(sample);
        else
          grid.for_each_near(x, reach, add);
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eigen(moments);
        if (near.size() < 4 || !(eigen.eigenvalues()[0] > 1e-10 * eigen.eigenvalues()[3])) continue;
        const Eigen::Vector4d row = eigen.eigenvectors() *
                                    eigen.eigenvalues().cwiseInverse().asDiagonal() *
                                    eigen.eigenvectors().row(0).transpose();  // A⁻¹ e₀
        PointWeights& result = found[static_cast<size_t>(point)];
        for (size_t n = 0; n < near.size(); ++n) {
          Eigen::Vector4d p;
          p << 1.0, (samples.row(near[n]).transpose() - x) / reach;
          result.samples.push_back(near[n]);
          result.weights.push_back(theta[n] * row.dot(p));
        }
        solved = true;
      }
      if (!solved)
        throw NumericalError("MLS embedding: embedded point " + std::to_string(point) +
                             " has fewer than four non-coplanar mesh nodes within 8 times its support");
    } catch (...) {
#pragma omp critical(mls_embedding_failure)
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
  for (const PointWeights& point : found) {
    samples_.insert(samples_.end(), point.samples.begin(), point.samples.end());
    weights_.insert(weights_.end(), point.weights.begin(), point.weights.end());
    max_samples_per_point_ = std::max(max_samples_per_point_, static_cast<int>(point.samples.size()));
    offsets_.push_back(static_cast<long long>(samples_.size()));
  }
}

Eigen::VectorXd longest_edge_at_nodes(const PolyhedralMesh& mesh) {
  Eigen::VectorXd spacing = Eigen::VectorXd::Zero(mesh.nodes.rows());
  for (const auto& loop : mesh.faces)
    for (size_t k = 0; k < loop.size(); ++k) {
      const int a = loop[k], b = loop[(k + 1) % loop.size()];
      const double length = (mesh.nodes.row(a) - mesh.nodes.row(b)).norm();
      spacing[a] = std::max(spacing[a], length);
      spacing[b] = std::max(spacing[b], length);
    }
  return spacing;
}

Eigen::MatrixXd MlsEmbedding::displacement(const Eigen::VectorXd& u) const {
  const Eigen::MatrixXd stitched = stitched_.displacement(u);
  const auto count = static_cast<Eigen::Index>(offsets_.size() - 1);
  Eigen::MatrixXd result = Eigen::MatrixXd::Zero(count, 3);
  for (Eigen::Index point = 0; point < count; ++point)
    for (long long entry = offsets_[point]; entry < offsets_[point + 1]; ++entry)
      result.row(point) += weights_[entry] * stitched.row(samples_[entry]);
  return result;
}

}  // namespace altfem
