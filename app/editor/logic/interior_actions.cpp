#include "app/editor/logic/interior_actions.hpp"

#include "app/document/interior_commands.hpp"
#include "app/editor/logic/tool.hpp"
#include "core/network/gb_face_free_points.hpp"

namespace pl {

std::optional<int> interior_face(const Scene& scene, const Selection& selection) {
  std::optional<int> face, point_face;
  int faces = 0;
  for (const SelectionItem& i : selection.items()) {
    if (!item_exists(scene, i)) continue;
    if (i.kind == SelectionItem::Kind::Face) {
      ++faces;
      face = i.index;
    }
    if (!point_face && i.kind == SelectionItem::Kind::Point &&
        i.point.kind == PointRef::Kind::FreePoint)
      point_face = i.point.object;
  }
  if (faces == 1) return face;
  if (faces == 0) return point_face;
  return std::nullopt;
}

std::optional<InteriorSummary> interior_summary(const Scene& scene, int face) {
  if (!scene.network || face < 0 || face >= int(scene.network->faces.size())) return std::nullopt;
  const NetworkFace& f = scene.network->faces[face];
  InteriorSummary s;
  s.face = face;
  s.why_not = no_interior_reason(scene, face);
  s.has_interior = s.why_not.empty();
  if (!s.has_interior) return s;
  s.degree = f.degree;
  s.free_points = int(gb_face_free_point_names(int(f.loop.size()), f.degree).size());
  s.moved = int(f.offsets.size());  // one entry per point (the reader and with_offset keep it so)
  return s;
}

namespace {

void add_interior_action(ActionRegistry& actions, Document& doc, Selection& selection,
                         const Say& say, const std::string& id, const std::string& label,
                         const std::string& help,
                         std::function<bool(const InteriorSummary&)> enabled,
                         std::function<std::shared_ptr<Command>(const InteriorSummary&)> command) {
  Action a = make_action(id, "Face", label, {}, help, nullptr);
  a.context = context_bit(ContextTarget::Face) | context_bit(ContextTarget::Point);
  const auto summary = [&doc, &selection]() -> std::optional<InteriorSummary> {
    const std::optional<int> f = interior_face(doc.scene(), selection);
    if (!f) return std::nullopt;
    return interior_summary(doc.scene(), *f);
  };
  a.enabled = [summary, enabled] {
    const auto s = summary();
    return s && s->has_interior && enabled(*s);
  };
  a.run = [&doc, summary, say, command](const std::optional<KeyChord>&) {
    const auto s = summary();
    if (!s) return;
    if (!s->has_interior) {
      if (say) say(s->why_not);
      return;
    }
    run_command(doc, say, command(*s));
  };
  actions.add(std::move(a));
}

}  // namespace

void add_interior_actions(ActionRegistry& actions, Document& doc, Selection& selection, Say say) {
  add_interior_action(
      actions, doc, selection, say, "face.degree.raise", "Raise Degree",
      "raise the selected GB face's degree by one: more free interior points, the boundary and its "
      "G1 data unchanged",
      [](const InteriorSummary& s) { return s.degree < kMaxGBFaceDegree; },
      [](const InteriorSummary& s) {
        return std::make_shared<SetFaceDegreeCommand>(s.face, s.degree + 1);
      });
  add_interior_action(
      actions, doc, selection, say, "face.degree.lower", "Lower Degree",
      "lower the selected GB face's degree by one (its moved points re-fitted)",
      [](const InteriorSummary& s) { return s.degree > 3; },
      [](const InteriorSummary& s) {
        return std::make_shared<SetFaceDegreeCommand>(s.face, s.degree - 1);
      });
  add_interior_action(
      actions, doc, selection, say, "face.interior.reset", "Reset Interior",
      "put every free interior point of the selected GB face back at its default",
      [](const InteriorSummary& s) { return s.moved > 0; },
      [](const InteriorSummary& s) { return std::make_shared<ResetInteriorCommand>(s.face); });
}

}  // namespace pl
