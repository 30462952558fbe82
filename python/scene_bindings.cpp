// Scenes for Python: the command line's validation, overrides and errors, unchanged.
#include <pybind11/stl.h>

#include "app/method_registry.hpp"
#include "python/bindings.hpp"
#include "shared/common/error.hpp"
#include "shared/scene/scene_override.hpp"

namespace py = pybind11;

namespace altfem::python {

Scene load_scene_source(const SceneSource& source, const std::vector<std::string>& methods) {
  std::vector<SceneOverride> overrides;
  for (const std::string& assignment : source.assignments)
    overrides.push_back(parse_scene_override(assignment, "Scene.set"));
  Scene scene =
      source.text.empty() ? load_scene(source.file, overrides) : parse_scene(source.text, source.file, overrides);
  cli::resolve_method_blocks(scene, methods);
  return scene;
}

void bind_scene(py::module_& module) {
  // InputError's message is the command line's one line ("file: /pointer: what").
  py::register_exception<InputError>(module, "SceneError", PyExc_ValueError);
  py::register_exception<NumericalError>(module, "NumericalError", PyExc_RuntimeError);

  module.def(
      "resolve_scene",
      [](const std::string& file, const std::string& text, const std::vector<std::string>& assignments,
         const std::vector<std::string>& methods) {
        return load_scene_source({file, text, assignments}, methods).resolved.dump();
      },
      py::arg("file"), py::arg("text"), py::arg("assignments"), py::arg("methods"),
      "The resolved scene as JSON text; raises SceneError.");
  module.def("methods", &cli::available_methods, "The methods of this build, as `altfem info` lists them.");
  module.def(
      "executable", [] { return std::string(ALTFEM_EXECUTABLE); },
      "The `altfem` executable of the same build (compare and the command-line tools).");
}

}  // namespace altfem::python
