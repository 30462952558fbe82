// The compiled part of the Python module `altfem` (python/altfem/__init__.py is the rest
// and documents the API; docs/python.md). It holds what must run in-process: the scene's
// validation, a run whose frames stay in memory as numpy arrays, a method's mesh, harmonic
// bases and DG element matrices.
#include <pybind11/pybind11.h>

#include "python/bindings.hpp"

PYBIND11_MODULE(_core, module) {
  module.doc() = "altfem's compiled core; use the package `altfem`, which documents it.";
  altfem::python::bind_scene(module);
  altfem::python::bind_run(module);
  altfem::python::bind_mesh(module);
  altfem::python::bind_harmonic(module);
  altfem::python::bind_dg(module);
}
