#include "python/array_views.hpp"

#include <pybind11/stl.h>

#include <algorithm>

namespace py = pybind11;

namespace altfem::python {
namespace {

py::array data_view(const std::string& name, const Eigen::MatrixXd& values, py::handle owner) {
  const py::ssize_t rows = values.rows(), size = sizeof(double);
  if (values.cols() == 1) return py::array_t<double>({rows}, {size}, values.data(), owner);
  // σ row by row in 9 columns stored column by column: σ[e, i, j] at e + (3i + j)·rows.
  if (name == "cauchy_stress" && values.cols() == 9)
    return py::array_t<double>({rows, py::ssize_t{3}, py::ssize_t{3}}, {size, 3 * rows * size, rows * size},
                               values.data(), owner);
  return matrix_view(values, owner);
}

py::dict data_views(const std::vector<std::pair<std::string, Eigen::MatrixXd>>& data, py::handle owner) {
  py::dict views;
  for (const auto& [name, values] : data) views[py::str(name)] = data_view(name, values, owner);
  return views;
}

}  // namespace

py::dict grid_arrays(const UnstructuredGrid& grid, py::handle owner) {
  py::dict arrays;
  arrays["points"] = matrix_view(grid.points, owner);
  arrays["cell_types"] = vector_view(grid.cell_types, owner);
  arrays["connectivity"] = vector_view(grid.connectivity, owner);
  arrays["offsets"] = vector_view(grid.offsets, owner);
  arrays["point_data"] = data_views(grid.point_data, owner);
  arrays["cell_data"] = data_views(grid.cell_data, owner);
  const auto& faces = grid.polyhedron_faces;
  if (std::any_of(faces.begin(), faces.end(), [](const auto& cell_faces) { return !cell_faces.empty(); }))
    arrays["polyhedron_faces"] = py::cast(faces);
  return arrays;
}

}  // namespace altfem::python
