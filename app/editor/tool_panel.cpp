// The active tool's fields in the side panel, below the tool buttons: typed coordinates for a
// new vertex (Enter in them or the button adds it), the chain a face is being made of with its
// Finish button. ImGui code; what the fields do is the tools'.
#include <imgui.h>

#include <cmath>

#include "app/editor/logic/add_edge_tool.hpp"
#include "app/editor/logic/add_vertex_tool.hpp"
#include "app/editor/logic/make_face_tool.hpp"
#include "app/editor/logic/new_curve_tool.hpp"
#include "app/editor/side_panel.hpp"

namespace pl {

namespace {

std::string list(const std::vector<int>& xs) {
  std::string s;
  for (int x : xs) s += (s.empty() ? "" : ", ") + std::to_string(x);
  return s;
}

void vertex_options(AddVertexTool& tool, ToolContext& ctx, const SidePanel& p) {
  // Starts at the work plane's origin: where a typed vertex most often goes.
  static double xyz[3] = {0, 0, 0};
  const char* add = "Add vertex";
  ImGui::SetNextItemWidth(-(ImGui::CalcTextSize(add).x + 2 * ImGui::GetStyle().FramePadding.x +
                            ImGui::GetStyle().ItemSpacing.x));
  // The fields take a value as it is typed (a click on the button after typing uses it).
  ImGui::InputScalarN("##new_vertex", ImGuiDataType_Double, xyz, 3, nullptr, nullptr, "%.6g");
  // Enter in a field adds the vertex, as the button does: a field lets go of the keyboard on
  // Enter (the editor's shortcuts, Enter's Finish among them, wait while a field has it).
  const bool entered =
      ImGui::IsItemDeactivated() && (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter)) ||
                                     ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_KeyPadEnter)));
  if (p.item_probe) {
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    p.item_probe("New vertex fields", lo.x, lo.y, hi.x, hi.y);
  }
  ImGui::SameLine();
  if (ImGui::Button(add) || entered) tool.add_at(ctx, Vec3(xyz[0], xyz[1], xyz[2]));
}

// The type of the new curve (one radio button each) and the points clicked so far.
void curve_options(NewCurveTool& tool, ToolContext& ctx) {
  for (CurveType t : {CurveType::BSpline, CurveType::Nurbs, CurveType::Bezier,
                      CurveType::Interpolating, CurveType::Hermite}) {
    const std::string label(curve_type_name(t));
    if (ImGui::RadioButton(label.c_str(), tool.type() == t)) tool.set_type(t);
    if (t != CurveType::Bezier && t != CurveType::Hermite) ImGui::SameLine();
  }
  ImGui::Text("%zu points", tool.points().size());
  ImGui::BeginDisabled(!tool.can_finish(ctx));
  if (ImGui::Button("Make curve  (Enter)")) tool.finish(ctx);
  ImGui::EndDisabled();
}

}  // namespace

void draw_tool_options(const SidePanel& p) {
  if (!p.tool_context) return;
  ToolContext& ctx = *p.tool_context;
  Tool& tool = p.model.tools().active();
  if (auto* t = dynamic_cast<AddVertexTool*>(&tool)) vertex_options(*t, ctx, p);
  if (auto* t = dynamic_cast<AddEdgeTool*>(&tool); t && t->from() >= 0)
    ImGui::Text("next edge from vertex %d", t->from());
  if (auto* t = dynamic_cast<NewCurveTool*>(&tool)) curve_options(*t, ctx);
  if (auto* t = dynamic_cast<MakeFaceTool*>(&tool)) {
    if (!t->vertices().empty()) ImGui::TextWrapped("vertices %s", list(t->vertices()).c_str());
    if (!t->edges().empty()) ImGui::TextWrapped("edges %s", list(t->edges()).c_str());
    ImGui::BeginDisabled(!t->can_finish(ctx));
    if (ImGui::Button("Make face  (Enter)")) t->finish(ctx);
    ImGui::EndDisabled();
  }
}

}  // namespace pl
