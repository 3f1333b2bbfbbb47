// The Transform rows of the Selection section: rotate, scale or move the selected points by
// typed values about a pivot (the selection's centre, a selected vertex, the origin or the work
// plane's point), one undo step each; Enter in a field or its button applies it. The work is
// GUI-free (logic/transform_selection.hpp).
#include <imgui.h>

#include "app/editor/logic/transform_selection.hpp"
#include "app/editor/side_panel.hpp"

namespace pl {

namespace {

struct TransformFields {
  int pivot = 0;  // PivotKind
  int axis = 2;   // AxisKind
  double angle = 90, factor = 2, offset[3] = {0, 0, 0};
};

// The first selected network vertex: the pivot "vertex" turns about.
int first_vertex(const Selection& selection) {
  for (const SelectionItem& i : selection.items())
    if (i.kind == SelectionItem::Kind::Point && i.point.kind == PointRef::Kind::NetworkVertex)
      return i.point.index;
  return -1;
}

}  // namespace

void draw_transform_section(const SidePanel& p) {
  static TransformFields f;
  const float label = ImGui::GetFontSize() * 6, button = ImGui::GetFontSize() * 4.5f;
  const int vertex = first_vertex(p.model.selection());
  const std::string vertex_item = vertex >= 0 ? "vertex " + std::to_string(vertex) : "a vertex";
  const char* pivots[] = {"selection centre", vertex_item.c_str(), "origin", "work plane point"};
  ImGui::TextDisabled("pivot");
  ImGui::SameLine(label);
  ImGui::SetNextItemWidth(-1);
  ImGui::Combo("##pivot", &f.pivot, pivots, 4);

  TransformRequest r;
  r.pivot = static_cast<PivotKind>(f.pivot);
  r.pivot_vertex = vertex;
  bool apply = false;

  ImGui::TextDisabled("rotate");
  ImGui::SameLine(label);
  const char* axes[] = {"X", "Y", "Z", "plane"};
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 4);
  ImGui::Combo("##axis", &f.axis, axes, 4);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-button);
  const bool rotate_enter = ImGui::InputDouble("##angle", &f.angle, 0, 0, "%.6g deg",
                                               ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  if (ImGui::Button("Rotate", ImVec2(-1, 0)) || rotate_enter) {
    r.kind = TransformKind::Rotate, r.axis = static_cast<AxisKind>(f.axis);
    r.angle_deg = f.angle, apply = true;
  }

  ImGui::TextDisabled("scale");
  ImGui::SameLine(label);
  ImGui::SetNextItemWidth(-button);
  const bool scale_enter = ImGui::InputDouble("##factor", &f.factor, 0, 0, "x %.6g",
                                              ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  if (ImGui::Button("Scale", ImVec2(-1, 0)) || scale_enter) {
    r.kind = TransformKind::Scale, r.factor = f.factor, apply = true;
  }

  ImGui::TextDisabled("move by");
  ImGui::SameLine(label);
  ImGui::SetNextItemWidth(-button);
  const bool move_enter =
      ImGui::InputScalarN("##offset", ImGuiDataType_Double, f.offset, 3, nullptr, nullptr, "%.6g",
                          ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  if (ImGui::Button("Move", ImVec2(-1, 0)) || move_enter) {
    r.kind = TransformKind::Move, r.offset = Vec3(f.offset[0], f.offset[1], f.offset[2]);
    apply = true;
  }
  if (apply) transform_selection(p.model, r);
}

}  // namespace pl
