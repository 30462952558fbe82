#pragma once
// The scene's materials, built, and which one each element takes: the first material
// whose region holds the element's centroid, else the first material
// (docs/scene-schema.md, "Material"). Every method assigns by the centroid of its
// element — for the FCM the background cell's, so a cut cell takes one material whole.
#include <Eigen/Core>
#include <memory>
#include <vector>

#include "shared/material/material.hpp"
#include "shared/scene/scene.hpp"

namespace altfem {

class SceneMaterials {
public:
  /// Builds every material of the scene.
  explicit SceneMaterials(const Scene& scene);

  /// One pointer per material, in scene order (material id = index).
  const std::vector<const Material*>& pointers() const { return pointers_; }
  /// The material id of an element with this centroid.
  int id_at(const Eigen::Vector3d& centroid) const;
  /// The ids of elements with these centroids (#elements × 3). Throws InputError naming
  /// /materials/i/region when a material's region selects no element.
  std::vector<int> ids_of(const Eigen::MatrixX3d& centroids) const;

private:
  std::string file_;
  std::vector<MaterialSpec> specs_;
  double tolerance_ = 0;
  std::vector<std::unique_ptr<Material>> materials_;
  std::vector<const Material*> pointers_;
};

}  // namespace altfem
