#include "shared/scene/scene_shape.hpp"

namespace altfem {

Eigen::Vector3d vector3_from_json(const nlohmann::json& value) {
  return {value.at(0).get<double>(), value.at(1).get<double>(), value.at(2).get<double>()};
}

ShapePointer shape_from_json(const nlohmann::json& shape) {
  if (shape.contains("box"))
    return make_box(vector3_from_json(shape["box"]["min"]), vector3_from_json(shape["box"]["max"]));
  if (shape.contains("sphere"))
    return make_sphere(vector3_from_json(shape["sphere"]["centre"]), shape["sphere"]["radius"].get<double>());
  if (shape.contains("cylinder")) {
    const auto& cylinder = shape["cylinder"];
    return make_cylinder(vector3_from_json(cylinder["base"]), vector3_from_json(cylinder["axis"]),
                         cylinder["height"].get<double>(), cylinder["radius"].get<double>(),
                         cylinder["inner_radius"].get<double>());
  }
  const auto children = [](const nlohmann::json& list) {
    std::vector<ShapePointer> result;
    for (const auto& child : list) result.push_back(shape_from_json(child));
    return result;
  };
  if (shape.contains("union")) return make_union(children(shape["union"]));
  if (shape.contains("intersection")) return make_intersection(children(shape["intersection"]));
  return make_difference(children(shape.at("difference")));
}

}  // namespace altfem
