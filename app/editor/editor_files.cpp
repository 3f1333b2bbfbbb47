// Files: new, open (scene or .gbp), save (back to the file's own type), save as, export (mesh
// at once, STEP/IGES on a worker thread), screenshots, drag and drop, the autosave and the
// recovery of work a crash left. Where a document may be written is the session's rule; errors
// go to a dialog.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdlib>
#include <ctime>
#include <iostream>

#include "app/document/scene_commands.hpp"
#include "app/editor/editor.hpp"
#include "app/editor/editor_windows.hpp"
#include "app/editor/screenshot.hpp"
#include "core/base/data_error.hpp"
#include "core/io/atomic_file.hpp"
#include "core/mesh/mesh_export.hpp"
#include "render/default_view.hpp"
#include "render/frame.hpp"

namespace pl {

namespace fs = std::filesystem;

FileDialogs::Handlers Editor::file_dialog_handlers() {
  FileDialogs::Handlers h;
  h.open = [this](const fs::path& p) { open_file(p); };
  h.save_as = [this](const fs::path& p) { save_as(p); };
  h.export_file = [this](const fs::path& p) { export_file(p); };
  h.screenshot = [this](const fs::path& p) { take_screenshot(p); };
  h.save = [this] { return save_in_place(); };
  h.dirty = [this] { return session_.doc().dirty(); };
  h.start_dir = [this] { return browse_start_dir(); };
  h.save_as_start = [this] {
    const DocumentSession::Suggestion s = session_.save_as_suggestion();
    std::error_code ec;
    return std::pair(fs::is_directory(s.dir, ec) && !session_.read_only(s.dir / "x")
                         ? s.dir
                         : browse_start_dir(),
                     s.name);
  };
  return h;
}

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

bool Editor::save_in_place() {
  try {
    if (!session_.save()) return false;
    autosave_.discard();
    status_.say("saved " + session_.doc().path().filename().string());
    if (debugging())
      std::cout << "saved " << session_.doc().path().string() << " revision "
                << session_.doc().revision() << std::endl;
  } catch (const std::exception& e) {
    dialogs_.show_error("Cannot save", e.what());
  }
  return true;
}

void Editor::save() {
  if (!save_in_place()) browse_save_as();
}

void Editor::browse_save_as() {
  dialogs_.browse_save_as();
}

void Editor::save_as(const fs::path& path) {
  try {
    const fs::path written = session_.save_as(path);
    autosave_.discard();
    prefs_.last_directory = written.parent_path().string();
    status_.say("saved " + written.filename().string());
    if (debugging())
      std::cout << "saved " << written.string() << " revision " << session_.doc().revision()
                << std::endl;
  } catch (const DataError& e) {
    dialogs_.show_error("Cannot save", e.what());
  } catch (const std::exception& e) {
    dialogs_.show_error("Cannot save", path.string() + ": " + e.what());
  }
}

void Editor::export_file(const fs::path& path) {
  if (cad_format_for(path)) {
    // The scene as it is now (a copy: editing may go on meanwhile), faces as their own schemes.
    CadExportOptions o;
    o.source = session_.untitled() ? session_.title() : session_.doc().path().string();
    if (!cad_job_.start(session_.doc().scene(), path, o, [] { glfwPostEmptyEvent(); }))
      dialogs_.show_error("Cannot export", "an export to " + cad_job_.target().filename().string() +
                                               " is still running; try again when it has finished");
    return;
  }
  if (!views_.ready()) return;
  try {
    export_meshes(views_.own(session_.doc()).fine().draw().surfaces, path);
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
    const CompareSetup& setup = views_.setup();
    for (int i = 0; i < views_.panels(); ++i) {
      ShotPanel p{&views_.panel(i).gpu(), prefs_.display, range, ""};
      if (views_.panels() > 1) p.label = scheme_title(setup.schemes[i]);
      if (views_.shows_distance(i)) {
        p.scene = views_.difference_scene(session_.doc().revision(), i);
        p.settings.base = BaseMode::Curvature;
        p.settings.curvature = CurvatureKind::Mean;
        p.label = scheme_short_title(setup.schemes[i]) + ": distance to " +
                  scheme_short_title(setup.base);
      }
      r.panels.push_back(p);
    }
    // One symmetric range for every pane's distances, known once all their fields are computed.
    if (views_.showing_difference()) {
      const double m = views_.difference_range();
      for (int i = 0; i < views_.panels(); ++i)
        if (views_.shows_distance(i)) r.panels[i].range = {-m, m};
      r.legend_title = "distance to " + scheme_short_title(setup.base);
      r.legend_range = {-m, m};
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

void Editor::files_frame() {
  const Document& doc = session_.doc();
  // While dragging the write waits for the release: it would hitch the drag's frames.
  if (!doc.dirty())
    autosave_.discard();
  else if (!doc.dragging())
    autosave_.tick(doc.scene(), true, doc.path().string(), Autosave::Clock::now());

  if (cad_job_.running())
    draw_busy_window("Exporting " + cad_job_.target().filename().string(), cad_job_.seconds(),
                     ui_scale_);
  if (const auto done = cad_job_.poll()) {
    if (done->ok) {
      status_.say("exported " + done->target.filename().string());
      dialogs_.show_report("Exported " + done->target.string(), done->text);
    } else {
      dialogs_.show_error("Cannot export", done->text);
    }
  }
}

void Editor::offer_recovery() {
  const std::vector<Autosave::Recovery> pending = autosave_.pending();
  if (pending.empty()) return;
  const Autosave::Recovery r = pending.front();
  FileDialogs::RecoveryOffer offer;
  offer.document = r.document;
  const auto written = std::chrono::file_clock::to_sys(r.written);
  const std::time_t t = std::chrono::system_clock::to_time_t(written);
  char when[64] = "";
  std::strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S", std::localtime(&t));
  offer.when = when;
  offer.recover = [this, r] {
    try {
      Scene scene = Autosave::recover(r);
      // On top of the file it was an edit of, so undo goes back to the file as saved; when
      // that file is gone (or was a shipped sample), as an untitled scene.
      const fs::path file = r.document;
      try {
        if (file.empty()) throw DataError("", "", "no file");
        session_.open(file);
      } catch (const DataError&) {
        session_.replace(Document(Scene{}), "recovered");
      }
      session_.doc().execute(
          std::make_unique<ReplaceSceneCommand>(std::move(scene), "recovered unsaved changes"));
      Autosave::drop(r);
      status_.say("recovered the unsaved changes; save them to keep them");
    } catch (const DataError& e) {
      dialogs_.show_error("Cannot recover", e.what());
    }
    offer_recovery();  // an older one, if any
  };
  offer.discard = [this, r] {
    Autosave::drop(r);
    offer_recovery();
  };
  if (debugging()) std::cout << "recovery-offer " << r.file.string() << std::endl;
  dialogs_.offer_recovery(std::move(offer));
}

std::vector<const DrawScene*> Editor::shown_scenes() const {
  std::vector<const DrawScene*> scenes;
  if (views_.ready())
    for (int i = 0; i < views_.panels(); ++i) scenes.push_back(&views_.panel(i).shown().draw());
  return scenes;
}

void Editor::open_view() {
  nav_.open_view(shown_scenes(), layout().panels(views_.panels())[0].aspect());
}

void Editor::frame_shown() {
  nav_.frame_tightly(shown_scenes(), layout().panels(views_.panels())[0].aspect());
}

}  // namespace pl
