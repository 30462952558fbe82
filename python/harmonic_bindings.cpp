// Harmonic bases of single polyhedra for teaching (Martin et al. 2008, §4–5; the
// harmonic method's own basis, polyhedral/element_harmonic_basis.hpp).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "polyhedral/element_harmonic_basis.hpp"
#include "python/bindings.hpp"

namespace py = pybind11;

namespace altfem::python {

void bind_harmonic(py::module_& module) {
  using harmonic::ElementHarmonicBasis;
  py::class_<ElementHarmonicBasis>(module, "HarmonicBasis", "altfem.harmonic.basis documents it.")
      .def(py::init([](const Eigen::MatrixXd& vertices, const std::vector<std::vector<int>>& faces, int edge_samples,
                       double offset) {
             harmonic::MfsOptions options;
             options.edge_samples = edge_samples;
             options.offset = offset;
             return ElementHarmonicBasis(checked_polyhedron(vertices, faces), options);
           }),
           py::arg("vertices"), py::arg("faces"), py::arg("edge_samples"), py::arg("offset"))
      .def_property_readonly("node_count", &ElementHarmonicBasis::node_count)
      .def_property_readonly("boundary_residual", &ElementHarmonicBasis::boundary_residual)
      .def_property_readonly("centres", &ElementHarmonicBasis::centres)
      .def(
          "values",
          [](const ElementHarmonicBasis& basis, const Eigen::MatrixXd& points) {
            if (points.cols() != 3) throw py::value_error("points: expected an (m, 3) array");
            return basis.values(points);
          },
          py::arg("points"))
      .def(
          "gradients",
          [](const ElementHarmonicBasis& basis, const Eigen::MatrixXd& points) {
            if (points.cols() != 3) throw py::value_error("points: expected an (m, 3) array");
            Eigen::MatrixXd values, gradients;
            basis.evaluate(points, values, gradients);
            return gradients;  // (#points·#nodes) × 3, point-major
          },
          py::arg("points"));
  module.def(
      "winding_number",
      [](const Eigen::MatrixXd& vertices, const std::vector<std::vector<int>>& faces, const Eigen::MatrixXd& points) {
        const Polyhedron polyhedron = checked_polyhedron(vertices, faces);
        if (points.cols() != 3) throw py::value_error("points: expected an (m, 3) array");
        Eigen::VectorXd numbers(points.rows());
        for (Eigen::Index q = 0; q < points.rows(); ++q)
          numbers[q] = harmonic::winding_number(polyhedron, points.row(q).transpose());
        return numbers;
      },
      py::arg("vertices"), py::arg("faces"), py::arg("points"));
}

}  // namespace altfem::python
