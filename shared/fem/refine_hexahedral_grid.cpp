#include "shared/fem/refine_hexahedral_grid.hpp"

#include "shared/fem/refine_marking.hpp"

namespace altfem {

std::string grid_refine_refusal(const RefineSpec& refine, bool scene_cuts) {
  if (refine.split == RefineSplit::halves)
    return "it splits 1to8 only: a hexahedron halved across its principal direction is no cell of the grid";
  if (scene_cuts) return "it does not refine a grid that a cut event cuts yet";
  return "";
}

std::optional<RefinedGrid> refine_hexahedral_grid(const HexahedralForest& forest, const RefineSpec& refine,
                                                  const std::vector<Eigen::Matrix3d>& stresses, nlohmann::json& facts) {
  std::vector<SharedFace> faces;
  if (refine.criterion == RefineCriterion::error_indicator)
    for (const ForestFace& face : forest_interior_faces(forest))
      faces.push_back({face.first, face.second, face.area, Eigen::Vector3d::Unit(face.axis)});
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
