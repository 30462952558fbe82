#include "shared/mesh/flat_cells.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace altfem {

Eigen::VectorXd cell_flatness(const PolyhedralMesh& mesh) {
  Eigen::VectorXd flatness(mesh.cell_count());
  for (int cell = 0; cell < mesh.cell_count(); ++cell) {
    double largest_face = 0;
    for (int face : mesh.cell_faces[cell]) largest_face = std::max(largest_face, mesh.face_areas[face]);
    flatness[cell] = mesh.cell_diameters[cell] * largest_face / mesh.cell_volumes[cell];
  }
  return flatness;
}

std::optional<std::string> flat_cell_locking_warning(const PolyhedralMesh& mesh, const std::string& method,
                                                     const std::string& remedy) {
  if (mesh.cell_count() == 0) return std::nullopt;
  const Eigen::VectorXd flatness = cell_flatness(mesh);
  std::vector<double> sorted(flatness.data(), flatness.data() + flatness.size());
  const auto middle = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
  std::nth_element(sorted.begin(), middle, sorted.end());
  // A cube's flatness is √3, a square cell h wide and t thick about √2 h / t: 20 is a
  // cell 14 times wider than thick.
  if (*middle <= 20) return std::nullopt;
  return method + ": the median cell is about " + std::to_string(std::lround(*middle / std::sqrt(2.0))) +
         " times wider than thick (a geometry thinner than the cells); a basis complete to degree 1 only represents "
         "bending by shear, and cells this flat lock in bending: the answer is too stiff; " +
         remedy;
}

}  // namespace altfem
