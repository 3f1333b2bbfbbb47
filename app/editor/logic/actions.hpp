// Every command the user can give, in one table: its menu place, label, keys, help text,
// whether it is available now, and what it does. The menu bar, the right-click context menu,
// the key bindings and the F1 help are all drawn from this table, so a new command (an
// authoring tool, a face command) is one entry and shows up everywhere at once, and no two
// commands can share a key unnoticed (conflicts()). GUI-free and unit-tested: keys are the
// editor's own codes, which the window layer maps from GLFW's.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace pl {

enum class Key {
  None,
  A,
  B,
  C,
  D,
  E,
  F,
  G,
  H,
  I,
  J,
  K,
  L,
  M,
  N,
  O,
  P,
  Q,
  R,
  S,
  T,
  U,
  V,
  W,
  X,
  Y,
  Z,
  Num0,
  Num1,
  Num2,
  Num3,
  Num4,
  Num5,
  Num6,
  Num7,
  Num8,
  Num9,
  F1,
  F2,
  F3,
  F4,
  F5,
  F6,
  F7,
  F8,
  F9,
  F10,
  F11,
  F12,
  Escape,
  Enter,
  Tab,
  Space,
  Backspace,
  Delete,
  Insert,
  Home,
  End,
  Left,
  Right,
  Up,
  Down,
  PageUp,
  PageDown,
};

struct KeyChord {
  Key key = Key::None;
  bool ctrl = false, shift = false, alt = false;
  bool operator==(const KeyChord&) const = default;
};

// "Ctrl+Shift+S", "F1", "Del", "PgUp"; parse_chord accepts what to_string gives.
std::string to_string(const KeyChord& chord);
std::optional<KeyChord> parse_chord(const std::string& text);

// What the right-click menu was opened on: the kind of object under the cursor.
enum class ContextTarget { Empty, Point, Edge, Face, Patch, Curve };

// Bit set of ContextTargets an action is offered on.
using ContextSet = unsigned;
constexpr ContextSet context_bit(ContextTarget t) {
  return 1u << static_cast<unsigned>(t);
}
constexpr ContextSet kAnyContext = 0x1f;

struct Action {
  std::string id;    // "file.new": stable, for tests and scripts
  std::string menu;  // menu path, "/"-separated ("Face/Scheme"); empty: no menu entry
  std::string label;
  std::function<std::string()> detail;  // shown after the label in menus ("Undo" "move vertex 2")
  std::vector<KeyChord> keys;           // the first is shown in menus; all are bound
  std::string keys_text;                // shown in F1 instead of the keys, when set ("Arrows")
  std::string help;                     // one line for F1
  bool separator_before = false;
  ContextSet context = 0;         // where the right-click menu offers it
  std::function<bool()> enabled;  // null: always
  // Why it is not enabled now, for the status bar (its key pressed) and the greyed menu item's
  // tooltip ("nothing selected to delete"); null or "": a general line (disabled_reason).
  std::function<std::string()> why_disabled;
  std::function<bool()> checked;  // null: not a toggle
  // Runs the action; `chord` is the key that triggered it (nullopt from a menu).
  std::function<void(const std::optional<KeyChord>& chord)> run;
};

// An action from its usual fields; `keys` as text ("Ctrl+S"; each must parse, else
// std::invalid_argument), `run` ignoring which key triggered it.
Action make_action(std::string id, std::string menu, std::string label,
                   const std::vector<std::string>& keys, std::string help,
                   std::function<void()> run);

class ActionRegistry {
 public:
  // Throws std::invalid_argument for a duplicate id or a missing run function.
  void add(Action action);
  const Action* find(const std::string& id) const;
  const std::vector<Action>& all() const { return actions_; }

  bool is_enabled(const Action& a) const { return !a.enabled || a.enabled(); }
  // Why `a` is not enabled now: its why_disabled, else that it does not apply now.
  std::string disabled_reason(const Action& a) const;
  // Runs `id` if it exists and is enabled; returns whether it ran.
  bool run(const std::string& id) const;
  // The action bound to `chord`, enabled or not; null if none.
  const Action* bound_to(const KeyChord& chord) const;
  // Runs the enabled action bound to `chord`; returns whether one ran. When the action bound to
  // it is not enabled, `refused` (if given) gets "<label>: <disabled_reason>".
  bool trigger(const KeyChord& chord,
               const std::function<void(const std::string&)>& refused = {}) const;

  // Top-level menus in the order their first action was added.
  std::vector<std::string> menus() const;
  // The direct entries of `menu`: actions whose menu is exactly it, and the names of its
  // sub-menus (as Entry with action null), in order of first appearance.
  struct Entry {
    const Action* action = nullptr;
    std::string submenu;  // full path of the sub-menu when action is null
  };
  std::vector<Entry> entries(const std::string& menu) const;
  // The actions offered on a right-click on `target`: the actions of one menu together (the
  // menus in the order their first offered action comes in the table), each menu's in table order.
  std::vector<const Action*> for_context(ContextTarget target) const;

  // Every key given to more than one action, as "Ctrl+S: file.save, other.id".
  std::vector<std::string> conflicts() const;

 private:
  std::vector<Action> actions_;
};

// The F1 table: one row per action with keys (its keys text and its help, or label), then the
// mouse rows given, then the actions reached from a menu only ("Network menu", "Tangent Plane >
// Fixed: " and their help), in that order: every command is listed.
struct HelpRow {
  std::string keys, what;
};
std::vector<HelpRow> help_rows(const ActionRegistry& actions, const std::vector<HelpRow>& mouse);

}  // namespace pl
