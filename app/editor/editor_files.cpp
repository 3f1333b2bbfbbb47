// Files: new, open (scene or .gbp import), save, save as, mesh export, screenshots, drag and
// drop. Where a document may be written is the session's rule; errors go to a dialog.
#include <cstdlib>
#include <iostream>

#include "app/editor/editor.hpp"
#include "app/editor/screenshot.hpp"
#include "core/io/atomic_file.hpp"
#include "core/base/data_error.hpp"
#include "core/mesh/mesh_export.hpp"
#include "render/frame.hpp"

namespace pl {

namespace fs = std::filesystem;

fs::path Editor::browse_start_dir() const {
  std::error_code ec;
  const fs::path& path = session_.doc().path();
  if (!path.empty() && fs::is_directory(path.parent_path(), ec)) return path.parent_path();
  // Never the samples' folder: nothing may be saved there.
  if (!prefs_.last_directory.empty() && fs::is_directory(prefs_.last_directory, ec) &&
      !session_.read_only(fs::path(prefs_.last_directory) / "x"))
    return prefs_.last_directory;
  if (const char* home = std::getenv("HOME")) return home;
  return fs::current_path(ec);
}

void Editor::new_scene() {
  session_.new_scene();
  work_plane_.shown = true;  // an empty view shows where new points will go
  status_.say("new scene");
}

void Editor::open_file(const fs::path& path) {
  try {
    session_.open(path);
    prefs_.last_directory = fs::absolute(path).parent_path().string();
    status_.say((session_.untitled() ? "opened a copy of " : "opened ") + path.filename().string());
  } catch (const DataError& e) {
    dialogs_.show_error("Cannot open file", e.what());
  } catch (const std::exception& e) {
    dialogs_.show_error("Cannot open file", path.string() + ": " + e.what());
  }
}

void Editor::save() {
  if (session_.untitled()) {
    dialogs_.browse(FileDialogs::Purpose::SaveAs, browse_start_dir());
    return;
  }
  try {
    session_.save();
    status_.say("saved " + session_.doc().path().filename().string());
    if (debugging())
      std::cout << "saved " << session_.doc().path().string() << " revision "
                << session_.doc().revision() << std::endl;
  } catch (const std::exception& e) {
    dialogs_.show_error("Cannot save", e.what());
  }
}

void Editor::save_as(const fs::path& path) {
  try {
    session_.save_as(path);
    prefs_.last_directory = path.parent_path().string();
    status_.say("saved " + path.filename().string());
    if (debugging())
      std::cout << "saved " << path.string() << " revision " << session_.doc().revision()
                << std::endl;
  } catch (const DataError& e) {
    dialogs_.show_error("Cannot save", e.what());
  } catch (const std::exception& e) {
    dialogs_.show_error("Cannot save", path.string() + ": " + e.what());
  }
}

void Editor::export_mesh(const fs::path& path) {
  if (!views_.ready()) return;
  try {
    export_meshes(views_.main()->fine().draw().surfaces, path);
    status_.say("exported " + path.filename().string());
  } catch (const std::exception& e) {
    dialogs_.show_error("Cannot export", path.string() + ": " + e.what());
  }
}

void Editor::take_screenshot(const fs::path& path) {
  if (!views_.ready()) return;
  try {
    ShotRequest r;
    r.width = prefs_.screenshot_width;
    r.height = prefs_.screenshot_height;
    r.transparent = prefs_.screenshot_transparent;
    const ColorRange range = views_.colour_range(prefs_.display, session_.doc().revision());
    for (int i = 0; i < views_.panels(); ++i) {
      ShotPanel p{&views_.panel(i).gpu(), prefs_.display, range, ""};
      if (views_.compare()) p.label = i == 0 ? "Gregory" : "Generalized Bezier";
      if (views_.showing_difference() && i == 1) {
        const double m = views_.difference_range();
        p.scene = views_.difference_scene(session_.doc().revision());
        p.settings.base = BaseMode::Curvature;
        p.settings.curvature = CurvatureKind::Mean;
        p.range = {-m, m};
        p.label = "GB: distance to Gregory";
        r.legend_title = "distance";
        r.legend_range = p.range;
      }
      r.panels.push_back(p);
    }
    if (r.legend_title.empty() && prefs_.display.base == BaseMode::Curvature) {
      r.legend_title = std::string(curvature_name(prefs_.display.curvature)) + " curvature";
      r.legend_range = range;
    }
    // The window's view, refitted only in aspect: same direction, target and zoom.
    r.camera = nav_.camera();
    const Image image = render_screenshot(renderer_, r);
    write_file_atomically(path, encode_png(image));
    status_.say("wrote " + path.filename().string());
  } catch (const std::exception& e) {
    dialogs_.show_error("Cannot write the screenshot", path.string() + ": " + e.what());
  }
}

void Editor::handle_drops() {
  if (dropped_.empty()) return;
  const fs::path path = dropped_.front();
  dropped_.clear();  // one document at a time: the first dropped file
  dialogs_.confirm_discard("open " + path.filename().string(), [this, path] { open_file(path); });
}

}  // namespace pl
