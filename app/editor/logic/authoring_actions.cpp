#include "app/editor/logic/authoring_actions.hpp"

#include "app/document/curve_commands.hpp"
#include "app/document/network_commands.hpp"
#include "app/editor/logic/command_sequence.hpp"
#include "app/editor/logic/plane_handles.hpp"
#include "app/editor/logic/split_edge_tool.hpp"
#include "app/editor/logic/tool.hpp"

namespace pl {

namespace {

using Kind = SelectionItem::Kind;

constexpr ContextSet kOnElements = context_bit(ContextTarget::Point) |
                                   context_bit(ContextTarget::Edge) |
                                   context_bit(ContextTarget::Face);

bool has_fixed_normal(const Network& n, int v) {
  return !n.normals.empty() && n.normals[v].has_value();
}

// Why Delete has nothing to act on in `selection` (which holds no vertex, edge, face or curve).
std::string why_nothing_to_delete(const Scene& scene, const Selection& selection) {
  if (selection.empty())
    return "nothing selected (select vertices, edges, faces or free curves to delete)";
  bool curve_point = false;
  for (const PointRef& p : selection.points())
    curve_point |= p.kind == PointRef::Kind::CurvePoint && point_exists(scene, p);
  if (curve_point)
    return "a free curve's control points are not deleted one by one: click the curve's line "
           "to select the curve, then Delete removes it";
  return "Delete removes network vertices, edges, faces and free curves; the selection (" +
         describe(selection, 3) + ") holds none";
}

}  // namespace

std::vector<int> selected_curves(const Scene& scene, const Selection& selection) {
  std::vector<int> r;
  for (const SelectionItem& i : selection.items())
    if (i.kind == Kind::Curve && item_exists(scene, i)) r.push_back(i.index);
  return r;
}

SelectedElements selected_elements(const Scene& scene, const Selection& selection) {
  SelectedElements s;
  if (!scene.network) return s;
  for (const SelectionItem& i : selection.items()) {
    if (!item_exists(scene, i)) continue;
    if (i.kind == Kind::Point && i.point.kind == PointRef::Kind::NetworkVertex)
      s.vertices.push_back(i.point.index);
    if (i.kind == Kind::Edge) s.edges.push_back(i.index);
    if (i.kind == Kind::Face) s.faces.push_back(i.index);
  }
  return s;
}

void add_authoring_actions(ActionRegistry& actions, Document& doc, Selection& selection,
                           AuthoringHooks hooks) {
  const Say say = hooks.say;
  auto elements = [&doc, &selection] { return selected_elements(doc.scene(), selection); };

  Action del = make_action(
      "edit.delete", "Edit", "Delete", {"Del", "Backspace"},
      "delete the selected vertices (with their edges and faces), edges (with their faces), "
      "faces and free curves",
      [&doc, &selection, say, elements] {
        const SelectedElements s = elements();
        const std::vector<int> curves = selected_curves(doc.scene(), selection);
        // Network elements and curves go in one undo step; the network's renumbering is read
        // from its command afterwards.
        std::vector<std::unique_ptr<Command>> steps;
        const DeleteCommand* network = nullptr;
        if (!s.empty()) {
          auto c = std::make_unique<DeleteCommand>(s.vertices, s.edges, s.faces);
          network = c.get();
          steps.push_back(std::move(c));
        }
        const DeleteCurvesCommand* free_curves = nullptr;
        if (!curves.empty()) {
          auto c = std::make_unique<DeleteCurvesCommand>(curves);
          free_curves = c.get();
          steps.push_back(std::move(c));
        }
        if (steps.empty()) return;
        // Both kinds in one step: the label names what goes.
        std::string label;
        for (const SelectionItem& i : selection.items()) {
          const bool goes =
              i.kind == Kind::Curve || i.kind == Kind::Edge || i.kind == Kind::Face ||
              (i.kind == Kind::Point && i.point.kind == PointRef::Kind::NetworkVertex);
          if (goes && item_exists(doc.scene(), i))
            label += (label.empty() ? "delete " : ", ") + describe(i);
        }
        const std::shared_ptr<Command> command = as_one_step(label, std::move(steps));
        if (!run_command(doc, say, command)) return;
        if (network) selection.remap(network->removed());
        if (free_curves) selection.remap_curves(free_curves->removed());
        selection.adopt(doc.scene());
      });
  del.separator_before = true;
  del.context = kOnElements | context_bit(ContextTarget::Curve);
  del.enabled = [&doc, &selection, elements] {
    return !elements().empty() || !selected_curves(doc.scene(), selection).empty();
  };
  del.why_disabled = [&doc, &selection] { return why_nothing_to_delete(doc.scene(), selection); };
  actions.add(std::move(del));

  Action edge = make_action(
      "network.add_edge", "Network", "Add Edge", {"Shift+E"},
      "join the two selected vertices by an edge (the Add Edge tool, E, picks them in the view)",
      [&doc, &selection, say, elements] {
        const SelectedElements s = elements();
        const int e = int(doc.scene().network->edges.size());  // appended
        if (run_command(doc, say, std::make_shared<AddEdgeCommand>(s.vertices[0], s.vertices[1])))
          selection.set({SelectionItem::edge(e)});
      });
  edge.context = context_bit(ContextTarget::Point);
  edge.enabled = [elements] { return elements().vertices.size() == 2; };
  edge.why_disabled = [elements] {
    return "select exactly two vertices (" + std::to_string(elements().vertices.size()) +
           " selected)";
  };
  actions.add(std::move(edge));

  Action face = make_action(
      "network.make_face", "Network", "Make Face", {"Shift+M"},
      "a face on the selected vertices (in the order picked; missing edges are made) or on the "
      "selected closed chain of edges (the Make Face tool, M, picks them in the view)",
      [&doc, &selection, say, elements, towards = hooks.towards] {
        const SelectedElements s = elements();
        const int f = int(doc.scene().network->faces.size());  // appended
        std::shared_ptr<Command> c;
        if (s.vertices.size() >= 3)
          c = std::make_shared<MakeFaceCommand>(s.vertices, towards());
        else
          c = MakeFaceCommand::from_edges(s.edges, towards());
        if (run_command(doc, say, c)) selection.set({SelectionItem::face(f)});
      });
  face.context = context_bit(ContextTarget::Point) | context_bit(ContextTarget::Edge);
  face.enabled = [elements] {
    const SelectedElements s = elements();
    return s.vertices.size() >= 3 || (s.vertices.empty() && s.edges.size() >= 3);
  };
  face.why_disabled = [] {
    return std::string("select 3 or more vertices in order, or a closed chain of 3 or more edges");
  };
  actions.add(std::move(face));

  Action fill = make_action("network.fill_holes", "Network", "Fill Holes", {"Ctrl+Shift+F"},
                            "a face in every closed loop of boundary edges with 3 to 12 sides",
                            [&doc, &selection, say] {
                              const int first = int(doc.scene().network->faces.size());
                              if (!run_command(doc, say, std::make_shared<FillHolesCommand>()))
                                return;
                              std::vector<SelectionItem> made;
                              for (int f = first; f < int(doc.scene().network->faces.size()); ++f)
                                made.push_back(SelectionItem::face(f));
                              selection.set(made);
                            });
  fill.context = context_bit(ContextTarget::Empty) | context_bit(ContextTarget::Edge);
  fill.enabled = [&doc] { return doc.scene().network && !doc.scene().network->edges.empty(); };
  actions.add(std::move(fill));

  Action split = make_action(
      "network.split_edge", "Network", "Split Edge", {"Shift+K"},
      "split the selected edge in the middle, or where it was right-clicked (the Split Edge "
      "tool, K, splits where you click)",
      [&doc, &selection, say, elements, at = hooks.split_parameter] {
        const int e = elements().edges.front();
        split_edge_at(doc, selection, say, e, at(e).value_or(0.5));
      });
  split.context = context_bit(ContextTarget::Edge);
  split.enabled = [elements] {
    const SelectedElements s = elements();
    return s.edges.size() == 1 && s.vertices.empty() && s.faces.empty();
  };
  split.why_disabled = [] { return std::string("select exactly one edge and nothing else"); };
  actions.add(std::move(split));

  // Tangent planes of the selected vertices: fitted to the edges, or fixed (the normal stored;
  // it is then turned by the normal's knob in the view or typed in the Selection panel).
  auto planes = [&doc, &selection, say, elements](bool fix) {
    const Network& n = *doc.scene().network;
    std::vector<std::unique_ptr<Command>> changes;
    std::string which;
    for (int v : elements().vertices) {
      if (has_fixed_normal(n, v) == fix) continue;
      std::optional<Vec3> normal;
      if (fix) {
        const auto plane = vertex_plane(n, v);
        if (!plane) continue;  // no plane to fix
        normal = plane->normal;
      }
      changes.push_back(std::make_unique<SetVertexNormalCommand>(v, normal));
      which += (which.empty() ? "" : ", ") + std::to_string(v);
    }
    if (changes.empty()) return;
    run_command(
        doc, say,
        as_one_step(std::string(fix ? "fix" : "fit") + " the tangent planes of vertices " + which,
                    std::move(changes)));
  };
  auto can = [&doc, elements](bool fix) {
    return [&doc, elements, fix] {
      if (!doc.scene().network) return false;
      const Network& n = *doc.scene().network;
      for (int v : elements().vertices)
        if (has_fixed_normal(n, v) != fix && (!fix || vertex_plane(n, v))) return true;
      return false;
    };
  };
  auto all = [&doc, elements](bool fixed) {
    return [&doc, elements, fixed] {
      const std::vector<int> vs = elements().vertices;
      if (vs.empty()) return false;
      for (int v : vs)
        if (has_fixed_normal(*doc.scene().network, v) != fixed) return false;
      return true;
    };
  };
  Action fitted = make_action("network.plane_fitted", "Network/Tangent Plane", "Fitted", {},
                              "fit the selected vertices' tangent planes to their edges again",
                              [planes] { planes(false); });
  fitted.context = context_bit(ContextTarget::Point);
  fitted.enabled = can(false);
  fitted.checked = all(false);
  actions.add(std::move(fitted));
  Action fixed = make_action(
      "network.plane_fixed", "Network/Tangent Plane", "Fixed", {},
      "keep the selected vertices' tangent planes as they are now (then drag the normal's knob "
      "or type a normal)",
      [planes] { planes(true); });
  fixed.context = context_bit(ContextTarget::Point);
  fixed.enabled = can(true);
  fixed.checked = all(true);
  actions.add(std::move(fixed));
}

}  // namespace pl
