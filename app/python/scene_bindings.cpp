// patchlab.load, patchlab.loads and patchlab.Scene: reading, saving and evaluating a scene the
// way the CLI does (load_scene_file, save_scene_file, evaluate_checked).
#include <filesystem>

#include "app/cli/load_input.hpp"
#include "app/cli/scene_outputs.hpp"
#include "app/document/scene_file.hpp"
#include "app/python/bindings.hpp"
#include "core/base/data_error.hpp"
#include "core/io/input_limits.hpp"
#include "core/io/scene_io.hpp"

namespace pl::python {

namespace {

std::string path_string(const py::handle& path) {
  return py::str(py::module_::import("os").attr("fspath")(path));
}

std::vector<PySamples> evaluate(const PyScene& s, int density,
                                const std::optional<std::string>& scheme) {
  const int d = checked_density(density);
  const auto fill = to_scheme(scheme);
  SceneSurfaces surfaces;
  {
    py::gil_scoped_release release;
    surfaces =
        evaluate_checked(s.scene, d, fill, *s.tessellations, s.source, nullptr, s.sample_buffers);
  }
  std::vector<PySamples> out;
  out.reserve(surfaces.surfaces.size());
  for (SceneSurface& surface : surfaces.surfaces)
    out.push_back({surface.name, surface.face, surface.patch, std::move(surface.evaluator)});
  return out;
}

}  // namespace

void bind_scene(py::module_& m) {
  py::class_<PyScene>(m, "Scene",
                      "A PatchLab scene: a curve network, explicit patches and free curves "
                      "(docs/scene-format.md). Messages about it name its source file.")
      .def(py::init([] {
             return PyScene{Scene{}, "<scene>"};
           }),
           "An empty scene.")
      .def_readonly("source", &PyScene::source, "The file the scene was read from.")
      .def_property_readonly(
          "vertex_count",
          [](const PyScene& s) { return s.scene.network ? s.scene.network->vertices.size() : 0; })
      .def_property_readonly(
          "edge_count",
          [](const PyScene& s) { return s.scene.network ? s.scene.network->edges.size() : 0; })
      .def_property_readonly(
          "face_count",
          [](const PyScene& s) { return s.scene.network ? s.scene.network->faces.size() : 0; })
      .def_property_readonly("patch_count", [](const PyScene& s) { return s.scene.patches.size(); })
      .def_property_readonly("curve_count", [](const PyScene& s) { return s.scene.curves.size(); })
      .def(
          "to_json", [](const PyScene& s) { return scene_to_json(s.scene); },
          "The scene as the JSON text `save` writes to a .json file.")
      .def(
          "save",
          [](const PyScene& s, const py::object& path) {
            const std::string file = path_string(path);
            py::gil_scoped_release release;
            save_scene_file(file, s.scene);
          },
          py::arg("path"),
          "Writes the scene atomically as the extension says (.json, or .gbp for a scene of one "
          "GB patch); a failed save keeps the previous file and raises DataError.")
      .def("evaluate", &evaluate, py::arg("density") = 32, py::arg("scheme") = py::none(),
           "Every surface sampled at `density` (samples per boundary curve), one PatchSamples "
           "per patch in the order of the objects of `patchlab export -o X.obj`; scheme "
           "\"gregory\" or \"gb\" fills every network face so, as --scheme does.")
      .def("__repr__", [](const PyScene& s) {
        return "<patchlab.Scene " + s.source + ": " +
               std::to_string(s.scene.network ? s.scene.network->faces.size() : 0) + " face(s), " +
               std::to_string(s.scene.patches.size()) + " patch(es), " +
               std::to_string(s.scene.curves.size()) + " curve(s)>";
      });

  m.def(
      "load",
      [](const py::object& path) {
        const std::string file = path_string(path);
        py::gil_scoped_release release;
        return PyScene{load_scene_file(file), file};
      },
      py::arg("path"),
      "Reads a scene (.json) or a GB patch (.gbp) as `patchlab FILE` does; raises DataError "
      "naming the file and the JSON path, line or token.");
  m.def(
      "loads",
      [](const std::string& text, const std::string& source) {
        if (text.size() > kMaxInputBytes)  // the bound read_text_file puts on a file
          throw DataError(source, "",
                          "the text has " + std::to_string(text.size()) +
                              " bytes; PatchLab reads at most " + std::to_string(kMaxInputBytes));
        py::gil_scoped_release release;
        return PyScene{parse_scene(text, source), source};
      },
      py::arg("text"), py::arg("source") = "<string>",
      "Reads a scene from JSON text; messages name `source`.");
}

}  // namespace pl::python
