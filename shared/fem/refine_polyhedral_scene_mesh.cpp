#include "shared/fem/refine_polyhedral_scene_mesh.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "shared/fem/refine_marking.hpp"
#include "shared/mesh/convex_cell.hpp"
#include "shared/mesh/split_polyhedral_cells.hpp"
#include "shared/simulation/cell_stresses.hpp"

namespace altfem {

namespace {

// The point the split planes pass through: the centroid, or the centre of the cell's box
// when they agree to round-off (a box's centre is its centroid exactly, and halving is exact
// in binary, so that repeated splits of a grid stay on the dyadic grid).
Eigen::Vector3d split_centre(const PolyhedralMesh& mesh, int cell, const std::vector<int>& nodes) {
  Eigen::AlignedBox3d box;
  for (const int node : nodes) box.extend(mesh.nodes.row(node).transpose());
  const Eigen::Vector3d centroid = mesh.cell_centroids.row(cell);
  return (box.center() - centroid).norm() <= 1e-12 * mesh.cell_diameters[cell] ? box.center() : centroid;
}

}  // namespace

std::optional<PolyhedralSceneMesh> refine_polyhedral_scene_mesh(const PolyhedralSceneMesh& mesh,
                                                                const RefineSpec& refine,
                                                                const std::vector<Eigen::Matrix3d>& stresses,
                                                                const PrescribedTraction& boundary,
                                                                nlohmann::json& facts) {
  const PolyhedralMesh& cells = mesh.sliced.mesh;
  if (static_cast<int>(stresses.size()) != cells.cell_count())
    throw std::invalid_argument("refine_polyhedral_scene_mesh: one stress per cell");
  const double tolerance = region_tolerance(
      Eigen::AlignedBox3d(cells.nodes.colwise().minCoeff().transpose(), cells.nodes.colwise().maxCoeff().transpose()));
  IndicatorFaces faces;
  if (refine.criterion == RefineCriterion::error_indicator)
    for (int face = 0; face < cells.face_count(); ++face) {
      const Eigen::Vector3d normal = cells.face_normals.row(face).transpose();  // out of face_cells(face, 0)
      if (!cells.is_boundary_face(face))
        faces.interior.push_back(
            {cells.face_cells(face, 0), cells.face_cells(face, 1), cells.face_areas[face], normal});
      else if (const auto traction = boundary.at(cells.face_centroids.row(face).transpose(), normal))
        faces.boundary.push_back({cells.face_cells(face, 0), cells.face_areas[face], normal, *traction});
    }
  const RefineMarks marks = mark_cells_to_refine(refine, stresses, faces, cells.cell_centroids, cells.cell_volumes,
                                                 mesh.cell_levels, tolerance, facts);
  std::vector<CellSplit> splits;
  int not_convex = 0;
  for (std::size_t m = 0; m < marks.cells.size(); ++m) {
    const int cell = marks.cells[m];
    const std::vector<int> nodes = cell_node_set(cells, cell);
    if (!is_convex_cell(cells, cell, nodes)) {
      ++not_convex;
      continue;
    }
    const Eigen::Vector3d centre = split_centre(cells, cell, nodes);
    CellSplit split{cell, {}};
    if (refine.split == RefineSplit::halves)
      split.planes.push_back(plane_through(cells.cell_centroids.row(cell).transpose(), marks.directions[m]));
    else
      for (int axis = 0; axis < 3; ++axis) split.planes.push_back(plane_through(centre, Eigen::Vector3d::Unit(axis)));
    splits.push_back(std::move(split));
  }
  facts.update({{"marked_cells", splits.size()},
                {"not_convex", not_convex},
                {"new_nodes", 0},
                {"hanging_nodes", 0},
                {"cells", cells.cell_count()}});
  if (splits.empty()) return std::nullopt;
  SplitCells split = split_polyhedral_cells(cells, splits);
  facts["new_nodes"] = split.new_nodes;
  facts["hanging_nodes"] = split.hanging_nodes;
  facts["cells"] = split.mesh.cell_count();
  std::vector<bool> was_split(static_cast<std::size_t>(cells.cell_count()), false);
  for (const CellSplit& marked : splits) was_split[marked.cell] = true;
  PolyhedralSceneMesh result = mesh;
  result.cell_levels.clear();
  for (const int parent : split.parent_cell)
    result.cell_levels.push_back((mesh.cell_levels.empty() ? 0 : mesh.cell_levels[parent]) +
                                 (was_split[parent] ? 1 : 0));
  result.sliced.mesh = std::move(split.mesh);
  result.load_surface = boundary_faces_surface(result.sliced.mesh);
  result.converted.reset();
  result.node_sources.clear();
  result.parent_cells = std::move(split.parent_cell);
  return result;
}

std::optional<PolyhedralSceneMesh> refine_polyhedral_scene_mesh_by_stress(
    const PolyhedralSceneMesh& mesh, const SceneEvent& refine, const TabulatedElements& elements,
    const SceneMaterials& materials, const Eigen::VectorXd& u, const PrescribedTraction& boundary,
    nlohmann::json& facts) {
  return refine_polyhedral_scene_mesh(mesh, refine.refine, mean_cell_stresses(elements, materials.pointers(), u),
                                      boundary, facts);
}

}  // namespace altfem
