#pragma once
// Builds an AnalyticShape from the resolved JSON of a shape (docs/scene-schema.md,
// "Analytic shapes"). Internal to shared/scene.
#include <nlohmann/json.hpp>

#include "shared/geometry/analytic_shape.hpp"

namespace altfem {

/// `shape` must already be validated (scene_schema.cpp); the result is before the
/// geometry's scale/translate.
ShapePointer shape_from_json(const nlohmann::json& shape);

/// A resolved [3] as a vector.
Eigen::Vector3d vector3_from_json(const nlohmann::json& value);

}  // namespace altfem
