#include "app/editor/logic/selection_actions.hpp"

#include <algorithm>

#include "app/document/network_commands.hpp"
#include "app/editor/logic/command_sequence.hpp"
#include "app/editor/logic/selection_properties.hpp"
#include "app/editor/logic/tool.hpp"
#include "core/scene/network_edit.hpp"

namespace pl {

namespace {

using Kind = SelectionItem::Kind;

std::vector<int> existing(const Scene& scene, const Selection& selection, Kind kind) {
  std::vector<int> r;
  for (int i : selection.of_kind(kind)) {
    const SelectionItem item = kind == Kind::Edge   ? SelectionItem::edge(i)
                               : kind == Kind::Face ? SelectionItem::face(i)
                                                    : SelectionItem::patch(i);
    if (item_exists(scene, item)) r.push_back(i);
  }
  return r;
}

void add_scheme_action(ActionRegistry& actions, Document& doc, Selection& selection, const Say& say,
                       FaceScheme scheme, const std::string& help) {
  const std::string name = scheme_name(scheme);
  const std::string id = "face.scheme." + scheme_keyword(scheme);
  Action a = make_action(id, "Face/Scheme", name, {}, help, nullptr);
  a.context = context_bit(ContextTarget::Face);
  // Gregory fills only triangles and quads: offered when every selected face is one.
  a.enabled = [&doc, &selection, scheme] {
    const std::vector<int> faces = existing(doc.scene(), selection, Kind::Face);
    if (faces.empty()) return false;
    if (scheme != FaceScheme::Gregory) return true;
    return std::all_of(faces.begin(), faces.end(),
                       [&](int f) { return face_properties(doc.scene(), f)->gregory_allowed; });
  };
  a.checked = [&doc, &selection, scheme] {
    const std::vector<int> faces = existing(doc.scene(), selection, Kind::Face);
    return !faces.empty() && std::all_of(faces.begin(), faces.end(), [&](int f) {
      return doc.scene().network->faces[f].scheme == scheme;
    });
  };
  a.run = [&doc, &selection, say, scheme, name](const std::optional<KeyChord>&) {
    std::vector<std::unique_ptr<Command>> changes;
    std::string faces;
    for (int f : existing(doc.scene(), selection, Kind::Face))
      if (doc.scene().network->faces[f].scheme != scheme) {
        changes.push_back(std::make_unique<SetFaceSchemeCommand>(f, scheme));
        faces += (faces.empty() ? "" : ", ") + std::to_string(f);
      }
    if (changes.empty()) return;  // nothing would change: no undo step
    run_command(doc, say,
                as_one_step("set scheme " + name + " on faces " + faces, std::move(changes)));
  };
  actions.add(std::move(a));
}

}  // namespace

void add_selection_actions(ActionRegistry& actions, Document& doc, Selection& selection,
                           const Say& say) {
  auto has = [&doc, &selection](Kind kind) {
    return [&doc, &selection, kind] {
      for (const SelectionItem& i : selection.items())
        if (i.kind == kind && item_exists(doc.scene(), i)) return true;
      return false;
    };
  };

  // An action that replaces the selection with objects related to it.
  auto select = [&](std::string id, std::string label, std::string help, ContextSet context,
                    std::function<bool()> enabled,
                    std::function<std::vector<SelectionItem>()> related) {
    Action a = make_action(std::move(id), "Select", std::move(label), {}, std::move(help),
                           [&selection, related] { selection.set(related()); });
    a.context = context;
    a.enabled = std::move(enabled);
    return a;
  };

  Action all =
      select("select.all", "All Points", "select every network vertex and explicit patch point",
             context_bit(ContextTarget::Empty), nullptr, [&doc] {
               std::vector<SelectionItem> items;
               const Scene& s = doc.scene();
               if (s.network)
                 for (std::size_t v = 0; v < s.network->vertices.size(); ++v)
                   items.push_back(SelectionItem::of_point(PointRef::vertex(int(v))));
               for (std::size_t p = 0; p < s.patches.size(); ++p)
                 for (std::size_t k = 0; k < s.patches[p].patch->size(); ++k)
                   items.push_back(SelectionItem::of_point(PointRef::patch_point(int(p), int(k))));
               return items;
             });
  all.keys = {*parse_chord("Ctrl+A")};
  actions.add(std::move(all));

  actions.add(select(
      "select.points_of", "Points of Selection",
      "select the editable points of the selected faces, edges, patches and curves",
      context_bit(ContextTarget::Face) | context_bit(ContextTarget::Edge) |
          context_bit(ContextTarget::Patch) | context_bit(ContextTarget::Curve),
      [has] {
        return has(Kind::Face)() || has(Kind::Edge)() || has(Kind::Patch)() || has(Kind::Curve)();
      },
      [&doc, &selection] {
        std::vector<SelectionItem> items;
        for (const PointRef& p : points_of(doc.scene(), selection))
          items.push_back(SelectionItem::of_point(p));
        return items;
      }));

  actions.add(select("select.face_edges", "Edges of Faces",
                     "select the edges around the selected faces", context_bit(ContextTarget::Face),
                     has(Kind::Face), [&doc, &selection] {
                       std::vector<SelectionItem> items;
                       const auto faces = existing(doc.scene(), selection, Kind::Face);
                       for (const std::vector<int>& sides : face_edges(*doc.scene().network, faces))
                         for (int e : sides)
                           if (e >= 0) items.push_back(SelectionItem::edge(e));
                       return items;
                     }));

  actions.add(select("select.edge_faces", "Faces of Edges",
                     "select the faces on either side of the selected edges",
                     context_bit(ContextTarget::Edge), has(Kind::Edge), [&doc, &selection] {
                       std::vector<SelectionItem> items;
                       for (int e : existing(doc.scene(), selection, Kind::Edge)) {
                         const std::optional<EdgeProperties> p = edge_properties(doc.scene(), e);
                         for (int f : p->faces) items.push_back(SelectionItem::face(f));
                       }
                       return items;
                     }));

  add_scheme_action(actions, doc, selection, say, FaceScheme::Auto,
                    "fill the selected faces by their side count (Gregory for 3 and 4 sides)");
  add_scheme_action(actions, doc, selection, say, FaceScheme::Gregory,
                    "fill the selected faces with Gregory patches");
  add_scheme_action(actions, doc, selection, say, FaceScheme::GB,
                    "fill the selected faces with Generalized Bezier patches");
  for (FaceScheme s : all_face_schemes())
    if (is_ribbon_scheme(s))
      add_scheme_action(actions, doc, selection, say, s,
                        "fill the selected faces with the " + scheme_keyword(s) +
                            " transfinite scheme (convex faces)");
}

}  // namespace pl
