#include "app/editor/editor_main.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "app/editor/editor.hpp"
#include "app/editor/logic/busy_core.hpp"
#include "app/editor/logic/compare_layout.hpp"
#include "app/editor/logic/editor_paths.hpp"
#include "app/editor/logic/grid_scene.hpp"
#include "app/editor/logic/selection.hpp"
#include "app/editor/pick_benchmark.hpp"
#include "core/analysis/compared_schemes.hpp"
#include "core/base/data_error.hpp"
#include "render/display_settings.hpp"

namespace pl {

namespace fs = std::filesystem;

namespace {

bool parse_size(const std::string& v, int& w, int& h) {
  const auto x = v.find('x');
  if (x == std::string::npos) return false;
  auto num = [](const std::string& s, int& out) {
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && end == s.data() + s.size() && out >= 64 && out <= 8192;
  };
  return num(v.substr(0, x), w) && num(v.substr(x + 1), h);
}

}  // namespace

int run_editor(std::span<const std::string> args, std::ostream& out, std::ostream& err) {
  EditorOptions o;
  bool busy = false;  // --busy: the drag benchmark with one core held busy by another process
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string* { return i + 1 < args.size() ? &args[++i] : nullptr; };
    if (a == "--bench-drag") {
      o.bench_drag = true;
    } else if (a == "--busy") {
      busy = true;
    } else if (a == "--display") {
      const std::string* v = value();
      try {
        if (!v) throw std::invalid_argument("--display takes a MODE such as mean+isophotes+combs");
        parse_display_mode(*v);
      } catch (const std::invalid_argument& e) {
        err << "patchlab: " << e.what() << "\n";
        return 2;
      }
      o.display = *v;
    } else if (a == "--bench-pick") {
      o.bench_pick = true;
    } else if (a == "--debug-point") {
      const std::string* v = value();
      const auto item = v ? parse_item_name(*v) : std::nullopt;
      if (!item) {
        err << "patchlab: --debug-point takes a name such as \"vertex 2\", \"face 1\" or "
               "\"edge 3\"\n";
        return 2;
      }
      o.debug_items.push_back(*item);
    } else if (a == "--debug-state") {
      o.debug_state = true;
    } else if (a == "--compare") {
      o.compare = true;
    } else if (a == "--difference") {
      o.compare = o.difference = true;
    } else if (a == "--compare-schemes") {
      // The comparison's panes (2, 3, 4 or 6 schemes), the first one the base.
      const std::string* v = value();
      const CompareSetup setup = v ? compare_setup_from(*v, "") : CompareSetup{};
      if (!v || schemes_keywords(setup) != *v) {
        err << "patchlab: --compare-schemes takes 2, 3, 4 or 6 of " << comparable_scheme_keywords()
            << ", comma-separated\n";
        return 2;
      }
      o.compare = true;
      o.compare_schemes = *v;
    } else if (a == "--screenshot") {
      const std::string* v = value();
      if (!v) {
        err << "patchlab: --screenshot takes OUT.png\n";
        return 2;
      }
      o.screenshot = *v;
    } else if (a == "--size") {
      const std::string* v = value();
      if (!v || !parse_size(*v, o.width, o.height)) {
        err << "patchlab: --size takes WxH (64 to 8192 each)\n";
        return 2;
      }
    } else if (a.rfind("--", 0) == 0) {
      err << "patchlab: unknown editor option " << a << "\n"
          << "usage: patchlab [FILE] [--size WxH] [--compare] [--compare-schemes S,S,...] "
             "[--difference] [--screenshot "
             "OUT.png] "
             "[--bench-drag [--busy] [--display MODE]] [--bench-pick] [--debug-point NAME]... "
             "[--debug-state]\n";
      return 2;
    } else if (!o.file) {
      o.file = a;
    } else {
      err << "patchlab: the editor opens one FILE\n";
      return 2;
    }
  }
  if (busy && !o.bench_drag) {
    err << "patchlab: --busy goes with --bench-drag\n";
    return 2;
  }
  if (o.display && !o.bench_drag) {
    err << "patchlab: --display goes with --bench-drag\n";
    return 2;
  }
  // The benchmark's window unless --size says otherwise.
  const bool sized = std::find(args.begin(), args.end(), "--size") != args.end();
  if (o.bench_drag && !sized) o.width = 1280, o.height = 720;

  if (o.bench_pick) return run_pick_benchmark(o.file, out, err);

  // Load before opening a window, so a bad file is reported like the CLI does. The default
  // scene and the other shipped samples open as untitled copies: Save asks for a path.
  DocumentSession session(shipped_scene_dirs(executable_path()));
  try {
    if (o.file) {
      session.open(*o.file);
    } else if (o.bench_drag) {
      session.replace(Document(make_grid_network_scene(2, 2)));
    } else {
      const auto def = default_scene_path(executable_path());
      if (!def) {
        err << "patchlab: cannot find assets/default.json next to the executable\n";
        return 1;
      }
      session.open(*def);
    }
  } catch (const DataError& e) {
    err << "patchlab: " << e.what() << "\n";
    return 1;
  }

  std::optional<fs::path> ini;
  if (!o.bench_drag)
    if (const auto dir = state_dir()) {
      std::error_code ec;
      fs::create_directories(*dir, ec);
      if (!ec) ini = *dir / "imgui.ini";
    }
  try {
    GlWindow window(o.width, o.height, "PatchLab", ini.value_or(fs::path()));
    Editor editor(window, o, std::move(session));
    std::optional<BusyCore> spinner;
    if (busy) {
      spinner.emplace();
      std::printf("# one core held busy by a spinning process (pid %d)\n", int(spinner->pid()));
    }
    return o.bench_drag ? editor.run_drag_benchmark() : editor.run();
  } catch (const WindowError& e) {
    err << "patchlab: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    err << "patchlab: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace pl
