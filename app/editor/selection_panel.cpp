// The Selection section: the properties of a single selected object (face: sides, scheme,
// name, a GB face's interior: degree, moved points, reset; edge: name, ends, length, faces; vertex:
// tangent plane fitted or fixed, its normal; patch: type), or a summary of several, and typed
// coordinates for the selected points. Every field that changes the document runs a command (one
// undo step) when it is left or Enter is pressed; a refusal shows in the status bar.
#include <imgui.h>

#include <cmath>
#include <cstring>
#include <string>

#include "app/document/network_commands.hpp"
#include "app/editor/logic/interior_actions.hpp"
#include "app/editor/logic/plane_handles.hpp"
#include "app/editor/logic/selection_properties.hpp"
#include "app/editor/logic/transform_selection.hpp"
#include "app/editor/side_panel.hpp"
#include "core/scene/network_edit.hpp"

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
    const Action* a = p.model.actions().find(id);
    if (!a) continue;
    ImGui::BeginDisabled(!p.model.actions().is_enabled(*a));
    if (ImGui::RadioButton(a->label.c_str(), a->checked && a->checked())) p.model.actions().run(id);
    ImGui::EndDisabled();
    ImGui::SameLine();
  }
  ImGui::NewLine();
  // The ribbon-based transfinite schemes, too many for radio buttons: one combo, showing the one
  // all selected faces share.
  ImGui::TextDisabled("transfinite");
  ImGui::SameLine(ImGui::GetFontSize() * 6);
  std::string current = "-";
  for (FaceScheme s : all_face_schemes())
    if (const Action* a = is_ribbon_scheme(s)
                              ? p.model.actions().find("face.scheme." + scheme_keyword(s))
                              : nullptr;
        a && a->checked && a->checked())
      current = a->label;
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 11);
  if (ImGui::BeginCombo("##transfinite-scheme", current.c_str())) {
    for (FaceScheme s : all_face_schemes()) {
      if (!is_ribbon_scheme(s)) continue;
      const std::string id = "face.scheme." + scheme_keyword(s);
      const Action* a = p.model.actions().find(id);
      if (!a) continue;
      ImGui::BeginDisabled(!p.model.actions().is_enabled(*a));
      if (ImGui::Selectable(a->label.c_str(), a->checked && a->checked()))
        p.model.actions().run(id);
      ImGui::EndDisabled();
    }
    ImGui::EndCombo();
  }
}

// Runs a command from a panel field, its label or refusal going to the status bar.
void run(const SidePanel& p, std::shared_ptr<Command> c) {
  if (p.tool_context)
    run_command(*p.tool_context, std::move(c));
  else
    run_command(p.model.doc(), {}, std::move(c));
}

// An editable name: applied (one command) when the field is left or Enter pressed, and only
// when it changed. `key` tells objects apart, so a field being typed in is not refilled.
void name_field(const SidePanel& p, const std::string& name, const std::string& key,
                const std::function<std::shared_ptr<Command>(const std::string&)>& command) {
  static char edit[256];
  static std::string editing;  // the key of the object whose name is being typed
  if (editing != key) std::snprintf(edit, sizeof edit, "%s", name.c_str());
  ImGui::TextDisabled("name");
  ImGui::SameLine(ImGui::GetFontSize() * 6);
  ImGui::SetNextItemWidth(-1);
  ImGui::InputTextWithHint(("##name" + key).c_str(), "(no name)", edit, sizeof edit);
  editing = ImGui::IsItemActive() ? key : std::string();
  if (ImGui::IsItemDeactivatedAfterEdit() && name != edit) run(p, command(edit));
}

// A button running action `id` (disabled when the action is), reported to scripts by `label`.
void action_button(const SidePanel& p, const char* id, const char* label) {
  const Action* a = p.model.actions().find(id);
  if (!a) return;
  ImGui::BeginDisabled(!p.model.actions().is_enabled(*a));
  if (ImGui::Button(label)) p.model.actions().run(id);
  ImGui::EndDisabled();
  if (p.item_probe) {
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    p.item_probe(label, lo.x, lo.y, hi.x, hi.y);
  }
}

// The interior of face `face`: a GB face's degree (raised and lowered by buttons), how many of
// its free points are moved, Reset Interior; a Gregory face says why it has none.
void interior_section(const SidePanel& p, int face) {
  const std::optional<InteriorSummary> s = interior_summary(p.model.doc().scene(), face);
  if (!s) return;
  ImGui::Separator();
  if (!s->has_interior) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped(
        "Gregory faces have no free interior: all their inner points are G1 data (they follow "
        "the network).");
    ImGui::PopStyleColor();
    return;
  }
  ImGui::TextDisabled("degree");
  ImGui::SameLine(ImGui::GetFontSize() * 6);
  ImGui::Text("%d", s->degree);
  ImGui::SameLine();
  action_button(p, "face.degree.lower", "Lower degree");
  ImGui::SameLine();
  action_button(p, "face.degree.raise", "Raise degree");
  field("free points", std::to_string(s->free_points) + ", " + std::to_string(s->moved) + " moved");
  action_button(p, "face.interior.reset", "Reset interior");
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped(
      "Drag the pentagon points (the free points) in the view; the boundary and the G1 joins "
      "stay.");
  ImGui::PopStyleColor();
}

void face_section(const SidePanel& p, const FaceProperties& f) {
  name_field(p, f.name, "face" + std::to_string(f.face),
             [&](const std::string& n) { return std::make_shared<SetFaceNameCommand>(f.face, n); });
  field("sides", std::to_string(f.sides));
  scheme_row(p);
  if (f.scheme == FaceScheme::Auto) field("filled as", scheme_name(f.resolved));
  interior_section(p, f.face);
}

