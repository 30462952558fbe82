#include "shared/simulation/mls_embedding.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <exception>
#include <span>
#include <string>
#include <unordered_map>

#include "shared/common/error.hpp"
#include "shared/mesh/disjoint_sets.hpp"

namespace altfem {

namespace {

// Sample indices listed under the cubes of a uniform grid of side `cell`.
class CubeBuckets {
public:
  CubeBuckets(double cell, const Eigen::RowVector3d& origin) : cell_(cell), origin_(origin) {}
  /// Lists `sample` under every cube that the box [low, high] overlaps.
  void insert(int sample, const Eigen::RowVector3d& low, const Eigen::RowVector3d& high) {
    for_each_cube(low, high, [&](long long cube) { buckets_[cube].push_back(sample); });
  }
  /// Visits the samples listed under every cube that the box [low, high] overlaps.
  template <typename Visit>
  void for_each_in(const Eigen::RowVector3d& low, const Eigen::RowVector3d& high, Visit&& visit) const {
    for_each_cube(low, high, [&](long long cube) {
      const auto found = buckets_.find(cube);
      if (found != buckets_.end())
        for (int sample : found->second) visit(sample);
    });
  }

private:
  template <typename Body>
  void for_each_cube(const Eigen::RowVector3d& low, const Eigen::RowVector3d& high, Body&& body) const {
    const Eigen::Vector3i first = cell_of(low), last = cell_of(high);
    for (int i = first.x(); i <= last.x(); ++i)
      for (int j = first.y(); j <= last.y(); ++j)
        for (int k = first.z(); k <= last.z(); ++k) body((static_cast<long long>(i) * 2097152 + j) * 2097152 + k);
  }
  Eigen::Vector3i cell_of(const Eigen::RowVector3d& x) const {
    return ((x - origin_) / cell_).array().floor().cast<int>().transpose();
  }
  double cell_;
  Eigen::RowVector3d origin_;
  std::unordered_map<long long, std::vector<int>> buckets_;
};

// Each sample under the cube that holds it (cubes of the largest support): a point's
// samples within a reach are among those of the cubes its box of that reach overlaps.
CubeBuckets sample_cubes(const Eigen::MatrixXd& samples, double largest_radius) {
  CubeBuckets cubes(largest_radius, samples.colwise().minCoeff());
  for (Eigen::Index i = 0; i < samples.rows(); ++i) cubes.insert(static_cast<int>(i), samples.row(i), samples.row(i));
  return cubes;
}

// Each sample under every cube its own support ball reaches (its bounding box): a point's
// candidates are those of its own cube. On a sliced mesh the spacings range from a grid
// cell's edge to a surface facet's, and a query reaching as far as the largest support
// visited every surface node near a point; cubes of the median support's side give a point
// few candidates and list a large ball in few cubes.
CubeBuckets support_cubes(const Eigen::MatrixXd& samples, const Eigen::VectorXd& radii) {
  std::vector<double> sorted(radii.data(), radii.data() + radii.size());
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  CubeBuckets cubes(std::max(sorted[sorted.size() / 2], 1e-12 * radii.maxCoeff()), samples.colwise().minCoeff());
  for (Eigen::Index i = 0; i < samples.rows(); ++i)
    cubes.insert(static_cast<int>(i), samples.row(i).array() - radii[i], samples.row(i).array() + radii[i]);
  return cubes;
}

// The largest basis function index a point of `embedding` uses, plus one.
int basis_function_bound(const BasisEmbedding& embedding, Eigen::Index point_count) {
  int bound = 0;
  for (Eigen::Index point = 0; point < point_count; ++point)
    for (int function : embedding.basis_of(point)) bound = std::max(bound, function + 1);
  return bound;
}

// One embedded point's samples and weights w_i(x) (eq. (32)).
struct PointWeights {
  std::vector<int> samples;
  std::vector<double> weights;
};

}  // namespace

MlsEmbedding::MlsEmbedding(const ElementBasisEvaluator& basis, const Eigen::MatrixXd& samples,
                           const Eigen::VectorXd& spacing, const Eigen::MatrixXd& points, const MlsOptions& options,
                           const std::vector<std::vector<int>>& sample_elements)
    : stitched_(basis, samples, sample_elements) {
  // Elements joined through the samples they share (a sample evaluates every element
  // holding it, or containing it), as sets of basis functions; a point's piece is its element's.
  const BasisEmbedding located(basis, points);
  DisjointSets pieces(
      std::max(basis_function_bound(stitched_, samples.rows()), basis_function_bound(located, points.rows())));
  for (Eigen::Index sample = 0; sample < samples.rows(); ++sample)
    for (int function : stitched_.basis_of(sample)) pieces.join(stitched_.basis_of(sample).front(), function);
  const auto piece_of = [&pieces](std::span<const int> functions) {
    return functions.empty() ? -1 : pieces.find(functions.front());
  };
  std::vector<int> sample_piece(static_cast<size_t>(samples.rows())), point_piece(static_cast<size_t>(points.rows()));
  for (Eigen::Index sample = 0; sample < samples.rows(); ++sample)
    sample_piece[sample] = piece_of(stitched_.basis_of(sample));
  for (Eigen::Index point = 0; point < points.rows(); ++point) point_piece[point] = piece_of(located.basis_of(point));
  const double largest_radius = options.support * spacing.maxCoeff();
  const CubeBuckets supports = support_cubes(samples, options.support * spacing);
  const CubeBuckets reachable = sample_cubes(samples, largest_radius);  // for enlarged supports (rare)
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
          if (sample_piece[sample] != point_piece[point]) return;
          const double sigma = enlarge * spacing[sample], radius = options.support * sigma;
          const double distance = (samples.row(sample).transpose() - x).norm();
          if (distance >= radius) return;
          const double weight =
              std::exp(-distance * distance / (sigma * sigma)) - std::exp(-radius * radius / (sigma * sigma));
          Eigen::Vector4d p;
          p << 1.0, (samples.row(sample).transpose() - x) / reach;
          moments += weight * p * p.transpose();
          near.push_back(sample);
          theta.push_back(weight);
        };
        if (enlarge == 1.0) supports.for_each_in(x.transpose(), x.transpose(), add);
        else reachable.for_each_in((x.array() - reach).transpose(), (x.array() + reach).transpose(), add);
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eigen(moments);
        if (near.size() < 4 || !(eigen.eigenvalues()[0] > 1e-10 * eigen.eigenvalues()[3])) continue;
        const Eigen::Vector4d row = eigen.eigenvectors() * eigen.eigenvalues().cwiseInverse().asDiagonal() *
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
        throw NumericalError(
            "MLS embedding: embedded point " + std::to_string(point) +
            " has fewer than four non-coplanar mesh nodes of its own piece within 8 times its support");
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

std::vector<std::vector<int>> cells_at_nodes(const PolyhedralMesh& mesh) {
  std::vector<std::vector<int>> cells(static_cast<std::size_t>(mesh.nodes.rows()));
  for (int cell = 0; cell < mesh.cell_count(); ++cell)
    for (const int face : mesh.cell_faces[cell])
      for (const int node : mesh.faces[face])
        if (cells[node].empty() || cells[node].back() != cell) cells[node].push_back(cell);
  return cells;
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
