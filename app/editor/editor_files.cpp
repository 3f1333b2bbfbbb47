// The window's side of files: the dialogs the model asks for (the shell's answers go back to
// the model's open_file, save_as, export_file), screenshots, and the busy indicator of a CAD
// export running on its worker.

#include "app/editor/editor.hpp"
#include "app/editor/editor_windows.hpp"
#include "app/editor/gpu_view_copy.hpp"
#include "app/editor/screenshot.hpp"
#include "core/io/atomic_file.hpp"
#include "render/default_view.hpp"
#include "render/frame.hpp"

namespace pl {

namespace fs = std::filesystem;

FileDialogs::Handlers Editor::file_dialog_handlers() {
  FileDialogs::Handlers h;
  h.open = [this](const fs::path& p) { model_.open_file(p); };
  h.save_as = [this](const fs::path& p) { model_.save_as(p); };
  h.export_file = [this](const fs::path& p) { model_.export_file(p); };
  h.screenshot = [this](const fs::path& p) { take_screenshot(p); };
  h.save = [this] { return model_.save_in_place(); };
  h.dirty = [this] { return model_.doc().dirty(); };
  h.start_dir = [this] { return model_.browse_start_dir(); };
  h.save_as_start = [this] { return model_.save_as_start(); };
  return h;
}

void Editor::confirm_discard(const std::string& doing, std::function<void()> then) {
  dialogs_.confirm_discard(doing, std::move(then));
}

void Editor::ask_open() {
  dialogs_.browse(FileDialogs::Purpose::Open, model_.browse_start_dir());
}

void Editor::ask_save_as() {
  dialogs_.browse_save_as();
}

void Editor::ask_export() {
  dialogs_.browse_export(model_.browse_start_dir(), model_.doc().path().stem().string(),
                         model_.export_format());
}

void Editor::ask_screenshot() {
  dialogs_.show_screenshot_options();
}

void Editor::show_error(const std::string& title, const std::string& message) {
  dialogs_.show_error(title, message);
}

void Editor::show_report(const std::string& title, const std::string& text) {
  dialogs_.show_report(title, text);
}

void Editor::offer_recovery(RecoveryOffer offer) {
  dialogs_.offer_recovery(std::move(offer));
}

void Editor::wake() {
  GlWindow::wake();
}

void Editor::take_screenshot(const fs::path& path) {
  const SceneViews& views = model_.views();
  const Preferences& prefs = model_.prefs();
  if (!views.ready()) return;
  try {
    ShotRequest r;
    r.width = prefs.screenshot_width;
    r.height = prefs.screenshot_height;
    r.transparent = prefs.screenshot_transparent;
    const ColorRange range = model_.views().colour_range(prefs.display, model_.doc().revision());
    const CompareSetup& setup = views.setup();
    for (int i = 0; i < views.panels(); ++i) {
      ShotPanel p{&gpu_of(views.panel(i).copy()), prefs.display, range, ""};
      if (views.panels() > 1) p.label = scheme_title(setup.schemes[i]);
      if (views.shows_distance(i)) {
        p.scene = &gpu_of(*model_.views().difference_scene(model_.doc().revision(), i));
        p.settings.base = BaseMode::Curvature;
        p.settings.curvature = CurvatureKind::Mean;
        p.label = scheme_short_title(setup.schemes[i]) + ": distance to " +
                  scheme_short_title(setup.base);
      }
      r.panels.push_back(p);
    }
    // One symmetric range for every pane's distances, known once all their fields are computed.
    if (views.showing_difference()) {
      const double m = views.difference_range();
      for (int i = 0; i < views.panels(); ++i)
        if (views.shows_distance(i)) r.panels[i].range = {-m, m};
    }
    // The legends the window shows beside the view (editor.cpp's legend column): with
    // difference colouring in a curvature mode, the base pane's curvature legend and the
    // distance legend of the others.
    r.legends = model_.legends(range);  // none without a surface to colour
    // The window's view, refitted only in aspect: same direction, target and zoom.
    r.camera = model_.nav().camera();
    const Image image = render_screenshot(renderer_, r);
    write_file_atomically(path, encode_png(image));
    model_.status().say("wrote " + path.filename().string());
  } catch (const std::exception& e) {
    show_error("Cannot write the screenshot", path.string() + ": " + e.what());
  }
}

void Editor::files_frame() {
  model_.tick_files();
  const CadExportJob& job = model_.cad_job();
  if (job.running())
    draw_busy_window("Exporting " + job.target().filename().string(), job.seconds(), ui_scale_);
}

}  // namespace pl
