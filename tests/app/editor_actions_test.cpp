// The action table: key names, menus and sub-menus, key dispatch, conflicts and the F1 rows.
#include <gtest/gtest.h>

#include "app/editor/logic/actions.hpp"

namespace pl {
namespace {

TEST(EditorActions, ChordsPrintAndParse) {
  for (const char* text : {"Ctrl+Shift+S", "F1", "F12", "Del", "PgUp", "Shift+F", "Alt+Left",
                           "Ctrl+0", "Esc", "Ctrl+Shift+Alt+Z"}) {
    const auto c = parse_chord(text);
    ASSERT_TRUE(c) << text;
    EXPECT_EQ(to_string(*c), text);
  }
  EXPECT_EQ(parse_chord("Ctrl+N")->key, Key::N);
  EXPECT_TRUE(parse_chord("Ctrl+N")->ctrl);
  EXPECT_FALSE(parse_chord("Ctrl+N")->shift);
  for (const char* bad : {"", "Ctrl+", "Ctrl+Ctrl+S", "F13", "F0", "Hyper+S", "SS", "s"})
    EXPECT_FALSE(parse_chord(bad)) << bad;
}

struct Counter {
  int runs = 0;
  std::optional<KeyChord> last;
};

Action counting(const std::string& id, const std::string& menu, Counter& c,
                std::vector<KeyChord> keys = {}) {
  Action a;
  a.id = id;
  a.menu = menu;
  a.label = id;
  a.keys = std::move(keys);
  a.run = [&c](const std::optional<KeyChord>& k) {
    ++c.runs;
    c.last = k;
  };
  return a;
}

TEST(EditorActions, MenusKeysAndContext) {
  ActionRegistry r;
  Counter save, close, scheme, frame;
  bool can_close = false;
  r.add(counting("file.save", "File", save, {*parse_chord("Ctrl+S")}));
  Action c = counting("file.close", "File", close, {*parse_chord("Ctrl+W")});
  c.enabled = [&] { return can_close; };
  r.add(std::move(c));
  Action s = counting("face.scheme.gb", "Face/Scheme", scheme);
  s.context = context_bit(ContextTarget::Face);
  r.add(std::move(s));
  r.add(counting("view.frame", "View", frame, {*parse_chord("F"), *parse_chord("Shift+F")}));
  EXPECT_THROW(r.add(counting("file.save", "File", save)), std::invalid_argument);
  Action nothing;
  nothing.id = "x";
  EXPECT_THROW(r.add(nothing), std::invalid_argument);

  EXPECT_EQ(r.menus(), (std::vector<std::string>{"File", "Face", "View"}));
  const auto face = r.entries("Face");
  ASSERT_EQ(face.size(), 1u);
  EXPECT_EQ(face[0].action, nullptr);
  EXPECT_EQ(face[0].submenu, "Face/Scheme");
  ASSERT_EQ(r.entries("Face/Scheme").size(), 1u);
  EXPECT_EQ(r.entries("Face/Scheme")[0].action->id, "face.scheme.gb");

  EXPECT_TRUE(r.trigger(*parse_chord("Ctrl+S")));
  EXPECT_EQ(save.runs, 1);
  EXPECT_EQ(*save.last, *parse_chord("Ctrl+S"));
  EXPECT_FALSE(r.trigger(*parse_chord("Ctrl+W")));  // disabled
  EXPECT_EQ(r.bound_to(*parse_chord("Ctrl+W"))->id, "file.close");
  can_close = true;
  EXPECT_TRUE(r.trigger(*parse_chord("Ctrl+W")));
  EXPECT_TRUE(r.trigger(*parse_chord("Shift+F")));
  EXPECT_EQ(frame.last->shift, true);
  EXPECT_FALSE(r.trigger(*parse_chord("Ctrl+Q")));  // unbound
  EXPECT_TRUE(r.run("face.scheme.gb"));
  EXPECT_FALSE(scheme.last);  // from a menu: no key
  EXPECT_FALSE(r.run("no.such"));

  ASSERT_EQ(r.for_context(ContextTarget::Face).size(), 1u);
  EXPECT_TRUE(r.for_context(ContextTarget::Empty).empty());
  // One menu's actions come together, whatever their place in the table.
  Action del = counting("edit.delete", "Edit", close), ren = counting("edit.rename", "Edit", close);
  Action top = counting("view.top", "View", frame);
  del.context = ren.context = top.context = context_bit(ContextTarget::Face);
  r.add(std::move(del));
  r.add(std::move(top));
  r.add(std::move(ren));
  std::vector<std::string> ids;
  for (const Action* a : r.for_context(ContextTarget::Face)) ids.push_back(a->id);
  EXPECT_EQ(ids,
            (std::vector<std::string>{"face.scheme.gb", "edit.delete", "edit.rename", "view.top"}));
  EXPECT_TRUE(r.conflicts().empty());
  r.add(counting("other.save", "Other", save, {*parse_chord("Ctrl+S")}));
  ASSERT_EQ(r.conflicts().size(), 1u);
  EXPECT_EQ(r.conflicts()[0], "Ctrl+S: file.save, other.save");
}

TEST(EditorActions, HelpListsEveryKeyThenTheMouseThenTheMenuOnlyCommands) {
  ActionRegistry r;
  Counter c;
  Action a = counting("view.frame", "View", c, {*parse_chord("F"), *parse_chord("Shift+F")});
  a.help = "frame all / selection";
  r.add(std::move(a));
  r.add(counting("file.export", "File/Mesh", c));  // no key: listed by its menu place
  r.add(counting("hidden", "", c));                // neither key nor menu: not a command
  Action nudge = counting("edit.nudge", "", c, {*parse_chord("Left")});
  nudge.keys_text = "Arrows";
  r.add(std::move(nudge));
  const auto rows = help_rows(r, {{"Wheel", "zoom"}});
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0].keys, "F, Shift+F");
  EXPECT_EQ(rows[0].what, "frame all / selection");
  EXPECT_EQ(rows[1].keys, "Arrows");
  EXPECT_EQ(rows[1].what, "edit.nudge");
  EXPECT_EQ(rows[2].keys, "Wheel");
  EXPECT_EQ(rows[3].keys, "File menu");
  EXPECT_EQ(rows[3].what, "Mesh > file.export");
}

