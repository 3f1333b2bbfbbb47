// patchlab.analyze, patchlab.export and patchlab.render: the CLI's `analyze --json`, `export` and
// `render` through the same functions (app/cli/scene_outputs.hpp, core/cad/cad_export.hpp).
#include <cmath>

#include "app/cli/scene_outputs.hpp"
#include "app/python/bindings.hpp"
#include "core/base/data_error.hpp"
#include "core/cad/cad_export.hpp"
#include "render/egl_context.hpp"

namespace pl::python {

namespace {

py::object analyze(const PyScene& s, int density, const std::optional<std::string>& scheme) {
  const int d = checked_density(density);
  const auto fill = to_scheme(scheme);
  std::string json;
  {
    py::gil_scoped_release release;
    json = report_to_json(analyze_input(s.scene, d, fill, s.source));
  }
  return py::module_::import("json").attr("loads")(json);
}

std::string export_file(const PyScene& s, const py::object& path, const std::optional<int>& density,
                        const std::optional<std::string>& scheme,
                        const std::optional<double>& tolerance) {
  const std::string target = py::str(py::module_::import("os").attr("fspath")(path));
  const auto fill = to_scheme(scheme);
  if (cad_format_for(target)) {  // the checks of `patchlab export`'s options
    if (density) throw py::value_error("density applies to mesh output only");
    CadExportOptions options;
    if (tolerance) {
      if (!(*tolerance > 0) || !std::isfinite(*tolerance))
        throw py::value_error("tolerance takes a positive number");
      options.tolerance = *tolerance;
    }
    options.scheme = fill;
    options.source = s.source;
    py::gil_scoped_release release;
    return cad_report_text(export_cad(s.scene, target, options));
  }
  if (tolerance) throw py::value_error("tolerance applies to STEP and IGES output only");
  const int d = checked_density(density.value_or(32));
  py::gil_scoped_release release;
  return mesh_export_summary(export_mesh_file(s.scene, target, d, fill, s.source), target);
}

py::array render(const PyScene& s, std::pair<int, int> size, const std::string& mode,
                 const std::optional<std::string>& view, int density,
                 const std::optional<std::string>& scheme, bool compare, bool transparent,
                 const std::optional<std::pair<double, double>>& range) {
  RenderJob job;
  std::tie(job.width, job.height) = size;
  if (job.width < 1 || job.height < 1 || job.width > kMaxImageSide || job.height > kMaxImageSide)
    throw py::value_error("size takes (width, height) with each side from 1 to " +
                          std::to_string(kMaxImageSide));
  job.density = checked_density(density);
  job.scheme = to_scheme(scheme);
  job.compare = compare;
  if (compare && job.scheme) throw py::value_error("compare renders both schemes; drop scheme");
  job.settings = parse_display_mode(mode);  // std::invalid_argument: a ValueError
  job.settings.transparent = transparent;
  if (range) {
    if (!(range->first < 0 && range->second > 0) || !std::isfinite(range->first) ||
        !std::isfinite(range->second))
      throw py::value_error("range needs lo < 0 < hi (the colour map is centred on zero)");
    job.settings.range = ColorRange{range->first, range->second};
  }
  job.view = view;
  auto image = std::make_unique<Image>();
  {
    py::gil_scoped_release release;
    try {
      *image = render_scene_image(s.scene, job, s.source).image;
    } catch (const DataError&) {
      throw;
    } catch (const std::runtime_error& e) {  // GlContextError too: as the CLI says it
      throw std::runtime_error("cannot render " + s.source + ": " + e.what());
    }
  }
  const py::ssize_t h = image->height, w = image->width;
  const uint8_t* pixels = image->rgba.data();
  py::capsule owner(image.release(), [](void* p) { delete static_cast<Image*>(p); });
  return py::array_t<uint8_t>({h, w, py::ssize_t(4)}, {w * 4, py::ssize_t(4), py::ssize_t(1)},
                              pixels, owner);
}

}  // namespace

void bind_outputs(py::module_& m) {
  m.def("analyze", &analyze, py::arg("scene"), py::arg("density") = 32,
        py::arg("scheme") = py::none(),
        "The report of `patchlab analyze --json` as Python objects (equal to json.loads of "
        "the CLI's output).");
  m.def("export", &export_file, py::arg("scene"), py::arg("path"), py::arg("density") = py::none(),
        py::arg("scheme") = py::none(), py::arg("tolerance") = py::none(),
        "`patchlab export`: a mesh (.obj, .ply, .off, .stl; at `density`, default 32) or B-spline "
        "faces (.step, .stp, .igs, .iges; within `tolerance`), written atomically. Returns what "
        "the CLI prints.");
  m.def("render", &render, py::arg("scene"), py::arg("size") = std::pair{1600, 1200},
        py::arg("mode") = "shaded", py::arg("view") = py::none(), py::arg("density") = 32,
        py::arg("scheme") = py::none(), py::arg("compare") = false, py::arg("transparent") = false,
        py::arg("range") = py::none(),
        "`patchlab render` into an h x w x 4 uint8 RGBA array (top row first), headless "
        "through EGL; the modes, views and options of the CLI.");
}

}  // namespace pl::python
