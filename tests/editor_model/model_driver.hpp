// Drives an EditorModel as the window would, with synthetic events and no display: a frame per
// event (the pointer as that frame saw it, then update()), and the model followed until it is at
// rest, as the end-to-end driver waits for the editor's state at rest. Where objects are on
// screen is read as the end-to-end driver reads the editor's --debug-state lines (pixels printed
// to 0.1, clicks at whole pixels rounded half to even), so the same script lands on the same
// pixels in both.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/editor/logic/editor_model.hpp"

namespace pl::test {

// Answers the model's questions as a user who agrees: no unsaved changes are ever in the way
// (the question is counted), and a Save As is recorded for the test to answer.
class ScriptedShell final : public EditorShell {
 public:
  std::function<bool()> dirty;  // whether confirm_discard would have to ask
  int discard_questions = 0, save_as_requests = 0, errors = 0;
  std::string last_error;
  std::optional<SelectionItem> rename_item;

  void confirm_discard(const std::string&, std::function<void()> then) override {
    if (dirty && dirty()) {
      ++discard_questions;
      return;
    }
    then();
  }
  void ask_open() override {}
  void ask_save_as() override { ++save_as_requests; }
  void ask_export() override {}
  void ask_screenshot() override {}
  void ask_name(const SelectionItem& item, const std::string&) override { rename_item = item; }
  void show_error(const std::string& title, const std::string& message) override {
    ++errors;
    last_error = title + ": " + message;
  }
  void show_report(const std::string&, const std::string&) override {}
  void offer_recovery(RecoveryOffer) override {}
  void wake() override {}
};

class ModelDriver {
 public:
  // A window of `width` x `height` at UI scale 1 with the editor's theme.
  ModelDriver(int width, int height, DocumentSession session = DocumentSession(),
              EditorModelOptions options = {});

  EditorModel& model() { return *model_; }
  ScriptedShell& shell() { return shell_; }

  // Frames until the views are shown at their fine density, nothing is held and the document
  // has been followed; fails the test after 20 s.
  void settle();
  // A key chord by its name ("Ctrl+S", "Enter", "V"), then the model at rest.
  void key(const std::string& chord);
  // File > New, then the orthographic view (where pixels map to the work plane affinely), as
  // the end-to-end driver's new_scene().
  void new_scene();
  // The pointer goes to whole pixels, as a real pointer does.
  void move(const Vec2& pixel);
  // Button 0 left, 1 right, 2 middle: moved there first (a frame of hover), then pressed.
  void press(const Vec2& pixel, int button = 0);
  void drag_to(const Vec2& pixel);
  void release(int button = 0);
  void click(const Vec2& pixel, int button = 0);
  // The modifier keys held from now on (as the pointer sees them).
  void hold(bool shift, bool ctrl, bool alt);

  // Where the --debug-state lines put things, as the end-to-end driver reads them.
  Vec2 vertex(int v);
  Vec2 edge(int e);
  Vec2 face(int f);
  Vec2 curve(int c);                   // on free curve c's line, away from its points
  Vec2 knob(int v);                    // the normal knob of selected vertex v
  Vec2 world_to_pixel(const Vec3& p);  // affine, from the printed axes (orthographic views)

 private:
  void frame(const PointerInput& in);
  ViewRect view_rect() const;
  Vec2 printed(const std::optional<Vec2>& p, const char* what) const;
  std::optional<Vec2> pick_pixel(const SelectionItem& item);

  ScriptedShell shell_;
  std::unique_ptr<EditorModel> model_;
  PointerInput pointer_;
};

// A folder of its own for a test's files (named after `name` and the process), removed after.
class TempDir {
 public:
  explicit TempDir(const std::string& name);
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// A pixel as a click lands on it: the end-to-end driver rounds (half to even) to whole pixels.
Vec2 whole_pixel(const Vec2& p);

}  // namespace pl::test
