// `altfem.mesh`: a method's mesh as `altfem mesh` builds it, without solving, as arrays.
#include <pybind11/stl.h>

#include <memory>

#include "app/method_registry.hpp"
#include "python/array_views.hpp"
#include "python/bindings.hpp"
#include "shared/common/error.hpp"
#include "shared/scene/scene_geometry.hpp"

namespace py = pybind11;

namespace altfem::python {
namespace {

struct MeshOutput {
  MeshPreview preview;
  std::vector<std::string> warnings;  ///< the geometry's, then the method's
};

std::shared_ptr<MeshOutput> mesh(const std::string& file, const std::string& text,
                                 const std::vector<std::string>& assignments, const std::string& method,
                                 const MeshPreviewOptions& options) {
  py::gil_scoped_release unlocked;
  const MethodDescription& description = cli::find_method(method, "method");
  if (!description.mesh_preview) throw InputError("method " + method + ": this method has no mesh preview");
  const Scene scene = load_scene_source({file, text, assignments}, {method});
  const SceneGeometry geometry = load_scene_geometry(scene);
  auto output = std::make_shared<MeshOutput>();
  output->preview = description.mesh_preview(scene, geometry, options);
  output->warnings = geometry.warnings;
  output->warnings.insert(output->warnings.end(), output->preview.warnings.begin(), output->preview.warnings.end());
  return output;
}

}  // namespace

void bind_mesh(py::module_& module) {
  py::class_<MeshOutput, std::shared_ptr<MeshOutput>>(module, "MeshOutput", "altfem.Mesh wraps it.")
      .def_property_readonly("facts", [](const MeshOutput& output) { return output.preview.facts.dump(); })
      .def_readonly("warnings", &MeshOutput::warnings)
      .def("arrays", [](py::object self) { return grid_arrays(self.cast<MeshOutput&>().preview.grid, self); });
  module.def(
      "mesh",
      [](const std::string& file, const std::string& text, const std::vector<std::string>& assignments,
         const std::string& method, const std::string& source, int resolution, double sliver_fraction,
         int octree_levels) {
        MeshPreviewOptions options;
        options.source = source;
        options.slicing.resolution = resolution;
        options.slicing.sliver_fraction = sliver_fraction;
        options.slicing.octree_levels = octree_levels;
        return mesh(file, text, assignments, method, options);
      },
      py::arg("file"), py::arg("text"), py::arg("assignments"), py::arg("method"), py::arg("source"),
      py::arg("resolution"), py::arg("sliver_fraction"), py::arg("octree_levels"));
}

}  // namespace altfem::python