void edge_section(const SidePanel& p, const EdgeProperties& e) {
  name_field(p, e.name, "edge" + std::to_string(e.edge),
             [&](const std::string& n) { return std::make_shared<SetEdgeNameCommand>(e.edge, n); });
  field("vertices", std::to_string(e.from) + " -> " + std::to_string(e.to));
  field("length", fmt("%.6g", e.length));
  // Named as faces, so that "face 0" does not read as a count.
  std::string faces;
  for (int f : e.faces) faces += (faces.empty() ? "" : " and ") + std::to_string(f);
  field("faces", e.faces.empty()       ? "none (a boundary of nothing)"
                 : e.faces.size() == 1 ? "face " + faces
                                       : "faces " + faces);
}

// The vertex's tangent plane: fitted to its edges or fixed (through the Network > Tangent Plane
// actions, one undo step), and its normal, typed (fixes the plane, turning the handles with it).
void vertex_section(const SidePanel& p, const VertexProperties& v) {
  field("edges", std::to_string(v.edges));
  ImGui::TextDisabled("tangent");
  ImGui::SameLine(ImGui::GetFontSize() * 6);
  for (const char* id : {"network.plane_fitted", "network.plane_fixed"}) {
    const Action* a = p.model.actions().find(id);
    if (!a) continue;
    const bool on = a->checked && a->checked();
    ImGui::BeginDisabled(!on && !p.model.actions().is_enabled(*a));
    if (ImGui::RadioButton(a->label.c_str(), on) && !on) p.model.actions().run(id);
    ImGui::EndDisabled();
    ImGui::SameLine();
  }
  ImGui::NewLine();
  const auto plane = vertex_plane(*p.model.doc().scene().network, v.vertex);
  if (!plane) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("no plane yet: it needs two edges that are not in line");
    ImGui::PopStyleColor();
    return;
  }
  // The normal shown is the stored one when fixed, else the fitted plane's.
  const Vec3 n = v.normal ? *v.normal : plane->normal;
  static double edit[3];
  static int editing = -1;  // the vertex whose normal is being typed
  if (editing != v.vertex) edit[0] = n.x, edit[1] = n.y, edit[2] = n.z;
  ImGui::TextDisabled("normal");
  ImGui::SameLine(ImGui::GetFontSize() * 6);
  ImGui::SetNextItemWidth(-1);
  ImGui::InputScalarN("##normal", ImGuiDataType_Double, edit, 3, nullptr, nullptr, "%.4g");
  editing = ImGui::IsItemActive() ? v.vertex : -1;
  if (ImGui::IsItemDeactivatedAfterEdit()) {
    const Vec3 typed(edit[0], edit[1], edit[2]);
    if (typed != n) run(p, std::make_shared<SetVertexNormalCommand>(v.vertex, typed));
  }
  ImGui::TextDisabled("Drag the knob in the view to turn it.");
}

void patch_section(const PatchProperties& q) {
  field("name", or_none(q.name));
  field("type", q.type);
  field("points", std::to_string(q.points));
}

// Where point r is: a free point as the views list it when they show the document as it is (the
// document would rebuild its face's G1 data every frame), any other from the document.
Vec3 position_of(const SidePanel& p, const PointRef& r) {
  if (r.kind == PointRef::Kind::FreePoint && p.model.views().ready()) {
    const LiveSurfaces& live = p.model.views().main()->shown();
    if (live.synced_revision() == p.model.doc().revision())
      if (const int i = live.points().find(r); i >= 0) return live.points().positions[i];
  }
  return point_position(p.model.doc().scene(), r);
}

// Typed coordinates of the selected points' centre: applied as one command when the field is
// left or Enter pressed.
void coordinates(const SidePanel& p, const std::vector<PointRef>& points) {
  Vec3 centre(0);
  for (const PointRef& r : points) centre += position_of(p, r);
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
      for (const PointRef& r : points) positions.push_back(position_of(p, r) + d);
      run(p, std::make_shared<MovePointsCommand>(points, positions));
    }
  }
}

}  // namespace

void draw_selection_section(const SidePanel& p) {
  const Scene& scene = p.model.doc().scene();
  std::vector<SelectionItem> present;
  for (const SelectionItem& i : p.model.selection().items())
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
    if (i.kind == Kind::Edge) edge_section(p, *edge_properties(scene, i.index));
    if (i.kind == Kind::Patch) patch_section(*patch_properties(scene, i.index));
    if (i.kind == Kind::Curve) draw_curve_section(p, i.index, -1);
    if (i.kind == Kind::Point && i.point.kind == PointRef::Kind::NetworkVertex)
      vertex_section(p, *vertex_properties(scene, i.point.index));
  } else {
    int counts[5] = {0, 0, 0, 0, 0};
    for (const SelectionItem& i : present) ++counts[int(i.kind)];
    static const char* names[5] = {"points", "edges", "faces", "patches", "curves"};
    std::string summary;
    for (int k = 0; k < 5; ++k)
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
    if (points[0].kind == PointRef::Kind::CurvePoint)
      draw_curve_section(p, points[0].object, points[0].index);
    if (points.size() == 1 && points[0].kind == PointRef::Kind::FreePoint)
      interior_section(p, points[0].object);
  }
  if (!transform_points(scene, p.model.selection()).empty()) {
    ImGui::Separator();
    draw_transform_section(p);
  }
}

}  // namespace pl
