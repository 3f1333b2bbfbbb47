// The Selection section: the properties of a single selected object (face: sides, scheme,
// name; edge: name, ends, length, faces; vertex: tangent plane fitted or fixed; patch: type),
// or a summary of several, and typed coordinates for the selected points.
#include <imgui.h>

#include <cmath>

#include "app/editor/logic/selection_properties.hpp"
#include "app/editor/side_panel.hpp"

namespace pl {

namespace {

using Kind = SelectionItem::Kind;

const char* or_none(const std::string& s) {
  return s.empty() ? "(no name)" : s.c_str();
}

// A row "label  value" with the value in the widget column.
void field(const char* label, const std::string& value) {
  ImGui::TextDisabled("%s", label);
  ImGui::SameLine(ImGui::GetFontSize() * 6);
  ImGui::TextUnformatted(value.c_str());
}

std::string fmt(const char* format, double a) {
  char b[64];
  std::snprintf(b, sizeof b, format, a);
  return b;
}

// The scheme of the selected faces through its actions: one undo step, Gregory offered for 3 and
// 4 sides only, the current one checked when all selected faces share it.
void scheme_row(const SidePanel& p) {
  ImGui::TextDisabled("scheme");
  ImGui::SameLine(ImGui::GetFontSize() * 6);
  for (const char* id : {"face.scheme.auto", "face.scheme.gregory", "face.scheme.gb"}) {
    const Action* a = p.actions.find(id);
    if (!a) continue;
    ImGui::BeginDisabled(!p.actions.is_enabled(*a));
    if (ImGui::RadioButton(a->label.c_str(), a->checked && a->checked())) p.actions.run(id);
    ImGui::EndDisabled();
    ImGui::SameLine();
  }
  ImGui::NewLine();
}

void face_section(const SidePanel& p, const FaceProperties& f) {
  field("name", or_none(f.name));
  field("sides", std::to_string(f.sides));
  scheme_row(p);
  if (f.scheme == FaceScheme::Auto) field("filled as", scheme_name(f.resolved));
}

void edge_section(const EdgeProperties& e) {
  field("name", or_none(e.name));
  field("vertices", std::to_string(e.from) + " -> " + std::to_string(e.to));
  field("length", fmt("%.6g", e.length));
  std::string faces;
  for (int f : e.faces) faces += (faces.empty() ? "" : ", ") + std::to_string(f);
  field("faces", faces.empty() ? "none (a boundary of nothing)" : faces);
}

void vertex_section(const VertexProperties& v) {
  field("edges", std::to_string(v.edges));
  if (v.tangent_plane_fixed) {
    const Vec3 n = *v.normal;
    char b[96];
    std::snprintf(b, sizeof b, "fixed, normal %.4g %.4g %.4g", n.x, n.y, n.z);
    field("tangent", b);
  } else {
    field("tangent", "fitted to the edges");
  }
}

void patch_section(const PatchProperties& q) {
  field("name", or_none(q.name));
  field("type", q.type);
  field("points", std::to_string(q.points));
}

// Typed coordinates of the selected points' centre: applied as one command when the field is
// left or Enter pressed.
void coordinates(const SidePanel& p, const std::vector<PointRef>& points) {
  const Scene& scene = p.doc.scene();
  Vec3 centre(0);
  for (const PointRef& r : points) centre += point_position(scene, r);
  centre /= double(points.size());
  static double edit[3];
  static bool editing = false;
  if (!editing) edit[0] = centre.x, edit[1] = centre.y, edit[2] = centre.z;
  ImGui::SetNextItemWidth(-1);
  ImGui::InputScalarN("##xyz", ImGuiDataType_Double, edit, 3, nullptr, nullptr, "%.6g");
  editing = ImGui::IsItemActive();
  if (ImGui::IsItemDeactivatedAfterEdit()) {
    const Vec3 d = Vec3(edit[0], edit[1], edit[2]) - centre;
    if (std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z) && d != Vec3(0)) {
      std::vector<Vec3> positions;
      for (const PointRef& r : points) positions.push_back(point_position(scene, r) + d);
      p.doc.execute(std::make_unique<MovePointsCommand>(points, positions));
    }
  }
}

}  // namespace

void draw_selection_section(const SidePanel& p) {
  const Scene& scene = p.doc.scene();
  std::vector<SelectionItem> present;
  for (const SelectionItem& i : p.selection.items())
    if (item_exists(scene, i)) present.push_back(i);
  if (present.empty()) {
    ImGui::TextDisabled("Click a point, curve or surface to select it;");
    ImGui::TextDisabled("Shift-click adds, Ctrl-click toggles.");
    ImGui::TextDisabled("Right-click for what can be done there.");
    return;
  }
  std::vector<PointRef> points;
  for (const SelectionItem& i : present)
    if (i.kind == Kind::Point) points.push_back(i.point);

  if (present.size() == 1) {
    const SelectionItem& i = present[0];
    ImGui::Text("%s", describe(i).c_str());
    if (i.kind == Kind::Face) face_section(p, *face_properties(scene, i.index));
    if (i.kind == Kind::Edge) edge_section(*edge_properties(scene, i.index));
    if (i.kind == Kind::Patch) patch_section(*patch_properties(scene, i.index));
    if (i.kind == Kind::Point && i.point.kind == PointRef::Kind::NetworkVertex)
      vertex_section(*vertex_properties(scene, i.point.index));
  } else {
    int counts[4] = {0, 0, 0, 0};
    for (const SelectionItem& i : present) ++counts[int(i.kind)];
    static const char* names[4] = {"points", "edges", "faces", "patches"};
    std::string summary;
    for (int k = 0; k < 4; ++k)
      if (counts[k])
        summary += (summary.empty() ? "" : ", ") + std::to_string(counts[k]) + " " + names[k];
    ImGui::Text("%s", summary.c_str());
    if (counts[int(Kind::Face)] > 0) scheme_row(p);
  }
  if (!points.empty()) {
    if (points.size() > 1) ImGui::TextDisabled("%zu points (centre shown)", points.size());
    coordinates(p, points);
    ImGui::TextDisabled("Drag in the view; hold X/Y/Z for an axis.");
    ImGui::TextDisabled("Arrows nudge (Shift x10, Alt x0.1).");
  }
}

}  // namespace pl
