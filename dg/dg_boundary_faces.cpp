#include "dg/dg_boundary_faces.hpp"

#include <string>

#include "dg/polyhedral_mesh_faces.hpp"
#include "shared/common/error.hpp"

namespace altfem::dg {

std::vector<DgFace> faces_with_conditions(const PolyhedralMesh& mesh, const Scene& scene) {
  const double tolerance = 1e-9 * (mesh.nodes.colwise().maxCoeff() - mesh.nodes.colwise().minCoeff()).norm();
  std::vector<DgFace> faces = mesh_faces(mesh);
  std::vector<int> faces_per_condition(scene.dirichlet.size(), 0);
  for (int f = 0; f < mesh.face_count(); ++f) {
    DgFace& face = faces[f];
    if (face.plus >= 0) continue;
    for (size_t c = 0; c < scene.dirichlet.size() && face.condition < 0; ++c)
      if (scene.dirichlet[c].region.contains(mesh.face_centroids.row(f).transpose(), tolerance)) {
        face.condition = static_cast<int>(c);
        face.components = scene.dirichlet[c].components;
        ++faces_per_condition[c];
      }
  }
  for (size_t c = 0; c < scene.dirichlet.size(); ++c) {
    if (faces_per_condition[c] == 0)
      throw InputError(
          input_message(scene.file.string(), scene.dirichlet[c].pointer + "/region",
                        "holds the centroid of no boundary face of the dg mesh (weak conditions act on faces)"));
  }
  return faces;
}

void hold_strongly(const Scene& scene, std::vector<DgFace>& faces, int cell_count) {
  std::vector<int> first_condition(cell_count, -1);
  for (DgFace& face : faces) {
    if (face.plus >= 0 || face.condition < 0) continue;
    face.strong = true;
    int& first = first_condition[face.minus];
    if (first < 0) first = face.condition;
    if (scene.dirichlet[first].components != face.components)
      throw InputError(input_message(
          scene.file.string(), "/discretization/dg/conditions",
          "'strong' needs the conditions on one cell's faces to prescribe the same components, but cell " +
              std::to_string(face.minus) + " touches " + scene.dirichlet[first].pointer + " and " +
              scene.dirichlet[face.condition].pointer + " (use 'weak')"));
  }
}

}  // namespace altfem::dg