TEST(EditorActions, AKeyWhoseActionDoesNotApplySaysWhy) {
  ActionRegistry r;
  int runs = 0;
  Action del = make_action("edit.delete", "Edit", "Delete", {"Del"}, "", [&] { ++runs; });
  bool selected = false;
  del.enabled = [&] { return selected; };
  del.why_disabled = [] { return std::string("nothing selected"); };
  r.add(std::move(del));
  Action other = make_action("view.other", "View", "Other", {"D"}, "", [&] { ++runs; });
  other.enabled = [] { return false; };
  r.add(std::move(other));

  std::vector<std::string> said;
  const auto say = [&](const std::string& m) { said.push_back(m); };
  EXPECT_FALSE(r.trigger(*parse_chord("Del"), say));
  EXPECT_FALSE(r.trigger(*parse_chord("D"), say));
  EXPECT_FALSE(r.trigger(*parse_chord("Ctrl+D"), say)) << "bound to nothing: nothing said";
  EXPECT_EQ(said,
            (std::vector<std::string>{"Delete: nothing selected", "Other: not available now"}));
  EXPECT_EQ(r.disabled_reason(*r.find("edit.delete")), "nothing selected");
  EXPECT_EQ(runs, 0);
  selected = true;
  EXPECT_TRUE(r.trigger(*parse_chord("Del"), say));
  EXPECT_EQ(runs, 1);
  EXPECT_EQ(said.size(), 2u) << "an action that runs says nothing here";
}

}  // namespace
}  // namespace pl
