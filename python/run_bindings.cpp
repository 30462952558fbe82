// `altfem.run` in-process: the run of `altfem run`, its frames kept in memory and handed
// to numpy as views of the Eigen matrices that hold them (no copy): each array's base is
// the RunOutput, so the arrays outlive every Python name of the result.
#include <pybind11/stl.h>

#include <chrono>
#include <memory>

#include "app/method_registry.hpp"
#include "python/array_views.hpp"
#include "python/bindings.hpp"
#include "shared/common/error.hpp"
#include "shared/io/output_folder.hpp"
#include "shared/mesh/text_file.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/simulation/run_simulation.hpp"

namespace py = pybind11;

namespace altfem::python {
namespace {

struct RunOutput {
  std::string summary;  ///< summary.json's text ("{}" when the run stopped before writing it)
  std::string error;    ///< the numerical failure's message; empty when the run succeeded
  std::vector<std::string> warnings;
  std::vector<RunFrame> frames;
};

std::shared_ptr<RunOutput> run(const std::string& file, const std::string& text,
                               const std::vector<std::string>& assignments, const std::string& method,
                               const std::string& out) {
  auto output = std::make_shared<RunOutput>();
  py::gil_scoped_release unlocked;  // the run touches no Python object
  const auto start = std::chrono::steady_clock::now();
  const MethodDescription& description = cli::find_method(method, "method");
  const Scene scene = load_scene_source({file, text, assignments}, {method});
  const SceneGeometry geometry = load_scene_geometry(scene);
  output->warnings = geometry.warnings;
  check_output_folder(out);
  const double loading = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  try {
    output->summary = run_simulation(scene, geometry, method, description, out, loading, [&](RunFrame&& frame) {
                        output->frames.push_back(std::move(frame));
                      }).dump();
  } catch (const NumericalError& error) {
    output->error = error.what();
    const std::filesystem::path summary = std::filesystem::path(out) / "summary.json";
    output->summary = std::filesystem::exists(summary) ? read_text_file(summary) : "{}";
  }
  return output;
}

// Frame `index`'s arrays by name (docs of altfem.Frame): views into `owner`'s RunOutput.
py::dict frame_arrays(const std::shared_ptr<RunOutput>& output, std::size_t index, py::handle owner) {
  const RunFrame& frame = output->frames.at(index);
  py::dict arrays = grid_arrays(frame.volume, owner);
  arrays["time"] = frame.time;
  arrays["surface_vertices"] = matrix_view(frame.surface_vertices, owner);
  arrays["surface_triangles"] = matrix_view(frame.surface_triangles, owner);
  arrays["surface_displacement"] = matrix_view(frame.surface_displacement, owner);
  return arrays;
}

}  // namespace

void bind_run(py::module_& module) {
  py::class_<RunOutput, std::shared_ptr<RunOutput>>(module, "RunOutput",
                                                    "What one run produced; altfem.Result wraps it.")
      .def_readonly("summary", &RunOutput::summary)
      .def_readonly("error", &RunOutput::error)
      .def_readonly("warnings", &RunOutput::warnings)
      .def("frame_count", [](const RunOutput& output) { return output.frames.size(); })
      .def(
          "frame_arrays",
          [](py::object self, std::size_t index) {
            return frame_arrays(self.cast<std::shared_ptr<RunOutput>>(), index, self);
          },
          py::arg("index"), "Frame `index`'s time and arrays (views that keep this object alive).");
  module.def("run", &run, py::arg("file"), py::arg("text"), py::arg("assignments"), py::arg("method"), py::arg("out"),
             "Runs the scene with `method` into the folder `out`; a numerical failure is returned in "
             "`error`, with the summary and frames up to it.");
}

}  // namespace altfem::python
