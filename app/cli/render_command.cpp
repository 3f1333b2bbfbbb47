// `patchlab render FILE -o OUT.png ...` (docs/cli.md, docs/rendering.md): headless, through an EGL
// offscreen context, so it works with no X server and DISPLAY unset.
#include <charconv>
#include <cmath>
#include <tuple>

#include "app/cli/arguments.hpp"
#include "app/cli/camera_file.hpp"
#include "app/cli/checked_scene.hpp"
#include "app/cli/cli.hpp"
#include "app/cli/commands.hpp"
#include "render/draw_scene_builder.hpp"
#include "app/cli/load_input.hpp"
#include "app/cli/progress_line.hpp"
#include "app/cli/scene_outputs.hpp"
#include "app/cli/work_limits.hpp"
#include "core/analysis/compared_schemes.hpp"
#include "core/analysis/curve_analysis.hpp"
#include "core/base/data_error.hpp"
#include "core/io/atomic_file.hpp"
#include "core/io/input_limits.hpp"
#include "core/io/json_node.hpp"
#include "core/mesh/finite_check.hpp"
#include "render/default_view.hpp"
#include "render/egl_context.hpp"
#include "render/frame.hpp"

namespace pl {

namespace {

std::pair<int, int> parse_size(const std::optional<std::string>& v) {
  if (!v) return {1600, 1200};
  const std::size_t x = v->find('x');
  int w = 0, h = 0;
  auto whole = [](const std::string& s, int& out) {
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && end == s.data() + s.size() && !s.empty();
  };
  if (x == std::string::npos || !whole(v->substr(0, x), w) || !whole(v->substr(x + 1), h) ||
      w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide)
    throw UsageError("--size takes WxH with each side from 1 to 4096, got \"" + *v + "\"");
  return {w, h};
}

// "--range R" gives [-R, R]; "--range LO:HI" needs LO < 0 < HI so zero keeps the neutral colour.
ColorRange parse_range(const std::string& v) {
  auto number = [&](const std::string& s) {
    double d = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), d);
    if (ec != std::errc() || end != s.data() + s.size() || s.empty() || !std::isfinite(d))
      throw UsageError("--range takes R or LO:HI (numbers), got \"" + v + "\"");
    return d;
  };
  const std::size_t colon = v.find(':');
  ColorRange r;
  if (colon == std::string::npos) {
    const double m = number(v);
    r = {-m, m};
  } else {
    r = {number(v.substr(0, colon)), number(v.substr(colon + 1))};
  }
  if (!(r.lo < 0 && r.hi > 0))
    throw UsageError("--range needs LO < 0 < HI (the colour map is centred on zero), got \"" + v +
                     "\"");
  return r;
}

bool ends_with_png(const std::string& s) {
  return s.size() > 4 &&
         (s.compare(s.size() - 4, 4, ".png") == 0 || s.compare(s.size() - 4, 4, ".PNG") == 0);
}

DisplaySettings parse_settings(const Arguments& a) {
  DisplaySettings settings;
  try {
    settings = parse_display_mode(a.value("--mode").value_or("shaded"));
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--mode: ") + e.what());
  }
  settings.transparent = a.flag("--transparent");
  settings.curvature_lighting = !a.flag("--flat");
  if (const auto r = a.value("--range")) settings.range = parse_range(*r);
  return settings;
}

}  // namespace

