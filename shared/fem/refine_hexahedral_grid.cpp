#include "shared/fem/refine_hexahedral_grid.hpp"

#include "shared/fem/refine_marking.hpp"

namespace altfem {

std::string grid_refine_refusal(const RefineSpec& refine, bool scene_cuts) {
  if (refine.split == RefineSplit::halves)
    return "it splits 1to8 only: a hexahedron halved across its principal direction is no cell of the grid";
  if (scene_cuts) return "it does not refine a grid that a cut event cuts yet";
  return "";
}

namespace {

// The leaves' faces on the grid's box that `boundary` does not hold, with its tractions.
std::vector<LoadedBoundaryFace> loaded_box_faces(const HexahedralForest& forest, const PrescribedTraction& boundary) {
  std::vector<LoadedBoundaryFace> faces;
  const Eigen::Vector3i top = forest.resolution * forest_units_per_cell;
  for (int leaf = 0; leaf < forest.leaf_count(); ++leaf) {
    const Eigen::Vector3i low = forest.origins[leaf];
    const Eigen::Vector3i high = low + Eigen::Vector3i::Constant(HexahedralForest::edge_units(forest.levels[leaf]));
    const Eigen::Vector3d from = forest.position(low), to = forest.position(high);
    for (int axis = 0; axis < 3; ++axis)
      for (const int side : {-1, +1}) {
        if (side < 0 ? low[axis] != 0 : high[axis] != top[axis]) continue;
        Eigen::Vector3d centre = 0.5 * (from + to);
        centre[axis] = side < 0 ? from[axis] : to[axis];
        const Eigen::Vector3d normal = side * Eigen::Vector3d::Unit(axis);
        const Eigen::Vector3d extent = to - from;
        if (const auto traction = boundary.at(centre, normal))
          faces.push_back({leaf, extent.prod() / extent[axis], normal, *traction});
      }
  }
  return faces;
}

}  // namespace

std::optional<RefinedGrid> refine_hexahedral_grid(const HexahedralForest& forest, const RefineSpec& refine,
                                                  const std::vector<Eigen::Matrix3d>& stresses,
                                                  const PrescribedTraction* boundary, nlohmann::json& facts) {
  IndicatorFaces faces;
  if (refine.criterion == RefineCriterion::error_indicator) {
    for (const ForestFace& face : forest_interior_faces(forest))
      faces.interior.push_back({face.first, face.second, face.area, Eigen::Vector3d::Unit(face.axis)});
    if (boundary) faces.boundary = loaded_box_faces(forest, *boundary);
  }
  Eigen::MatrixXd centroids(forest.leaf_count(), 3);
  Eigen::VectorXd volumes(forest.leaf_count());
  for (int leaf = 0; leaf < forest.leaf_count(); ++leaf) {
    const int edge = HexahedralForest::edge_units(forest.levels[leaf]);
    const Eigen::Vector3d low = forest.position(forest.origins[leaf]),
                          high = forest.position(forest.origins[leaf] + Eigen::Vector3i::Constant(edge));
    centroids.row(leaf) = 0.5 * (low + high);
    volumes[leaf] = (high - low).prod();
  }
  const RefineMarks marks = mark_cells_to_refine(refine, stresses, faces, centroids, volumes, forest.levels,
                                                 region_tolerance(forest.box), facts);
  facts.update({{"balancing_splits", 0}, {"hanging_nodes", 0}, {"cells", forest.leaf_count()}});
  if (marks.cells.empty()) return std::nullopt;
  int balancing = 0;
  RefinedGrid refined;
  refined.forest = refine_forest(forest, marks.cells, &balancing);
  refined.mesh = forest_mesh(refined.forest);
  facts.update({{"balancing_splits", balancing},
                {"hanging_nodes", refined.mesh.constraints.hanging_nodes()},
                {"cells", refined.forest.leaf_count()}});
  return refined;
}

}  // namespace altfem
