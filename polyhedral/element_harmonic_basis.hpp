#pragma once
// The harmonic basis of one polyhedral element (Martin et al. 2008 §4-5): for each
// node (vertex) i, the function harmonic inside the element that equals the 2D
// harmonic coordinate of node i on every face (FaceHarmonicCoordinates) — hence 1 at
// node i, 0 at the others, linear along edges, continuous across shared faces up to the
// fit's accuracy. MFS, eq. (11) in 3D: N(x) = Σ_j w_j / ‖x − k_j‖ + a·x + a₀, fitted in
// the least-squares sense to the boundary data at m ≈ 3n collocation points (eq. (14));
// one factorisation serves every node. The linear polynomial makes the basis a partition
// of unity that reproduces linear fields exactly, which is what rules out ghost forces.
#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "polyhedral/face_harmonic_coordinates.hpp"
#include "polyhedral/mfs_options.hpp"
#include "shared/geometry/polyhedron.hpp"
#include "shared/io/binary_cache.hpp"
#include "shared/mesh/polyhedral_cell_location.hpp"

namespace altfem::harmonic {

/// One face's 2D harmonic coordinates as an element sees them: column k of
/// `coordinates` is the element's node nodes[k] (the face's loop in whichever order the
/// coordinates were fitted, e.g. the mesh face's stored loop, which one neighbour sees
/// reversed).
struct ElementFace {
  const FaceHarmonicCoordinates* coordinates = nullptr;
  std::vector<int> nodes;
};

class ElementHarmonicBasis {
public:
  /// The element's nodes are its vertices. Convex or not; faces planar, counter-clockwise
  /// seen from outside. Fits its own face coordinates. Throws std::invalid_argument for a
  /// polyhedron with no face.
  ElementHarmonicBasis(const Polyhedron& element, const MfsOptions& options);
  /// On face coordinates fitted once per mesh face and shared with the neighbour
  /// (faces[f] for element.faces[f]), so both cells interpolate the same boundary data.
  ElementHarmonicBasis(const Polyhedron& element, std::span<const ElementFace> faces, const MfsOptions& options);

  int node_count() const { return static_cast<int>(coefficients_.cols()); }
  /// N_i(x) (#nodes) and ∇N_i(x) (#nodes × 3).
  void evaluate(const Eigen::Vector3d& x, Eigen::VectorXd& values, Eigen::MatrixXd& gradients) const;
  /// N_i(x) (#nodes) alone: one product of the kernel row with the coefficients (what
  /// surface loads and embedded points read, thousands of points per rebuild).
  void evaluate(const Eigen::Vector3d& x, Eigen::VectorXd& values) const;
  /// N_i and ∇N_i at many points (#points × 3) at once, by products of the kernel matrices
  /// with the coefficients: values #points × #nodes, gradients (#points·#nodes) × 3,
  /// point-major (row q·#nodes + i: ∇N_i(x_q)), as a tabulation stores them.
  void evaluate(const Eigen::MatrixXd& points, Eigen::MatrixXd& values, Eigen::MatrixXd& gradients) const;
  /// N_i at each point: #points × #nodes.
  Eigen::MatrixXd values(const Eigen::MatrixXd& points) const;
  /// The kernel centres k_j (#centres × 3, physical coordinates), all outside the element.
  Eigen::MatrixXd centres() const;
  /// The collocation points' RMS misfit of the boundary data, over all nodes (a fit quality).
  double boundary_residual() const { return boundary_residual_; }
  /// ∫_∂e b_i n dA per node (#nodes × 3) of the boundary data b_i — the faces' harmonic
  /// coordinates, which neighbours share — by a strength-6 rule on each face: what
  /// ∫_e ∇N_i dV must be (divergence theorem), and what the consistency correction of
  /// harmonic_tabulation makes the quadrature of the gradients give.
  const Eigen::MatrixXd& boundary_integrals() const { return boundary_integrals_; }

  /// The same basis with its nodes in another order: node i of the result is node
  /// order[i] of this one (the cell numbered otherwise by a rebuilt mesh).
  ElementHarmonicBasis reordered(const std::vector<int>& order) const;
  /// The basis of the cell's image under x ↦ to + factor (x − from), a translation and a
  /// scaling: harmonic_element_bases fits one of several cells alike but for their place
  /// and size and moves it to the others. The fit lives in coordinates about the cell's
  /// centroid in units of its size, so only those two change, and the boundary integrals
  /// (∫ b_i n dA) scale with the area, by factor².
  ElementHarmonicBasis moved(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double factor) const;

  /// Everything the basis evaluates from, bit for bit (harmonic_basis_cache).
  void write(BinaryWriter& out) const;
  /// What write wrote, or nullopt when it does not read back whole and consistent.
  static std::optional<ElementHarmonicBasis> read(BinaryReader& in);
  /// A hash of what write writes (without its magic), made once per basis: what an embedded point's holder is
  /// keyed by (HarmonicBasisEvaluator::element_key) at every rebuild, which hashing the
  /// bases' bytes anew took 5% of a run of cuts.
  std::uint64_t content_key() const { return content_key_; }

private:
  /// Sets content_key_ from the basis as it is now.
  void key_contents();
  ElementHarmonicBasis() = default;
  /// Makes the coefficients reproduce constants and linear fields exactly (`nodes`: the
  /// nodes' local coordinates, #nodes × 3).
  void restore_linear_precision(const Eigen::MatrixX3d& nodes);

  Eigen::Vector3d origin_;
  double scale_ = 1;
  Eigen::MatrixX3d centres_;      // #centres × 3, local (x − origin) / scale
  Eigen::MatrixXd coefficients_;  // (#centres + 4) × #nodes
  double boundary_residual_ = 0;
  Eigen::MatrixXd boundary_integrals_;  // #nodes × 3
  std::uint64_t content_key_ = 0;
};

/// The generalised winding number (shared/mesh/polyhedral_cell_location.hpp).
using altfem::winding_number;

}  // namespace altfem::harmonic
