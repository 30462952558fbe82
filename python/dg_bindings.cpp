// DG's element matrices of one polyhedron for teaching (Kaufmann et al. 2009 §5, App. A):
// the dg method's own exact integration, from Python arrays.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "dg/exact_element_matrices.hpp"
#include "python/bindings.hpp"
#include "shared/material/lame_parameters.hpp"

namespace py = pybind11;

namespace altfem::python {

void bind_dg(py::module_& module) {
  module.def(
      "dg_element_matrices",
      [](const Eigen::MatrixXd& vertices, const std::vector<std::vector<int>>& faces, int degree, double youngs_modulus,
         double poisson_ratio, double density) {
        if (degree < 1 || degree > 3)
          throw py::value_error("degree: expected 1, 2 or 3, got " + std::to_string(degree));
        const Polyhedron element = checked_polyhedron(vertices, faces);
        const dg::MonomialBasis basis = dg::cell_monomial_basis(element, degree);
        const LameParameters lame = lame_parameters(youngs_modulus, poisson_ratio);
        dg::ElementMatrices matrices = dg::exact_element_matrices(element, basis, lame.lambda, lame.mu, density);
        py::dict result;
        result["stiffness"] = std::move(matrices.stiffness);
        result["mass"] = std::move(matrices.mass);
        result["integrals"] = std::move(matrices.integrals);
        result["exponents"] = Eigen::MatrixXi(basis.exponents());
        result["centre"] = basis.centre();
        result["scale"] = basis.scale();
        return result;
      },
      py::arg("vertices"), py::arg("faces"), py::arg("degree"), py::arg("youngs_modulus"), py::arg("poisson_ratio"),
      py::arg("density"));
}

}  // namespace altfem::python
