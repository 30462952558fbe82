#pragma once
// Which cells a `refine` event marks (docs/scene-schema.md, "Events"), the same for every
// method: by the largest absolute principal stress (Kaufmann et al. 2009 §9.3, Martin et al.
// 2008 §8) or by the traction-jump error indicator, above the threshold, below max_level, in
// the region.
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <vector>

#include "shared/scene/scene.hpp"

namespace altfem {

/// One face two cells share, for the error indicator.
struct SharedFace {
  int first = 0, second = 0;  ///< cells
  double area = 0;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();  ///< unit, either orientation
};

/// A face of one cell on the body's boundary where no Dirichlet condition holds the body,
/// for the error indicator: there the exact traction σn is the prescribed one (0 on a free
/// face), so σ_K n − t is the residual that an interior face's jump is.
struct LoadedBoundaryFace {
  int cell = 0;
  double area = 0;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();   ///< unit, out of the cell
  Eigen::Vector3d traction = Eigen::Vector3d::Zero();  ///< prescribed [Pa]
};

/// The faces the error indicator measures: every interior face, and the boundary faces
/// no Dirichlet condition holds (the traction of a held face is the unknown reaction).
struct IndicatorFaces {
  std::vector<SharedFace> interior;
  std::vector<LoadedBoundaryFace> boundary;
};

/// Per cell, the area-weighted RMS traction residual over its faces,
/// √(Σ_F |F| |r_F|² / Σ_F |F|) [Pa], with r_F = (σ_K − σ_N) n_F on an interior face and
/// σ_K n_F − t_F on a loaded or free boundary face, σ the cells' mean stresses (one per
/// cell): a Kelly-type error indicator (Kelly et al. 1983; deal.II's KellyErrorEstimator
/// integrates the jump of the gradient on the faces and the Neumann residual on the
/// boundary, this takes each cell's mean) — the exact stress is continuous and meets the
/// loads, so these residuals measure the discrete one's error. 0 for a cell without such
/// faces.
Eigen::VectorXd traction_jump_indicator(int cell_count, const IndicatorFaces& faces,
                                        const std::vector<Eigen::Matrix3d>& stresses);

struct RefineMarks {
  std::vector<int> cells;                   ///< marked, ascending
  std::vector<Eigen::Vector3d> directions;  ///< each marked cell's principal direction (1→2's normal)
};

/// The cells `refine` marks: stress (one per cell; with the criterion error_indicator, the
/// indicator over `faces`) above the threshold, centroid (#cells × 3) in the region within
/// `tolerance`, level (#cells, empty: all 0) below max_level. With `fraction`, instead of the
/// threshold, bulk marking (Dörfler 1996) of the cells in the region: the fewest, largest
/// estimates first, whose squared estimates carry that fraction of the sum over them, the
/// estimate of a cell of volume |K| (`volumes`, #cells) and size h = |K|^⅓ being
/// η² = h Σ_F |F| |r_F|² for error_indicator (Kelly et al. 1983's scaling of the energy
/// norm's error) and |K| σ₁² for principal_stress; marked cells at max_level are then left
/// out. `facts` gets marked_cells, at_max_level, largest_stress (and largest_indicator).
RefineMarks mark_cells_to_refine(const RefineSpec& refine, const std::vector<Eigen::Matrix3d>& stresses,
                                 const IndicatorFaces& faces, const Eigen::MatrixXd& centroids,
                                 const Eigen::VectorXd& volumes, const std::vector<int>& levels, double tolerance,
                                 nlohmann::json& facts);

}  // namespace altfem
