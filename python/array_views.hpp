#pragma once
// numpy views of memory that C++ keeps (Eigen matrices, std::vectors, grids): no copy,
// and each array's base is `owner`, the Python object that keeps that memory alive.
#include <pybind11/numpy.h>

#include <string>
#include <vector>

#include "shared/io/unstructured_grid.hpp"

namespace altfem::python {

/// `rows` × `columns` values stored column by column at `data`.
template <class Scalar>
pybind11::array column_major_view(const Scalar* data, pybind11::ssize_t rows, pybind11::ssize_t columns,
                                  pybind11::handle owner) {
  const auto size = static_cast<pybind11::ssize_t>(sizeof(Scalar));
  return pybind11::array_t<Scalar>({rows, columns}, {size, size * rows}, data, owner);
}

template <class Matrix>
pybind11::array matrix_view(const Matrix& matrix, pybind11::handle owner) {
  return column_major_view(matrix.data(), matrix.rows(), matrix.cols(), owner);
}

template <class Scalar>
pybind11::array vector_view(const std::vector<Scalar>& values, pybind11::handle owner) {
  return pybind11::array_t<Scalar>({static_cast<pybind11::ssize_t>(values.size())},
                                   {static_cast<pybind11::ssize_t>(sizeof(Scalar))}, values.data(), owner);
}

/// A grid's arrays: "points" (#points, 3), "cell_types" (#cells,), "connectivity",
/// "offsets" (VTK's), "point_data" and "cell_data" (dicts of name → (#, components)
/// arrays; "cauchy_stress" as (#cells, 3, 3) and single components as (#,)), and where
/// some cell is a polyhedron "polyhedron_faces" (per cell a list of faces, each a list of
/// point ids, empty for a cell that is not a polyhedron; copied).
pybind11::dict grid_arrays(const UnstructuredGrid& grid, pybind11::handle owner);

}  // namespace altfem::python
