#include "shared/simulation/mls_embedding.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <map>
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

// A piece's samples under cubes of the piece's largest support: a point's enlarged
// supports (rare) reach only its own piece's samples, and only as far as that piece's
// largest support. One grid of the whole mesh's largest support made each point of a chip
// a blade took off visit every sample of the body beside it.
struct PieceSamples {
  double largest_radius = 0;
  CubeBuckets cubes;
};

// Samples of piece −1 (none asked for) are left out, here and in SupportCubes.
std::unordered_map<int, PieceSamples> piece_samples(const Eigen::MatrixXd& samples, const Eigen::VectorXd& radii,
                                                    const std::vector<int>& sample_piece) {
  std::map<int, double> largest;
  for (Eigen::Index i = 0; i < samples.rows(); ++i)
    if (sample_piece[i] >= 0) largest[sample_piece[i]] = std::max(largest[sample_piece[i]], radii[i]);
  const Eigen::RowVector3d origin = samples.colwise().minCoeff();
  std::unordered_map<int, PieceSamples> pieces;
  for (const auto& [piece, radius] : largest) {
    const double side = std::max(radius, 1e-12 * radii.maxCoeff());
    pieces.emplace(piece, PieceSamples{side, CubeBuckets(side, origin)});
  }
  for (Eigen::Index i = 0; i < samples.rows(); ++i)
    if (sample_piece[i] >= 0)
      pieces.at(sample_piece[i]).cubes.insert(static_cast<int>(i), samples.row(i), samples.row(i));
  return pieces;
}

// Each sample under every cube its own support ball reaches (its bounding box), in one grid
// per piece and power of two of the support radius, with cubes of that level's largest
// radius: a point's candidates are those of its own cube in each level of its own piece.
// On a sliced mesh the spacings range from a grid cell's edge to a surface facet's, and on
// a cut one from the body's cells to the chips a blade took off its tip; one grid of the
// median support's side listed each large ball in (its radius / the median)³ cubes, and
// one grid for every piece had a point at a pencil's tip visit the samples of every chip
// beside it. Here a ball is in at most 27 cubes, and a point meets its own piece alone.
class SupportCubes {
public:
  SupportCubes(const Eigen::MatrixXd& samples, const Eigen::VectorXd& radii, const std::vector<int>& sample_piece) {
    const Eigen::RowVector3d origin = samples.colwise().minCoeff();
    const double smallest = std::max(radii.minCoeff(), 1e-12 * radii.maxCoeff());
    for (Eigen::Index i = 0; i < samples.rows(); ++i) {
      if (sample_piece[i] < 0) continue;
      const int level = std::max(0, static_cast<int>(std::floor(std::log2(radii[i] / smallest))));
      const std::pair<int, int> key(sample_piece[i], level);
      auto slot = grids_.find(key);
      if (slot == grids_.end()) slot = grids_.emplace(key, CubeBuckets(std::ldexp(smallest, level + 1), origin)).first;
      slot->second.insert(static_cast<int>(i), samples.row(i).array() - radii[i], samples.row(i).array() + radii[i]);
    }
  }
  /// Visits, once each, the samples of `piece` whose support's box holds x's cube.
  template <typename Visit>
  void for_each_at(int piece, const Eigen::RowVector3d& x, Visit&& visit) const {
    for (auto grid = grids_.lower_bound({piece, 0}); grid != grids_.end() && grid->first.first == piece; ++grid)
      grid->second.for_each_in(x, x, visit);
  }

private:
  std::map<std::pair<int, int>, CubeBuckets> grids_;  // by (piece, level)
};

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

// A hash of a piece's sample coordinates (their bits): pieces of equal coordinates meet
// under one hash, and are then compared exactly.
std::uint64_t hash_of(const std::vector<double>& coordinates) {
  std::uint64_t hash = 1469598103934665603ull;
  for (const double value : coordinates) {
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    hash = (hash ^ bits) * 1099511628211ull;
  }
  return hash;
}

}  // namespace

