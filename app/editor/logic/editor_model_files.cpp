// Files: new, open (scene or .gbp), save (back to the file's own type), save as, export (mesh
// at once, STEP/IGES on a worker thread), drops, the autosave and the recovery of work a crash
// left; and the names of faces and edges. Where a document may be written is the session's
// rule; errors go to the shell's dialog.
#include <cstdlib>
#include <ctime>
#include <iostream>
#include <stdexcept>

#include "app/document/network_commands.hpp"
#include "app/document/scene_commands.hpp"
#include "app/editor/logic/editor_model.hpp"
#include "core/base/data_error.hpp"
#include "core/mesh/mesh_export.hpp"

namespace pl {

namespace fs = std::filesystem;

fs::path EditorModel::browse_start_dir() const {
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

std::pair<fs::path, std::string> EditorModel::save_as_start() const {
  const DocumentSession::Suggestion s = session_.save_as_suggestion();
  std::error_code ec;
  return {
      fs::is_directory(s.dir, ec) && !session_.read_only(s.dir / "x") ? s.dir : browse_start_dir(),
      s.name};
}

void EditorModel::new_scene() {
  session_.new_scene();
  work_plane_.shown = true;  // an empty view shows where new points will go
  say("new scene");
}

void EditorModel::open_file(const fs::path& path) {
  try {
    session_.open(path);
    prefs_.last_directory = fs::absolute(path).parent_path().string();
    say((session_.untitled() ? "opened a copy of " : "opened ") + path.filename().string());
  } catch (const DataError& e) {
    shell_.show_error("Cannot open file", e.what());
  } catch (const std::exception& e) {
    shell_.show_error("Cannot open file", path.string() + ": " + e.what());
  }
}

bool EditorModel::save_in_place() {
  try {
    if (!session_.save()) return false;
    autosave_.discard();
    say("saved " + session_.doc().path().filename().string());
    if (options_.report_saves)
      std::cout << "saved " << session_.doc().path().string() << " revision "
                << session_.doc().revision() << std::endl;
  } catch (const std::exception& e) {
    shell_.show_error("Cannot save", e.what());
  }
  return true;
}

void EditorModel::save() {
  if (!save_in_place()) shell_.ask_save_as();
}

void EditorModel::save_as(const fs::path& path) {
  try {
    const fs::path written = session_.save_as(path);
    autosave_.discard();
    prefs_.last_directory = written.parent_path().string();
    say("saved " + written.filename().string());
    if (options_.report_saves)
      std::cout << "saved " << written.string() << " revision " << session_.doc().revision()
                << std::endl;
  } catch (const DataError& e) {
    shell_.show_error("Cannot save", e.what());
  } catch (const std::exception& e) {
    shell_.show_error("Cannot save", path.string() + ": " + e.what());
  }
}

void EditorModel::export_file(const fs::path& typed) {
  fs::path path;
  try {
    path = export_target(typed, export_format_);
  } catch (const std::invalid_argument& e) {
    shell_.show_error("Cannot export", typed.filename().string() + ": " + e.what());
    return;
  }
  if (export_format_of(path)->cad) {
    // The scene as it is now (a copy: editing may go on meanwhile), faces as their own schemes.
    CadExportOptions o;
    o.source = session_.untitled() ? session_.title() : session_.doc().path().string();
    if (!cad_job_.start(session_.doc().scene(), path, o, [this] { shell_.wake(); }))
      shell_.show_error("Cannot export", "an export to " + cad_job_.target().filename().string() +
                                             " is still running; try again when it has finished");
    return;
  }
  if (!views_.ready()) return;
  try {
    export_meshes(views_.own(session_.doc()).fine().draw().surfaces, path);
    say("exported " + path.filename().string());
  } catch (const std::exception& e) {
    shell_.show_error("Cannot export", path.string() + ": " + e.what());
  }
}

void EditorModel::drop(const fs::path& path) {
  follow_session();
  shell_.confirm_discard("open " + path.filename().string(), [this, path] { open_file(path); });
  follow_session();
}

void EditorModel::tick_files() {
  const Document& doc = session_.doc();
  // While dragging the write waits for the release: it would hitch the drag's frames.
  if (!doc.dirty())
    autosave_.discard();
  else if (!doc.dragging())
    autosave_.tick(doc.scene(), true, doc.path().string(), Autosave::Clock::now());
  if (const auto done = cad_job_.poll()) {
    if (done->ok) {
      say("exported " + done->target.filename().string());
      shell_.show_report("Exported " + done->target.string(), done->text);
    } else {
      shell_.show_error("Cannot export", done->text);
    }
  }
}

void EditorModel::offer_recovery() {
  const std::vector<Autosave::Recovery> pending = autosave_.pending();
  if (pending.empty()) return;
  const Autosave::Recovery r = pending.front();
  RecoveryOffer offer;
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
      say("recovered the unsaved changes; save them to keep them");
    } catch (const DataError& e) {
      shell_.show_error("Cannot recover", e.what());
    }
    offer_recovery();  // an older one, if any
  };
  offer.discard = [this, r] {
    Autosave::drop(r);
    offer_recovery();
  };
  if (options_.report_saves) std::cout << "recovery-offer " << r.file.string() << std::endl;
  shell_.offer_recovery(std::move(offer));
}

void EditorModel::start_rename() {
  const Scene& scene = session_.doc().scene();
  if (selection_.size() != 1 || !scene.network) return;
  const SelectionItem& item = selection_.items()[0];
  if (!item_exists(scene, item)) return;
  if (item.kind == SelectionItem::Kind::Face)
    shell_.ask_name(item, scene.network->faces[item.index].name);
  else if (item.kind == SelectionItem::Kind::Edge)
    shell_.ask_name(item, scene.network->edges[item.index].name);
}

void EditorModel::rename(const SelectionItem& item, const std::string& name) {
  const Scene& scene = session_.doc().scene();
  if (!item_exists(scene, item)) return;  // gone meanwhile
  const bool face = item.kind == SelectionItem::Kind::Face;
  if (name ==
      (face ? scene.network->faces[item.index].name : scene.network->edges[item.index].name))
    return;  // unchanged: no undo step
  std::shared_ptr<Command> c;
  if (face)
    c = std::make_shared<SetFaceNameCommand>(item.index, name);
  else
    c = std::make_shared<SetEdgeNameCommand>(item.index, name);
  run_command(
      session_.doc(), [this](const std::string& m) { say(m); }, c);
}

}  // namespace pl
