// `patchlab --bench-drag [FILE] [--compare-schemes S,S,...]`: a scripted drag of the network
// vertex with the most edges (of FILE, or of a generated 2 x 2 quad network) in a 1280x720
// window, each step a full editor frame (coarse re-evaluation of every view shown, upload, draw,
// UI, swap, glFinish); with --compare-schemes the comparison's panes are shown and followed, one
// evaluation per pane. Prints
//   figure editor_drag_fps, editor_frame_ms_p50, editor_frame_ms_p95,
//          editor_eval_ms_per_drag_frame, editor_cpu_ms_per_drag_frame, editor_settle_ms,
//          editor_first_frame_ms, editor_loaded_ms, editor_peak_rss_mb
// where evaluation is the views' share of a drag frame (engine sync and mesh arrays), settle is
// the time from the release to the first frame showing the fine surfaces in every pane, first frame
// and loaded are the times from the process's launch to the first frame swapped (the progress bar)
// and to the moment the worker's evaluated scene is taken (the frame showing it follows), and the
// peak RSS is the process's high-water mark after all of it: loading and the first evaluation
// included. Display settings are the defaults (the user's preferences are not read), or those
// --display MODE names.
#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "app/editor/editor.hpp"
#include "render/gl.hpp"

namespace pl {

namespace {
constexpr int kWarmupFrames = 5;
constexpr int kDragFrames = 180;

// CPU time of every thread of the process so far.
double process_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

double percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const std::size_t i = std::min(v.size() - 1, static_cast<std::size_t>(q * (v.size() - 1) + 0.5));
  return v[i];
}
}  // namespace

int Editor::run_drag_benchmark() {
  if (!model_.session().doc().scene().network ||
      model_.session().doc().scene().network->vertices.empty()) {
    std::fprintf(stderr, "patchlab: --bench-drag needs a scene with a curve network\n");
    return 1;
  }
  const Network& net = *model_.session().doc().scene().network;
  std::vector<int> valence(net.vertices.size(), 0);
  for (const NetworkEdge& e : net.edges) ++valence.at(e.v[0]), ++valence.at(e.v[1]);
  const int vertex = int(std::max_element(valence.begin(), valence.end()) - valence.begin());
  // The scene is evaluated behind the progress bar, as when a user opens it: frames at the
  // interactive loop's loading pace until it is shown.
  while (!model_.views().ready() && (model_.views().loading() || frames_ < 1)) {
    window_.wait_events(0.05);
    frame();
  }
  if (!model_.views().ready()) {
    std::fprintf(stderr, "patchlab: --bench-drag: %s\n", model_.views().error().c_str());
    return 1;
  }
  for (int i = 0; i < kWarmupFrames; ++i) {
    window_.poll_events();
    frame();
  }
  glFinish();
  const PointRef ref = PointRef::vertex(vertex);
  const Vec3 start = point_position(model_.session().doc().scene(), ref);
  const double amplitude = 0.15 * std::max(model_.nav().camera().scene_radius, 1e-9);
  model_.session().doc().begin_drag({ref});
  std::vector<double> ms;
  double eval_ms = 0;  // the core's share: coarse re-evaluation and mesh arrays
  const double cpu_begin = process_cpu_ms();
  auto t_begin = Clock::now();
  for (int k = 0; k < kDragFrames; ++k) {
    const auto t0 = Clock::now();
    const double a = 2 * 3.141592653589793 * k / 90.0;
    model_.session().doc().drag_to(
        {start + amplitude * Vec3(std::sin(a), 0.5 * std::sin(2 * a), 0.6 * std::cos(a) - 0.6)});
    window_.poll_events();
    frame();
    glFinish();
    eval_ms += model_.status().eval_ms;
    ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
  }
  const double total = std::chrono::duration<double>(Clock::now() - t_begin).count();
  const double cpu_ms = (process_cpu_ms() - cpu_begin) / kDragFrames;
  model_.session().doc().end_drag();
  const auto release = Clock::now();
  int settle_frames = 0;
  do {
    window_.poll_events();
    frame();
    glFinish();
    ++settle_frames;
  } while (!model_.views().settled() && settle_frames < 100);
  const double settle = std::chrono::duration<double, std::milli>(Clock::now() - release).count();
  const EvaluatedView& view = *model_.views().main();
  std::size_t coarse = 0, fine = 0;
  for (int i = 0; i < model_.views().panels(); ++i) {
    coarse += model_.views().panel(i).coarse().sample_count();
    fine += model_.views().panel(i).fine().sample_count();
  }
  std::printf(
      "# drag of vertex %d, %d frames at %dx%d, %d pane(s)%s%s: %zu samples while dragging, %zu "
      "at rest (%s)\n",
      vertex, kDragFrames, options_.width, options_.height, model_.views().panels(),
      model_.views().panels() > 1 ? " " : "",
      model_.views().panels() > 1 ? schemes_keywords(model_.views().setup()).c_str() : "", coarse,
      fine, view.density_note().c_str());
  if (options_.display) std::printf("# display %s\n", options_.display->c_str());
  std::printf("# mean evaluation per drag frame %.2f ms (the rest is drawing, UI and swap)\n",
              eval_ms / kDragFrames);
  std::printf("figure editor_panes %d panes\n", model_.views().panels());
  std::printf("figure editor_drag_fps %.1f fps\n", kDragFrames / total);
  std::printf("figure editor_frame_ms_p50 %.2f ms\n", percentile(ms, 0.5));
  std::printf("figure editor_frame_ms_p95 %.2f ms\n", percentile(ms, 0.95));
  std::printf("figure editor_eval_ms_per_drag_frame %.2f ms\n", eval_ms / kDragFrames);
  // The work of a drag frame whatever else runs on the machine: every thread's CPU time
  // (llvmpipe's rasteriser threads included). Idle cores bound the frame rate by 1000 / this
  // (all of it serial) and cores / this (all of it parallel).
  std::printf("figure editor_cpu_ms_per_drag_frame %.2f ms\n", cpu_ms);
  std::printf("figure editor_settle_ms %.1f ms\n", settle);
  std::printf("figure editor_first_frame_ms %.0f ms\n", first_frame_ms_.value_or(-1));
  std::printf("figure editor_loaded_ms %.0f ms\n", loaded_ms_.value_or(-1));
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);  // ru_maxrss: the peak resident set, in KiB on Linux
  std::printf("figure editor_peak_rss_mb %.1f MB\n", usage.ru_maxrss / 1024.0);
  std::fflush(stdout);
  return 0;
}

}  // namespace pl
