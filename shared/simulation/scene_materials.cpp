#include "shared/simulation/scene_materials.hpp"

#include "shared/common/error.hpp"

namespace altfem {

SceneMaterials::SceneMaterials(const Scene& scene) : file_(scene.file.string()), specs_(scene.materials) {
  for (const MaterialSpec& spec : specs_) {
    materials_.push_back(
        make_material(*material_model_from_name(spec.model), spec.youngs_modulus, spec.poisson_ratio, spec.density));
    pointers_.push_back(materials_.back().get());
  }
}

int SceneMaterials::id_at(const Eigen::Vector3d& centroid) const {
  for (std::size_t m = 0; m < specs_.size(); ++m)
    if (specs_[m].region && specs_[m].region->contains(centroid, 0.0)) return static_cast<int>(m);
  return 0;
}

std::vector<int> SceneMaterials::ids_of(const Eigen::MatrixX3d& centroids) const {
  std::vector<int> ids(centroids.rows());
  std::vector<int> counts(specs_.size(), 0);
  for (Eigen::Index e = 0; e < centroids.rows(); ++e) ++counts[ids[e] = id_at(centroids.row(e).transpose())];
  for (std::size_t m = 0; m < specs_.size(); ++m)
    if (specs_[m].region && counts[m] == 0)
      throw InputError(input_message(file_, specs_[m].region->pointer,
                                     "expected a region that holds the centroid of at least one element, got none of " +
                                         std::to_string(centroids.rows())));
  return ids;
}

}  // namespace altfem
