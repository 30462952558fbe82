#pragma once
// The moving-least-squares surface embedding of Kaufmann et al. 2009 §7 for a
// discontinuous basis (any ElementBasisEvaluator): the displacement is first stitched at
// sample points — the mesh nodes — by averaging the values of every element containing
// the sample (eq. (30), BoundaryPointRule::average), then interpolated at each embedded
// point x by the affine field a(x)ᵀ(1, x) that minimises
//   Σ_i θ_i(‖x − x_i‖) ‖a(x)ᵀ p(x_i) − ũ_i‖²                                 (31)
// with θ_i a truncated Gaussian. The result is ũ(x) = Σ_i w_i(x) ũ_i (eq. (32)); the
// weights w_i(x) of every embedded point are computed once. Affine fields (rigid
// motions included) are reproduced exactly, and ũ is continuous in x however
// discontinuous the field is across element faces.
//
// Kaufmann et al. draw the samples from a ball around x; where two bodies pass closer than
// the support (two bars 4 mm apart on 0.1 m cells), that ball holds both, and the surface
// of a falling body would follow the body that is held. So a point uses only the samples
// of its own piece: elements joined through shared samples (a sample on a shared face,
// edge or node evaluates every element containing it), a point's piece that of the
// element containing it (or the nearest one).
#include <Eigen/Core>
#include <unordered_map>
#include <vector>

#include "shared/mesh/polyhedral_mesh.hpp"
#include "shared/simulation/basis_embedding.hpp"

namespace altfem {

struct MlsOptions {
  /// θ_i(d) = exp(−d²/σ_i²) − exp(−ρ_i²/σ_i²) for d < ρ_i, else 0 (shifted so that it
  /// vanishes continuously at the truncation radius), with σ_i = spacing_i and
  /// ρ_i = support · spacing_i (Kaufmann et al.: "support radius proportional to the
  /// local sampling density").
  double support = 2.0;
};

class MlsEmbedding final : public PointEmbedding {
public:
  /// samples: #samples × 3 (the mesh nodes); spacing: #samples, the local sample spacing
  /// (e.g. the longest mesh edge at the node); points: #points × 3, the embedded points.
  /// Where fewer than four non-coplanar samples lie within the support of a point, the
  /// support is enlarged for that point. Throws NumericalError if it stays degenerate.
  /// sample_elements (optional, #samples lists): the elements holding each sample node
  /// (cells_at_nodes), which the stitching averages and the pieces are joined through,
  /// instead of every element containing the sample's position: after a cut, the copies
  /// of a node on the blade share a position but not a side.
  /// previous (optional): the embedding before an event. A point at the same index and
  /// position whose piece holds the same samples (positions and spacings) as its piece
  /// there keeps its weights, on those samples' new indices: the weights depend on nothing
  /// else, so they are what this constructor computes, to the rounding of the order the
  /// samples are summed in. A cut appends the surface's new vertices, so the chips and
  /// bodies a cut left alone keep their points' weights.
  MlsEmbedding(const ElementBasisEvaluator& basis, const Eigen::MatrixXd& samples, const Eigen::VectorXd& spacing,
               const Eigen::MatrixXd& points, const MlsOptions& options = {},
               const std::vector<std::vector<int>>& sample_elements = {}, const MlsEmbedding* previous = nullptr);

  /// Displacement at every embedded point (#points × 3) from the coefficients u.
  Eigen::MatrixXd displacement(const Eigen::VectorXd& u) const override;
  /// {"mls_max_samples_per_vertex", "surface_vertices_relocated": the points whose weights
  /// were computed (all but those kept from `previous`)}.
  nlohmann::json facts() const override {
    return {{"mls_max_samples_per_vertex", max_samples_per_point_}, {"surface_vertices_relocated", computed_count_}};
  }
  /// The stitched sample displacements ũ_i of eq. (30) (#samples × 3).
  Eigen::MatrixXd stitched(const Eigen::VectorXd& u) const { return stitched_.displacement(u); }
  /// The largest number of samples one point's weights use.
  int max_samples_per_point() const { return max_samples_per_point_; }

private:
  // What the embedding after an event compares with: the points, and per point its piece's
  // samples in the order of their positions and spacings (pieces_[point_piece_[point]]).
  struct PieceOrder {
    std::vector<int> samples;         // sorted by (position, spacing)
    std::vector<double> coordinates;  // x, y, z, spacing of each, in that order
  };
  /// Fills pieces_ from the samples' pieces (DisjointSets roots); returns each root's place.
  std::unordered_map<int, int> list_pieces(const Eigen::MatrixXd& samples, const Eigen::VectorXd& spacing,
                                           const std::vector<int>& sample_piece);
  /// Per point, whether it keeps its weights from `previous` (the constructor's comment
  /// says when), setting point_piece_ of those; `sample_after`: per sample of `previous`
  /// in a piece with a twin here, its index here (else −1).
  std::vector<char> keep_points(const MlsEmbedding* previous, const Eigen::MatrixXd& points,
                                std::vector<int>& sample_after);

  Eigen::Index sample_count_ = 0;
  Eigen::MatrixXd points_;
  std::vector<int> point_piece_;  // per point: its place in pieces_, −1 for none
  std::vector<PieceOrder> pieces_;

  BasisEmbedding stitched_;
  std::vector<long long> offsets_{0};  // #points + 1
  std::vector<int> samples_;
  std::vector<double> weights_;
  int max_samples_per_point_ = 0;
  int computed_count_ = 0;
};

/// Per node of a polyhedral mesh the longest mesh edge at it (#nodes): the MLS sample
/// spacing at the mesh nodes.
Eigen::VectorXd longest_edge_at_nodes(const PolyhedralMesh& mesh);
/// Per node of a polyhedral mesh the cells holding it (ascending): MlsEmbedding's
/// sample_elements when the mesh's cells are the evaluator's elements.
std::vector<std::vector<int>> cells_at_nodes(const PolyhedralMesh& mesh);

}  // namespace altfem
