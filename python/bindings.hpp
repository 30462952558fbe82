#pragma once
// What each binding file adds to the module `altfem._core`.
#include <pybind11/pybind11.h>

namespace altfem::python {

/// `_core.SceneError`, `_core.NumericalError`, `_core.resolve_scene`, `_core.methods`,
/// `_core.executable`.
void bind_scene(pybind11::module_& module);
/// `_core.run` and its `RunOutput`.
void bind_run(pybind11::module_& module);
/// `_core.mesh` and its `MeshOutput`.
void bind_mesh(pybind11::module_& module);
/// `_core.HarmonicBasis` and `_core.winding_number`.
void bind_harmonic(pybind11::module_& module);
/// `_core.dg_element_matrices`.
void bind_dg(pybind11::module_& module);

}  // namespace altfem::python

#include <string>
#include <vector>

#include <Eigen/Core>

#include "shared/geometry/polyhedron.hpp"
#include "shared/scene/scene.hpp"

namespace altfem::python {

/// A scene as `altfem.Scene` holds it: read from `file`, or from JSON `text` (then `file`
/// names it in messages and anchors its relative paths), with `assignments` ("KEY=JSON",
/// as `--set` takes them) applied before validation.
struct SceneSource {
  std::string file;
  std::string text;
  std::vector<std::string> assignments;
};

/// The scene validated and resolved, the blocks of `methods` too (app/method_registry.hpp);
/// throws InputError with the command line's one-line messages.
Scene load_scene_source(const SceneSource& source, const std::vector<std::string>& methods);

/// The polyhedron of Python's arrays (vertices #vertices × 3, faces of vertex ids),
/// checked: a bad one raises ValueError naming the face, not a crash.
Polyhedron checked_polyhedron(const Eigen::MatrixXd& vertices, const std::vector<std::vector<int>>& faces);

}  // namespace altfem::python