MlsEmbedding::MlsEmbedding(const ElementBasisEvaluator& basis, const Eigen::MatrixXd& samples,
                           const Eigen::VectorXd& spacing, const Eigen::MatrixXd& points, const MlsOptions& options,
                           const std::vector<std::vector<int>>& sample_elements, const MlsEmbedding* previous)
    : sample_count_(samples.rows()),
      points_(points),
      point_piece_(static_cast<size_t>(points.rows()), -1),
      stitched_(basis, samples, sample_elements) {
  // Elements joined through the samples they share (a sample evaluates every element
  // holding it, or containing it), as sets of basis functions.
  const int functions = basis_function_bound(stitched_, samples.rows());
  DisjointSets pieces(functions);
  for (Eigen::Index sample = 0; sample < samples.rows(); ++sample)
    for (int function : stitched_.basis_of(sample)) pieces.join(stitched_.basis_of(sample).front(), function);
  const auto piece_of = [&](std::span<const int> basis_functions) {
    return basis_functions.empty() || basis_functions.front() >= functions ? -1 : pieces.find(basis_functions.front());
  };
  std::vector<int> sample_piece(static_cast<size_t>(samples.rows()));
  for (Eigen::Index sample = 0; sample < samples.rows(); ++sample)
    sample_piece[sample] = piece_of(stitched_.basis_of(sample));
  const std::unordered_map<int, int> place = list_pieces(samples, spacing, sample_piece);
  // A point's piece is its element's: a point kept from `previous` lies in its piece's twin
  // (pieces do not overlap at rest), the others are located.
  std::vector<int> sample_after;
  const std::vector<char> kept = keep_points(previous, points, sample_after);
  std::vector<Eigen::Index> moved;
  for (Eigen::Index point = 0; point < points.rows(); ++point)
    if (!kept[point]) moved.push_back(point);
  computed_count_ = static_cast<int>(moved.size());
  Eigen::MatrixXd moved_points(static_cast<Eigen::Index>(moved.size()), 3);
  for (size_t k = 0; k < moved.size(); ++k) moved_points.row(static_cast<Eigen::Index>(k)) = points.row(moved[k]);
  const BasisEmbedding located(basis, moved_points);
  std::vector<int> point_root(static_cast<size_t>(points.rows()), -1);  // the DisjointSets root of a moved point
  for (size_t k = 0; k < moved.size(); ++k) {
    point_root[moved[k]] = piece_of(located.basis_of(static_cast<Eigen::Index>(k)));
    if (const auto slot = place.find(point_root[moved[k]]); slot != place.end()) point_piece_[moved[k]] = slot->second;
  }
  const Eigen::VectorXd radii = options.support * spacing;
  // Only the pieces of the points located: those kept need no samples.
  std::vector<char> asked(static_cast<size_t>(functions), 0);
  for (const Eigen::Index point : moved)
    if (point_root[point] >= 0) asked[point_root[point]] = 1;
  std::vector<int> asked_piece(sample_piece);
  for (int& piece : asked_piece)
    if (piece >= 0 && !asked[piece]) piece = -1;
  const SupportCubes supports(samples, radii, asked_piece);
  const std::unordered_map<int, PieceSamples> reachable = piece_samples(samples, radii, asked_piece);
  std::vector<PointWeights> found(static_cast<size_t>(points.rows()));
  const double truncation = std::exp(-options.support * options.support);
  std::exception_ptr failure;  // an exception must not leave the OpenMP region
#pragma omp parallel
  {
    std::vector<int> near;                  // per thread: no allocation per point
    std::vector<Eigen::Vector4d> weighted;  // θ_i p_i of each near sample
#pragma omp for schedule(dynamic, 32)
    for (Eigen::Index point = 0; point < points.rows(); ++point) {
      try {
        if (kept[point]) continue;  // taken from `previous` below
        const Eigen::Vector3d x = points.row(point).transpose();
        // Eq. (31) around x: p_i = (1, (x_i − x)/ℓ) with ℓ the reach, so the 4 × 4 moment
        // matrix A = Σ θ_i p_i p_iᵀ is O(1); ũ(x) = e₀ᵀ A⁻¹ Σ θ_i p_i ũ_iᵀ, i.e.
        // w_i(x) = θ_i e₀ᵀ A⁻¹ p_i (eq. (32)); ℓ's scale cancels there.
        const auto own = reachable.find(point_root[point]);
        bool solved = false;
        // A point whose piece has no samples has nothing to be embedded by (the error below).
        for (double enlarge = 1.0; own != reachable.end() && enlarge <= 8.0 && !solved; enlarge *= 1.5) {
          near.clear();
          weighted.clear();
          Eigen::Matrix4d moments = Eigen::Matrix4d::Zero();
          const double reach = enlarge * own->second.largest_radius;
          // Both grids hold the point's own piece's samples alone.
          const auto add = [&](int sample) {
            const double sigma = enlarge * spacing[sample], radius = options.support * sigma;
            const Eigen::Vector3d offset = samples.row(sample).transpose() - x;
            const double squared_distance = offset.squaredNorm();
            if (squared_distance >= radius * radius) return;
            // exp(−ρ²/σ²) = exp(−support²): the same for every sample.
            const double weight = std::exp(-squared_distance / (sigma * sigma)) - truncation;
            Eigen::Vector4d p;
            p << 1.0, offset / reach;
            weighted.push_back(weight * p);
            moments += weighted.back() * p.transpose();
            near.push_back(sample);
          };
          if (enlarge == 1.0) supports.for_each_at(point_root[point], x.transpose(), add);
          else own->second.cubes.for_each_in((x.array() - reach).transpose(), (x.array() + reach).transpose(), add);
          if (near.size() < 4) continue;
          // A⁻¹ e₀, where λ_min/λ_max of A exceeds 1e-10. λ_min ≥ 1/‖A⁻¹‖_F and λ_max ≤ tr A
          // bound the ratio from below, and a 4 × 4 inverse costs less than the eigenvalues:
          // only where the bound does not decide do they.
          const Eigen::Matrix4d inverse = moments.inverse();
          Eigen::Vector4d row = inverse.col(0);  // A is symmetric
          if (!(1.0 > 1e-10 * inverse.norm() * moments.trace())) {
            const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eigen(moments);
            if (!(eigen.eigenvalues()[0] > 1e-10 * eigen.eigenvalues()[3])) continue;
            row = eigen.eigenvectors() * eigen.eigenvalues().cwiseInverse().asDiagonal() *
                  eigen.eigenvectors().row(0).transpose();
          }
          PointWeights& result = found[static_cast<size_t>(point)];
          result.weights.reserve(near.size());
          result.samples = near;
          for (const Eigen::Vector4d& theta_p : weighted) result.weights.push_back(row.dot(theta_p));
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
  }
  if (failure) std::rethrow_exception(failure);
  for (Eigen::Index point = 0; point < points.rows(); ++point) {
    const std::size_t start = samples_.size();
    if (kept[point]) {
      for (long long entry = previous->offsets_[point]; entry < previous->offsets_[point + 1]; ++entry)
        samples_.push_back(sample_after[previous->samples_[entry]]);
      weights_.insert(weights_.end(), previous->weights_.begin() + previous->offsets_[point],
                      previous->weights_.begin() + previous->offsets_[point + 1]);
    } else {
      const PointWeights& weighed = found[static_cast<size_t>(point)];
      samples_.insert(samples_.end(), weighed.samples.begin(), weighed.samples.end());
      weights_.insert(weights_.end(), weighed.weights.begin(), weighed.weights.end());
    }
    max_samples_per_point_ = std::max(max_samples_per_point_, static_cast<int>(samples_.size() - start));
    offsets_.push_back(static_cast<long long>(samples_.size()));
  }
}

std::unordered_map<int, int> MlsEmbedding::list_pieces(const Eigen::MatrixXd& samples, const Eigen::VectorXd& spacing,
                                                       const std::vector<int>& sample_piece) {
  std::unordered_map<int, int> place;
  for (Eigen::Index sample = 0; sample < samples.rows(); ++sample) {
    const auto [slot, added] = place.try_emplace(sample_piece[sample], static_cast<int>(pieces_.size()));
    if (added) pieces_.emplace_back();
    pieces_[slot->second].samples.push_back(static_cast<int>(sample));
  }
  const auto coordinates_of = [&](int sample) {
    return std::array<double, 4>{samples(sample, 0), samples(sample, 1), samples(sample, 2), spacing[sample]};
  };
  for (PieceOrder& piece : pieces_) {
    std::sort(piece.samples.begin(), piece.samples.end(),
              [&](int a, int b) { return coordinates_of(a) < coordinates_of(b); });
    for (const int sample : piece.samples)
      for (const double value : coordinates_of(sample)) piece.coordinates.push_back(value);
  }
  return place;
}

std::vector<char> MlsEmbedding::keep_points(const MlsEmbedding* previous, const Eigen::MatrixXd& points,
                                            std::vector<int>& sample_after) {
  std::vector<char> kept(static_cast<size_t>(points.rows()), 0);
  if (!previous) return kept;
  // Each piece of `previous` with the same samples' coordinates as one here: its twin.
  std::unordered_multimap<std::uint64_t, int> before;
  for (size_t piece = 0; piece < previous->pieces_.size(); ++piece)
    before.emplace(hash_of(previous->pieces_[piece].coordinates), static_cast<int>(piece));
  std::vector<int> twin(previous->pieces_.size(), -1);
  sample_after.assign(static_cast<size_t>(previous->sample_count_), -1);
  for (size_t piece = 0; piece < pieces_.size(); ++piece) {
    const auto [first, last] = before.equal_range(hash_of(pieces_[piece].coordinates));
    for (auto match = first; match != last; ++match) {
      const PieceOrder& old = previous->pieces_[match->second];
      if (twin[match->second] >= 0 || old.coordinates != pieces_[piece].coordinates) continue;
      twin[match->second] = static_cast<int>(piece);
      // Samples of one position and spacing have one weight: their order does not matter.
      for (size_t k = 0; k < old.samples.size(); ++k) sample_after[old.samples[k]] = pieces_[piece].samples[k];
      break;
    }
  }
  for (Eigen::Index point = 0; point < std::min(points.rows(), previous->points_.rows()); ++point) {
    const int old_piece = previous->point_piece_[point];
    if (old_piece < 0 || twin[old_piece] < 0 || points.row(point) != previous->points_.row(point)) continue;
    kept[point] = 1;
    point_piece_[point] = twin[old_piece];
  }
  return kept;
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
