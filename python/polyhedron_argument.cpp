#include <pybind11/pybind11.h>

#include <string>

#include "python/bindings.hpp"

namespace altfem::python {

Polyhedron checked_polyhedron(const Eigen::MatrixXd& vertices, const std::vector<std::vector<int>>& faces) {
  if (vertices.cols() != 3) throw pybind11::value_error("vertices: expected an (n, 3) array");
  if (faces.size() < 4) throw pybind11::value_error("faces: a closed polyhedron has at least 4 faces");
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (faces[f].size() < 3)
      throw pybind11::value_error("faces[" + std::to_string(f) + "]: expected at least 3 vertices");
    for (const int vertex : faces[f])
      if (vertex < 0 || vertex >= vertices.rows())
        throw pybind11::value_error("faces[" + std::to_string(f) + "]: vertex " + std::to_string(vertex) +
                                    " is not one of the " + std::to_string(vertices.rows()) + " vertices");
  }
  return {vertices, faces};
}

}  // namespace altfem::python
