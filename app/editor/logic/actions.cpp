#include "app/editor/logic/actions.hpp"

#include <algorithm>
#include <stdexcept>

namespace pl {

namespace {

// Names of the keys that are not a letter, a digit or F1-F12.
struct KeyName {
  Key key;
  const char* name;
};
constexpr KeyName kNamedKeys[] = {
    {Key::Escape, "Esc"},  {Key::Enter, "Enter"},         {Key::Tab, "Tab"},
    {Key::Space, "Space"}, {Key::Backspace, "Backspace"}, {Key::Delete, "Del"},
    {Key::Insert, "Ins"},  {Key::Home, "Home"},           {Key::End, "End"},
    {Key::Left, "Left"},   {Key::Right, "Right"},         {Key::Up, "Up"},
    {Key::Down, "Down"},   {Key::PageUp, "PgUp"},         {Key::PageDown, "PgDn"},
};

std::string key_name(Key k) {
  const int i = static_cast<int>(k);
  if (k >= Key::A && k <= Key::Z) return std::string(1, char('A' + i - int(Key::A)));
  if (k >= Key::Num0 && k <= Key::Num9) return std::string(1, char('0' + i - int(Key::Num0)));
  if (k >= Key::F1 && k <= Key::F12) {
    static const char* const f[] = {"F1", "F2", "F3", "F4",  "F5",  "F6",
                                    "F7", "F8", "F9", "F10", "F11", "F12"};
    return f[i - int(Key::F1)];
  }
  for (const KeyName& n : kNamedKeys)
    if (n.key == k) return n.name;
  return "";
}

std::optional<Key> key_of(const std::string& name) {
  if (name.size() == 1 && name[0] >= 'A' && name[0] <= 'Z')
    return static_cast<Key>(int(Key::A) + name[0] - 'A');
  if (name.size() == 1 && name[0] >= '0' && name[0] <= '9')
    return static_cast<Key>(int(Key::Num0) + name[0] - '0');
  if (name.size() >= 2 && name[0] == 'F' &&
      name.find_first_not_of("0123456789", 1) == std::string::npos) {
    const int n = std::stoi(name.substr(1));
    if (n >= 1 && n <= 12) return static_cast<Key>(int(Key::F1) + n - 1);
    return std::nullopt;
  }
  for (const KeyName& n : kNamedKeys)
    if (name == n.name) return n.key;
  return std::nullopt;
}

}  // namespace

std::string to_string(const KeyChord& c) {
  std::string s;
  if (c.ctrl) s += "Ctrl+";
  if (c.shift) s += "Shift+";
  if (c.alt) s += "Alt+";
  return s + key_name(c.key);
}

std::optional<KeyChord> parse_chord(const std::string& text) {
  KeyChord c;
  std::size_t start = 0;
  while (true) {
    const std::size_t plus = text.find('+', start);
    // A trailing '+' belongs to the key name only if the key were '+', which has no code here.
    const std::string part = text.substr(start, plus == std::string::npos ? plus : plus - start);
    if (plus == std::string::npos) {
      const auto k = key_of(part);
      if (!k) return std::nullopt;
      c.key = *k;
      return c;
    }
    if (part == "Ctrl" && !c.ctrl)
      c.ctrl = true;
    else if (part == "Shift" && !c.shift)
      c.shift = true;
    else if (part == "Alt" && !c.alt)
      c.alt = true;
    else
      return std::nullopt;
    start = plus + 1;
  }
}

Action make_action(std::string id, std::string menu, std::string label,
                   const std::vector<std::string>& keys, std::string help,
                   std::function<void()> run) {
  Action a;
  a.id = std::move(id);
  a.menu = std::move(menu);
  a.label = std::move(label);
  for (const std::string& k : keys) {
    const auto chord = parse_chord(k);
    if (!chord) throw std::invalid_argument("action " + a.id + ": no such key \"" + k + "\"");
    a.keys.push_back(*chord);
  }
  a.help = std::move(help);
  if (run) a.run = [run = std::move(run)](const std::optional<KeyChord>&) { run(); };
  return a;
}

void ActionRegistry::add(Action action) {
  if (action.id.empty() || find(action.id))
    throw std::invalid_argument("action id empty or used twice: \"" + action.id + "\"");
  if (!action.run) throw std::invalid_argument("action " + action.id + " does nothing");
  actions_.push_back(std::move(action));
}

const Action* ActionRegistry::find(const std::string& id) const {
  for (const Action& a : actions_)
    if (a.id == id) return &a;
  return nullptr;
}

bool ActionRegistry::run(const std::string& id) const {
  const Action* a = find(id);
  if (!a || !is_enabled(*a)) return false;
  a->run(std::nullopt);
  return true;
}

const Action* ActionRegistry::bound_to(const KeyChord& chord) const {
  for (const Action& a : actions_)
    if (std::find(a.keys.begin(), a.keys.end(), chord) != a.keys.end()) return &a;
  return nullptr;
}

std::string ActionRegistry::disabled_reason(const Action& a) const {
  std::string why = a.why_disabled ? a.why_disabled() : std::string();
  return why.empty() ? "not available now" : why;
}

bool ActionRegistry::trigger(const KeyChord& chord,
                             const std::function<void(const std::string&)>& refused) const {
  const Action* a = bound_to(chord);
  if (!a) return false;
  if (!is_enabled(*a)) {
    if (refused) refused(a->label + ": " + disabled_reason(*a));
    return false;
  }
  a->run(chord);
  return true;
}

std::vector<std::string> ActionRegistry::menus() const {
  std::vector<std::string> m;
  for (const Action& a : actions_) {
    if (a.menu.empty()) continue;
    const std::string top = a.menu.substr(0, a.menu.find('/'));
    if (std::find(m.begin(), m.end(), top) == m.end()) m.push_back(top);
  }
  return m;
}

std::vector<ActionRegistry::Entry> ActionRegistry::entries(const std::string& menu) const {
  std::vector<Entry> e;
  const std::string prefix = menu + "/";
  for (const Action& a : actions_) {
    if (a.menu == menu) {
      e.push_back({&a, ""});
    } else if (a.menu.rfind(prefix, 0) == 0) {
      const std::size_t slash = a.menu.find('/', prefix.size());
      const std::string sub = a.menu.substr(0, slash);
      const bool listed = std::any_of(
          e.begin(), e.end(), [&](const Entry& x) { return !x.action && x.submenu == sub; });
      if (!listed) e.push_back({nullptr, sub});
    }
  }
  return e;
}

std::vector<const Action*> ActionRegistry::for_context(ContextTarget target) const {
  std::vector<const Action*> r;
  for (const Action& a : actions_)
    if (a.context & context_bit(target)) r.push_back(&a);
  // Tables add actions by feature, so one menu's may be apart ("Edit/Delete" with the authoring
  // actions, "Edit/Rename" later): the menu shows each menu's once, as one group.
  std::vector<std::string> order;
  for (const Action* a : r)
    if (std::find(order.begin(), order.end(), a->menu) == order.end()) order.push_back(a->menu);
  std::stable_sort(r.begin(), r.end(), [&](const Action* x, const Action* y) {
    return std::find(order.begin(), order.end(), x->menu) <
           std::find(order.begin(), order.end(), y->menu);
  });
  return r;
}

std::vector<std::string> ActionRegistry::conflicts() const {
  std::vector<std::string> out;
  std::vector<KeyChord> reported;
  for (const Action& a : actions_)
    for (const KeyChord& k : a.keys) {
      if (std::find(reported.begin(), reported.end(), k) != reported.end()) continue;
      std::string users;
      int n = 0;
      for (const Action& b : actions_)
        if (std::find(b.keys.begin(), b.keys.end(), k) != b.keys.end())
          users += (n++ ? ", " : "") + b.id;
      if (n > 1) {
        out.push_back(to_string(k) + ": " + users);
        reported.push_back(k);
      }
    }
  return out;
}

std::vector<HelpRow> help_rows(const ActionRegistry& actions, const std::vector<HelpRow>& mouse) {
  std::vector<HelpRow> rows, menu_only;
  for (const Action& a : actions.all()) {
    const std::string what = a.help.empty() ? a.label : a.help;
    if (a.keys.empty() && a.keys_text.empty()) {
      // Reached from a menu only: the menu instead of a key, the place in it before the help
      // ("View menu", "Work Plane > XY Plane: ...").
      if (a.menu.empty()) continue;
      const std::size_t slash = a.menu.find('/');
      std::string place =
          slash == std::string::npos ? std::string() : a.menu.substr(slash + 1) + "/";
      for (std::size_t i = 0; (i = place.find('/', i)) != std::string::npos; i += 3)
        place.replace(i, 1, " > ");
      menu_only.push_back({a.menu.substr(0, slash) + " menu",
                           place + a.label + (a.help.empty() ? "" : ": " + a.help)});
      continue;
    }
    std::string keys = a.keys_text;
    if (keys.empty())
      for (const KeyChord& k : a.keys) keys += (keys.empty() ? "" : ", ") + to_string(k);
    rows.push_back({keys, what});
  }
  rows.insert(rows.end(), mouse.begin(), mouse.end());
  rows.insert(rows.end(), menu_only.begin(), menu_only.end());
  return rows;
}

}  // namespace pl
