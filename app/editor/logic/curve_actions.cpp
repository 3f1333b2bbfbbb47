#include "app/editor/logic/curve_actions.hpp"

#include <algorithm>
#include <limits>

#include "app/document/curve_commands.hpp"
#include "app/document/curves_to_edges_command.hpp"
#include "app/editor/logic/tool.hpp"
#include "render/draw_scene_builder.hpp"

namespace pl {

std::optional<int> selected_curve(const Scene& scene, const Selection& selection) {
  const std::vector<int> curves = curves_of_selection(scene, selection);
  return curves.empty() ? std::nullopt : std::optional<int>(curves.front());
}

double nearest_curve_parameter(const SceneCurve& curve, const Vec3& at) {
  double best_t = curve.t_min(), best = std::numeric_limits<double>::infinity();
  for (double t : curve_sample_parameters(curve, 4 * free_curve_samples_per_span(curve))) {
    const double d = glm::length(evaluate(curve, t).p - at);
    if (d < best) best = d, best_t = t;
  }
  return best_t;
}

double default_knot_parameter(const SceneCurve& curve) {
  double a = curve.t_min(), b = curve.t_max();
  for (const auto& [s0, s1] : curve_spans(curve))
    if (s1 - s0 > b - a || (a == curve.t_min() && b == curve.t_max())) a = s0, b = s1;
  return 0.5 * (a + b);
}

void add_curve_actions(ActionRegistry& r, Document& doc, Selection& selection,
                       CurveActionHooks hooks) {
  using Op = CurveOperationCommand::Operation;
  // The parameter an insertion or split acts at: where the menu was opened, else the default.
  auto parameter = [&doc, hooks](int c) {
    const SceneCurve& curve = doc.scene().curves[c];
    if (const auto at = hooks.menu_point()) return nearest_curve_parameter(curve, *at);
    return default_knot_parameter(curve);
  };
  const struct {
    const char* id;
    const char* label;
    const char* help;
    Op op;
    bool at_parameter;
  } entries[] = {
      {"curve.insert_knot", "Insert Knot", "a knot where the menu was opened (the curve stays)",
       Op::InsertKnot, true},
      {"curve.elevate", "Elevate Degree", "one degree more (the curve stays)", Op::ElevateDegree,
       false},
      {"curve.split", "Split Curve", "two curves, split where the menu was opened", Op::Split,
       true},
      {"curve.reverse", "Reverse Curve", "the same curve run the other way", Op::Reverse, false},
  };
  for (const auto& e : entries) {
    Action a =
        make_action(e.id, "Curve", e.label, {}, e.help, [&doc, &selection, hooks, e, parameter] {
          const auto c = selected_curve(doc.scene(), selection);
          if (!c) return;
          const double t = e.at_parameter ? parameter(*c) : 0.0;
          run_command(doc, hooks.say, std::make_shared<CurveOperationCommand>(*c, e.op, t));
        });
    a.context = context_bit(ContextTarget::Point) | context_bit(ContextTarget::Curve) |
                context_bit(ContextTarget::Empty);
    a.enabled = [&doc, &selection] { return selected_curve(doc.scene(), selection).has_value(); };
    r.add(std::move(a));
  }
  // Every selected curve at once, so that curves drawn to meet become one connected chain; the
  // new edges are selected (Make Face then takes them as they are).
  Action to_edges = make_action(
      "curve.to_edges", "Curve", "To Network Edges", {},
      "the selected curves become network edges (cubic spans: exact for a cubic, else fitted "
      "within 1e-4 of their size); ends meeting vertices connect to them",
      [&doc, &selection, hooks] {
        const std::vector<int> curves = curves_of_selection(doc.scene(), selection);
        if (curves.empty()) return;
        const auto command = std::make_shared<CurvesToEdgesCommand>(curves);
        if (!run_command(doc, hooks.say, command)) return;
        std::vector<SelectionItem> edges;
        for (int e : command->edges()) edges.push_back(SelectionItem::edge(e));
        selection.set(std::move(edges));
      });
  to_edges.context = context_bit(ContextTarget::Point) | context_bit(ContextTarget::Curve) |
                     context_bit(ContextTarget::Empty);
  to_edges.enabled = [&doc, &selection] {
    return selected_curve(doc.scene(), selection).has_value();
  };
  r.add(std::move(to_edges));
}

std::vector<int> curves_of_selection(const Scene& scene, const Selection& selection) {
  std::vector<int> out;
  for (const SelectionItem& i : selection.items()) {
    int c = -1;
    if (i.kind == SelectionItem::Kind::Curve && item_exists(scene, i)) c = i.index;
    if (i.kind == SelectionItem::Kind::Point && i.point.kind == PointRef::Kind::CurvePoint &&
        point_exists(scene, i.point))
      c = i.point.object;
    if (c >= 0 && std::find(out.begin(), out.end(), c) == out.end()) out.push_back(c);
  }
  return out;
}

}  // namespace pl