RenderedImage render_scene_image(const Scene& scene, const RenderJob& job,
                                 const std::string& file) {
  const DisplaySettings& settings = job.settings;
  const auto preset = job.view ? parse_view_preset(*job.view) : std::nullopt;
  if (job.compare && !scene.network)
    throw DataError(file, "", "--compare needs a scene with a curve network");
  TessellationCache cache;
  // No comb work unless combs are drawn.
  const int teeth = settings.combs ? settings.comb_teeth : 0;
  std::vector<DrawScene> draws;
  std::vector<std::string> labels;
  if (job.compare) {
    for (FaceScheme s : job.compared) {
      const SceneSurfaces surfaces = evaluate_checked(scene, job.density, s, cache, file);
      ProgressLine::set_stage("preparing the drawing");
      draws.push_back(build_draw_scene(scene, surfaces, teeth));
      labels.push_back(s == FaceScheme::GB ? "Generalized Bézier" : scheme_title(s));
    }
  } else {
    const SceneSurfaces surfaces = evaluate_checked(scene, job.density, job.scheme, cache, file);
    ProgressLine::set_stage("preparing the drawing");
    draws.push_back(build_draw_scene(scene, surfaces, teeth));
    labels.emplace_back();
  }

  Box box;
  std::vector<const SurfaceMesh*> meshes;
  std::vector<const DrawScene*> scenes;
  for (const DrawScene& d : draws) {
    const Box b = d.bounds();
    if (!b.empty()) {
      box.add(b.lo);
      box.add(b.hi);
    }
    // Combs stand out of the curves: a preset view frames their tips too, as the default does.
    if (settings.combs) {
      std::vector<Vec3> tips;
      append_comb_tips(d, settings, tips);
      for (const Vec3& p : tips) box.add(p);
    }
    for (const SurfaceMesh& m : d.surfaces) meshes.push_back(&m);
    check_finite(d.surfaces, file);  // a NaN would draw nothing, or garbage, without a word
    scenes.push_back(&d);
  }
  FrameRequest request;
  request.width = job.width;
  request.height = job.height;
  request.settings = settings;
  // One range for every panel, so equal colours mean equal curvature across the comparison.
  request.range = settings.range
                      ? *settings.range
                      : automatic_range(meshes, settings.curvature, settings.range_percentile);
  request.panels.resize(draws.size());
  PointKeyEntries key;
  for (std::size_t i = 0; i < draws.size(); ++i) {
    request.panels[i].label = labels[i];
    if (settings.control_net) key |= PointKeyEntries::of(draws[i]);
  }
  request.key_entries = key;
  const double aspect = panel_aspect(request);
  request.camera = !job.view ? default_camera(scenes, aspect, &settings)
                   : preset  ? preset_camera(*preset, box, aspect)
                             : read_camera_file(*job.view, box, aspect);

  EglContext context;
  SceneRenderer renderer;
  std::vector<GpuScene> gpu;
  gpu.reserve(draws.size());
  for (const DrawScene& d : draws) gpu.emplace_back(d);
  for (std::size_t i = 0; i < gpu.size(); ++i) request.panels[i].scene = &gpu[i];
  ProgressLine::set_stage("drawing the image");
  return {render_frame(renderer, request), meshes.size()};
}

int run_render(std::span<const std::string> args, std::ostream& out, std::ostream& err) {
  const Arguments a(
      args, {"-o", "--size", "--mode", "--view", "--density", "--scheme", "--range", "--schemes"},
      {"--compare", "--transparent", "--flat"});
  if (a.positional().size() != 1) throw UsageError("render takes exactly one input FILE");
  const auto target = a.value("-o");
  if (!target) throw UsageError("render needs -o OUT.png");
  if (!ends_with_png(*target))
    throw UsageError("render writes .png, not \"" +
                     std::filesystem::path(*target).extension().string() + "\"");
  RenderJob job;
  std::tie(job.width, job.height) = parse_size(a.value("--size"));
  job.density = a.integer("--density", kDefaultDensity, 1, kMaxDensity);
  job.scheme = parse_scheme_option(a.value("--scheme"));
  job.compare = a.flag("--compare");
  if (job.compare && job.scheme) throw UsageError("--compare renders both schemes; drop --scheme");
  // --compare --schemes S,S,...: one panel per scheme (default: Gregory and GB).
  if (const auto list = a.value("--schemes")) {
    if (!job.compare) throw UsageError("--schemes goes with --compare");
    job.compared = parse_scheme_list(*list, "--schemes");
  }
  job.settings = parse_settings(a);
  // No --view: the default view (render/default_view.hpp), which faces a single patch's front.
  job.view = a.value("--view");
  // Anything else must name a camera file: a word that is neither is a mistyped preset.
  if (job.view && !parse_view_preset(*job.view) &&
      std::filesystem::path(*job.view).extension() != ".json")
    throw UsageError(
        "--view takes iso, front, back, left, right, top, bottom or a camera "
        "file NAME.json, got \"" +
        *job.view + "\"");

  const std::string file = a.positional()[0];
  check_input_name(file);
  ProgressLine::set_stage("reading " + printable(file));
  const Scene scene = load_scene_file(file);
  std::size_t patches = 0;
  try {
    const RenderedImage r = render_scene_image(scene, job, file);
    patches = r.patches;
    write_file_atomically(*target, encode_png(r.image));
  } catch (const GlContextError& e) {
    err << "patchlab: cannot render " << printable(file) << ": " << printable(e.what()) << "\n";
    return kExitBadInput;
  } catch (const DataError&) {
    throw;
  } catch (const std::runtime_error& e) {
    err << "patchlab: cannot render " << printable(file) << ": " << printable(e.what()) << "\n";
    return kExitBadInput;
  }
  out << "wrote " << job.width << "x" << job.height << " image of " << patches << " patch(es) to "
      << printable(*target) << "\n";
  return kExitOk;
}

}  // namespace pl
