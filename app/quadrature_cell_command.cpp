// `altfem quadrature cell`: the initial and simplified rules of one cube of a scene's
// background grid (Longva et al. 2020, §4.4–4.5), as VTU point clouds with weights, for
// inspection and teaching. The scene's fcm block does not exist yet: the grid comes
// from the command line.
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/commands.hpp"
#include "fcm/embedded_mesh.hpp"
#include "shared/common/error.hpp"
#include "shared/cut_cells/cell_rules.hpp"
#include "shared/element/geometry_map.hpp"
#include "shared/element/reference_element.hpp"
#include "shared/io/unstructured_grid.hpp"
#include "shared/io/vtu_writer.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/scene/scene.hpp"
#include "shared/scene/scene_geometry.hpp"

namespace altfem::cli {

namespace {

constexpr int vtk_vertex = 1;

/// "n" or "nx,ny,nz" (option `key`); each entry >= 1.
Eigen::Vector3i parse_triple(const std::string& text, const std::string& key, int minimum) {
  std::vector<int> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    try {
      std::size_t used = 0;
      values.push_back(std::stoi(item, &used));
      if (used != item.size()) values.back() = minimum - 1;
    } catch (const std::exception&) {
      values.push_back(minimum - 1);
    }
  }
  if (values.size() == 1 && key == "--resolution") values.assign(3, values[0]);
  if (values.size() != 3 || *std::min_element(values.begin(), values.end()) < minimum) {
    throw InputError(input_message(
        "command line", key,
        "expected three integers >= " + std::to_string(minimum) + " separated by commas, got '" + text + "'"));
  }
  return {values[0], values[1], values[2]};
}

/// The rules of `cells` as one VTU of vertices: physical positions, the reference
/// weight, the physical weight w·|J| and the background cell index.
void write_rules(const std::filesystem::path& path, const VolumeMesh& background,
                 const std::vector<Eigen::Index>& cells, const CellRules& rules) {
  UnstructuredGrid grid;
  Eigen::Index total = 0;
  for (const auto& cell : rules.cells) total += cell.rule.points.rows();
  grid.points.resize(total, 3);
  Eigen::MatrixXd weight(total, 1), physical_weight(total, 1), cell_index(total, 1);
  const ElementType corner_type =
      element_shape(background.element_type) == ElementShape::tetrahedron ? ElementType::tet4 : ElementType::hex8;
  const ReferenceElement& element = reference_element(corner_type);
  Eigen::Index row = 0;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    Eigen::MatrixXd corners(element.node_count(), 3);
    for (int i = 0; i < element.node_count(); ++i) corners.row(i) = background.nodes.row(background.cells(c, i));
    const QuadratureRule& rule = rules.cells[c].rule;
    for (Eigen::Index q = 0; q < rule.points.rows(); ++q, ++row) {
      const Eigen::Vector3d xi = rule.points.row(q).transpose();
      grid.points.row(row) = map_to_physical(element, corners, xi).transpose();
      weight(row) = rule.weights(q);
      physical_weight(row) = rule.weights(q) * std::abs(map_jacobian(element, corners, xi).determinant());
      cell_index(row) = static_cast<double>(cells[c]);
      grid.cell_types.push_back(vtk_vertex);
      grid.connectivity.push_back(row);
      grid.offsets.push_back(row + 1);
    }
  }
  grid.point_data = {{"weight", weight}, {"physical_weight", physical_weight}, {"cell", cell_index}};
  write_vtu(path, grid);
}

}  // namespace

int quadrature_cell_command(const std::filesystem::path& scene_file, const std::string& cell_text,
                            const std::string& cell_type_name, const std::string& resolution_text, int order,
                            const std::string& simplifier, const std::filesystem::path& output, bool json) {
  const auto cell_type = element_type_from_name(cell_type_name);
  if (!cell_type || *cell_type == ElementType::tet20) {
    throw InputError(input_message("command line", "--cell-type",
                                   "expected hex8, hex20, hex27, tet4 or tet10, got '" + cell_type_name + "'"));
  }
  if (order < 1 || order > 20) {
    throw InputError(input_message("command line", "--order", "expected 1..20, got " + std::to_string(order)));
  }
  const Eigen::Vector3i resolution = parse_triple(resolution_text, "--resolution", 1);
  const Eigen::Vector3i cube = parse_triple(cell_text, "--cell", 0);
  if ((cube.array() >= resolution.array()).any()) {
    throw InputError(input_message("command line", "--cell",
                                   "index '" + cell_text + "' is outside the " + resolution_text + " grid"));
  }
  const SimplificationMethod method = parse_simplification_method(simplifier);

  const Scene scene = load_scene(scene_file);
  const SceneGeometry geometry = load_scene_geometry(scene);
  const VolumeMesh grid = structured_grid(geometry.bounds, resolution, *cell_type);
  const double cell_size = geometry.bounds.sizes().cwiseQuotient(resolution.cast<double>()).minCoeff();
  // Embedded tetrahedra a few times smaller than the background cells, as in §6.
  const VolumeMesh embedded = fcm::embedded_tetrahedra(geometry, cell_size / 3.0, scene_file.string());

  // The cube's background cells: one hexahedron, or Kuhn's six tetrahedra.
  const int per_cube = element_shape(*cell_type) == ElementShape::tetrahedron ? 6 : 1;
  const Eigen::Index first = per_cube * (cube.x() + resolution.x() * (cube.y() + resolution.y() * cube.z()));
  std::vector<Eigen::Index> cells;
  VolumeMesh selected{grid.element_type, grid.nodes, grid.cells.middleRows(first, per_cube)};
  for (int i = 0; i < per_cube; ++i) cells.push_back(first + i);

  CellRuleOptions options;
  options.order = order;
  options.method = method;
  options.simplify = false;
  const CellRules initial = compute_cell_rules(selected, embedded, options);
  options.simplify = true;
  const CellRules simplified = compute_cell_rules(selected, embedded, options);

  std::filesystem::create_directories(output);
  const std::filesystem::path initial_path = output / "initial_rule.vtu",
                              simplified_path = output / "simplified_rule.vtu";
  write_rules(initial_path, selected, cells, initial);
  write_rules(simplified_path, selected, cells, simplified);

  nlohmann::json report = {{"cells", cells},
                           {"cut_cells", simplified.cut_cells},
                           {"inside_cells", simplified.inside_cells},
                           {"initial_points", initial.final_points},
                           {"final_points", simplified.final_points},
                           {"basis_size", (order + 1) * (order + 2) * (order + 3) / 6},
                           {"max_residual", simplified.max_residual},
                           {"failed_simplifications", simplified.failed_simplifications},
                           {"embedded_tetrahedra", embedded.cells.rows()},
                           {"files", {initial_path.string(), simplified_path.string()}}};
  double volume = 0.0;
  for (const auto& cell : simplified.cells) volume += cell.clipped_volume;
  report["clipped_volume"] = volume;
  if (json) {
    std::printf("%s\n", report.dump(2).c_str());
  } else {
    std::printf(
        "cells %s: %d cut, %d inside; %lld -> %lld points (M = %d), max residual %.2e, clipped volume %.6g\n"
        "wrote %s and %s\n",
        cell_text.c_str(), simplified.cut_cells, simplified.inside_cells, static_cast<long long>(initial.final_points),
        static_cast<long long>(simplified.final_points), report["basis_size"].get<int>(), simplified.max_residual,
        volume, initial_path.c_str(), simplified_path.c_str());
  }
  return exit_ok;
}

}  // namespace altfem::cli
