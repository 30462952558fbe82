// The `fem` block of docs/scene-schema.md, as data; keep the two in step.
#include "shared/fem/fem_scene_block.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "shared/mesh/structured_grid.hpp"
#include "shared/mesh/volume_mesh.hpp"
#include "shared/scene/scene_shape.hpp"

namespace altfem {

namespace {

using nlohmann::json;
using scene_schema::KeyRule;
using scene_schema::Validator;
using scene_schema::ValueType;

std::vector<std::string_view> element_names() {
  std::vector<std::string_view> result;
  for (auto type : {ElementType::tet4, ElementType::tet10, ElementType::tet20, ElementType::hex8, ElementType::hex20,
                    ElementType::hex27})
    result.push_back(element_name(type));
  return result;
}

std::string geometry_kind(const json& geometry) {
  if (geometry.contains("surface")) return "a surface file";
  if (geometry.contains("mesh")) return "a volume mesh file";
  return "a '" + geometry["shape"].begin().key() + "' shape";
}

// A volume mesh geometry fixes the element: `element` defaults to the file's and
// must equal it when given.
void resolve_file_element(const Validator& validator, const json& geometry, json& fem, const std::string& pointer) {
  const ElementType in_file = read_volume_mesh(geometry["mesh"].get<std::string>()).element_type;
  const std::string name(element_name(in_file));
  if (!fem.contains("element")) fem["element"] = name;
  if (fem["element"] != name)
    validator.fail(pointer + "/element", "must match the mesh file's element '" + name + "', got '" +
                                             fem["element"].get<std::string>() + "'");
}

// A grid over a shape built of boxes holds it exactly when each of the shape's planes is
// one of the grid's: then every cell lies wholly inside or outside it.
void check_grid_holds_faces(const Validator& validator, const AnalyticShape& shape, const json& fem,
                            const std::string& pointer) {
  const Eigen::AlignedBox3d bounds = shape.bounding_box();
  const AxisPlanes planes = *shape.axis_planes();
  for (int axis = 0; axis < 3; ++axis) {
    const int cells = fem["resolution"][axis].get<int>();
    const double spacing = bounds.sizes()[axis] / cells;
    for (const double plane : planes[axis]) {
      const double index = (plane - bounds.min()[axis]) / spacing;
      if (std::abs(index - std::round(index)) > 1e-9 * cells) {
        std::ostringstream message;
        message << "must put a grid plane on each face of the shape: "
                << "xyz"[axis] << " = " << plane << " falls between the planes " << bounds.min()[axis] << " + k · "
                << spacing;
        validator.fail(pointer + "/resolution", message.str());
        return;
      }
    }
  }
}

// The defaults that depend on the geometry (docs/scene-schema.md, "fem").
void complete_fem(const Validator& validator, const json& scene, json& fem, const std::string& pointer) {
  const json& geometry = scene["geometry"];
  const bool is_box = geometry.contains("shape") && geometry["shape"].contains("box");
  if (!fem.contains("mesh")) fem["mesh"] = geometry.contains("mesh") ? "file" : (is_box ? "grid" : "tetrahedralize");
  const std::string mesh = fem["mesh"];
  if (mesh == "file" && !geometry.contains("mesh"))
    validator.fail(pointer + "/mesh", "'file' needs a volume mesh geometry, got " + geometry_kind(geometry));
  if (mesh == "file") resolve_file_element(validator, geometry, fem, pointer);
  if (!fem.contains("element")) fem["element"] = "tet10";
  const ElementType element = *element_type_from_name(fem["element"].get<std::string>());
  const bool hex = element_shape(element) == ElementShape::hexahedron;
  const ShapePointer shape = geometry.contains("shape") ? shape_from_json(geometry["shape"]) : nullptr;
  const bool built_of_boxes = shape && shape->axis_planes();
  if (mesh == "grid" && !built_of_boxes)
    validator.fail(pointer + "/mesh", "'grid' needs a box or a shape built of boxes, got " + geometry_kind(geometry));
  if (mesh == "grid" && !is_box && !fem.contains("resolution"))
    validator.fail(pointer + "/resolution",
                   "is required for 'grid' on a shape built of boxes: cells whose faces hold the shape's faces");
  if (mesh == "tetrahedralize" && geometry.contains("mesh"))
    validator.fail(pointer + "/mesh",
                   "'tetrahedralize' needs a surface or shape geometry, got " + geometry_kind(geometry));
  if (mesh == "tetrahedralize" && hex)
    validator.fail(pointer + "/element",
                   "'tetrahedralize' needs a tet element, got " + scene_schema::describe(fem["element"]));
  if (mesh != "grid" && fem.contains("resolution"))
    validator.fail(pointer + "/resolution", "applies only to mesh 'grid', got mesh '" + mesh + "'");
  if (mesh != "tetrahedralize" && fem.contains("max_cell_size"))
    validator.fail(pointer + "/max_cell_size", "applies only to mesh 'tetrahedralize', got mesh '" + mesh + "'");

  if (mesh == "grid" && !is_box && built_of_boxes && fem.contains("resolution"))
    check_grid_holds_faces(validator, *shape, fem, pointer);
  const double scale = geometry["scale"].get<double>();
  if (mesh == "grid" && !fem.contains("resolution")) {
    const Eigen::Vector3d extent = scale * (vector3_from_json(geometry["shape"]["box"]["max"]) -
                                            vector3_from_json(geometry["shape"]["box"]["min"]));
    const Eigen::Vector3i resolution = default_grid_resolution(extent);
    fem["resolution"] = {resolution.x(), resolution.y(), resolution.z()};
  }
  // A surface's bounds are known only once it is read: its default stays absent
  // (fem_max_cell_size).
  if (mesh == "tetrahedralize" && !fem.contains("max_cell_size") && geometry.contains("shape"))
    fem["max_cell_size"] = scale * shape_from_json(geometry["shape"])->bounding_box().diagonal().norm() / 15.0;
  // 2 × the degree integrates the mass of simplices and serendipity cells well; the
  // triquadratic Hex27's stiffness has terms up to x²y⁴z⁴, and at strength 4 (or 5) it was
  // integrated so loosely that the cantilever's potential energy rose under refinement,
  // which nested conforming spaces cannot do (the minimum principle; issue #35). Strength
  // 7 is the lowest whose energies agree with strength 9's to 1e-6 and fall as they must.
  if (!fem.contains("quadrature_order"))
    fem["quadrature_order"] = element == ElementType::hex27 ? 7 : 2 * element_degree(element);
}

const scene_schema::ObjectRule fem_rule{
    {{.key = "element", .type = ValueType::string, .choices = element_names()},
     {.key = "mesh", .type = ValueType::string, .choices = scene_schema::names(fem_mesh_names)},
     {.key = "resolution", .type = ValueType::integer3, .lower = scene_schema::at_least_one},
     {.key = "max_cell_size", .type = ValueType::number, .lower = scene_schema::positive},
     {.key = "quadrature_order", .type = ValueType::integer, .lower = scene_schema::at_least_one},
     scene_schema::flag("curved", false),
     {.key = "cut_stabilization",
      .type = ValueType::number,
      .default_value = 0.0,
      .lower = scene_schema::non_negative}}};

}  // namespace

const MethodSceneBlock& fem_scene_block() {
  static const MethodSceneBlock block{"fem", &fem_rule, complete_fem};
  return block;
}

FemSpec fem_spec(const Scene& scene) { return fem_spec_from_block(resolve_method_block(scene, fem_scene_block())); }

FemSpec fem_spec_from_block(const json& fem) {
  FemSpec spec;
  spec.element = *element_type_from_name(fem["element"].get<std::string>());
  const std::string mesh = fem["mesh"];
  spec.mesh =
      static_cast<FemMeshKind>(std::find(fem_mesh_names.begin(), fem_mesh_names.end(), mesh) - fem_mesh_names.begin());
  if (fem.contains("resolution"))
    spec.resolution = {fem["resolution"][0].get<int>(), fem["resolution"][1].get<int>(),
                       fem["resolution"][2].get<int>()};
  if (fem.contains("max_cell_size")) spec.max_cell_size = fem["max_cell_size"].get<double>();
  spec.quadrature_order = fem["quadrature_order"].get<int>();
  spec.curved = fem["curved"].get<bool>();
  spec.cut_stabilization = fem["cut_stabilization"].get<double>();
  return spec;
}

double fem_max_cell_size(const FemSpec& fem, const Eigen::AlignedBox3d& geometry_bounds) {
  return fem.max_cell_size.value_or(geometry_bounds.diagonal().norm() / 15.0);
}

}  // namespace altfem
