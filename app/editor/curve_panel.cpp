// The Selection section of a free curve (shown when the curve or one of its points is selected):
// its type, degree, point count and parameter range, the selected point's weight (typed: a B-spline
// becomes a NURBS curve), and the curve operations at a typed parameter t. Every change is one
// command (one undo step); a refusal shows in the status bar.
#include <imgui.h>

#include <cstdio>

#include "app/document/curve_commands.hpp"
#include "app/editor/logic/curve_actions.hpp"
#include "app/editor/side_panel.hpp"

namespace pl {

namespace {

void row(const char* label, const std::string& value) {
  ImGui::TextDisabled("%s", label);
  ImGui::SameLine(ImGui::GetFontSize() * 6);
  ImGui::TextUnformatted(value.c_str());
}

std::string number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

void run(const SidePanel& p, std::shared_ptr<Command> c) {
  if (p.tool_context)
    run_command(*p.tool_context, std::move(c));
  else
    run_command(p.model.doc(), {}, std::move(c));
}

}  // namespace

void draw_curve_section(const SidePanel& p, int c, int point) {
  const SceneCurve& curve = p.model.doc().scene().curves.at(c);
  ImGui::Separator();
  ImGui::Text("%s", curve_name(curve, c).c_str());
  row("type", std::string(curve_type_name(curve.type)));
  row("degree", std::to_string(curve_degree(curve)));
  row("points", std::to_string(curve.points.size()));
  row("t range", number(curve.t_min()) + " .. " + number(curve.t_max()));
  if (point >= 0 && (curve.type == CurveType::BSpline || curve.type == CurveType::Nurbs)) {
    const double w = curve.weights.empty() ? 1.0 : curve.weights.at(point);
    static double edit = 1;
    static std::string editing;
    const std::string key = std::to_string(c) + ":" + std::to_string(point);
    if (editing != key) edit = w;
    ImGui::TextDisabled("weight");
    ImGui::SameLine(ImGui::GetFontSize() * 6);
    ImGui::SetNextItemWidth(-1);
    ImGui::InputDouble("##weight", &edit, 0, 0, "%.6g");
    editing = ImGui::IsItemActive() ? key : std::string();
    if (ImGui::IsItemDeactivatedAfterEdit() && edit != w)
      run(p, std::make_shared<SetCurveWeightCommand>(c, point, edit));
  }
  // The parameter of the operations: kept per curve until the curve changes its range.
  static double t = 0;
  static int t_curve = -1;
  if (t_curve != c || !(t > curve.t_min() && t < curve.t_max())) {
    t = default_knot_parameter(curve);
    t_curve = c;
  }
  ImGui::TextDisabled("at t");
  ImGui::SameLine(ImGui::GetFontSize() * 6);
  ImGui::SetNextItemWidth(-1);
  ImGui::InputDouble("##curve_t", &t, 0, 0, "%.6g");
  using Op = CurveOperationCommand::Operation;
  if (ImGui::Button("Insert Knot"))
    run(p, std::make_shared<CurveOperationCommand>(c, Op::InsertKnot, t));
  ImGui::SameLine();
  if (ImGui::Button("Split")) run(p, std::make_shared<CurveOperationCommand>(c, Op::Split, t));
  if (ImGui::Button("Elevate Degree"))
    run(p, std::make_shared<CurveOperationCommand>(c, Op::ElevateDegree));
  ImGui::SameLine();
  if (ImGui::Button("Reverse")) run(p, std::make_shared<CurveOperationCommand>(c, Op::Reverse));
}

}  // namespace pl
