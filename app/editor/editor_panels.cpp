// Menus, the side panel (display, selection inspector, comparison, continuity), the status bar,
// the probe read-out and the help window.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/editor/editor.hpp"
#include "app/editor/theme.hpp"

namespace pl {

namespace {

constexpr float kSidePanelWidth = 340.0f;  // at UI scale 1; matches editor_viewport.cpp

}  // namespace

void Editor::draw_menu_bar() {
  if (!ImGui::BeginMainMenuBar()) return;
  if (ImGui::BeginMenu("File")) {
    if (ImGui::MenuItem("Open...", "Ctrl+O"))
      confirm_discard("open another file", [this] {
        browse_for_ = BrowseFor::Open;
        browser_.open("Open scene", "Open", browse_start_dir(), {".json", ".gbp"}, "");
      });
    if (ImGui::MenuItem("Save", "Ctrl+S")) {
      if (doc_.path().empty()) {
        browse_for_ = BrowseFor::SaveAs;
        browser_.open("Save scene as", "Save", browse_start_dir(), {".json"}, ".json");
      } else {
        save();
      }
    }
    if (ImGui::MenuItem("Save As...", "Ctrl+Shift+S")) {
      browse_for_ = BrowseFor::SaveAs;
      browser_.open("Save scene as", "Save", browse_start_dir(), {".json"}, ".json",
                    doc_.path().filename().string());
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Export Mesh...")) {
      browse_for_ = BrowseFor::ExportMesh;
      browser_.open("Export mesh", "Export", browse_start_dir(), {".obj", ".ply", ".off", ".stl"},
                    ".obj", doc_.path().stem().string() + ".obj");
    }
    if (ImGui::MenuItem("Screenshot...")) show_screenshot_ = true;
    ImGui::Separator();
    if (ImGui::MenuItem("Quit", "Ctrl+Q")) confirm_discard("quit", [this] { quit_ = true; });
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Edit")) {
    const std::string u = "Undo " + doc_.undo_label(), r = "Redo " + doc_.redo_label();
    if (ImGui::MenuItem(u.c_str(), "Ctrl+Z", false, doc_.can_undo())) doc_.undo();
    if (ImGui::MenuItem(r.c_str(), "Ctrl+Shift+Z / Ctrl+Y", false, doc_.can_redo())) doc_.redo();
    ImGui::Separator();
    if (ImGui::MenuItem("Clear Selection", "Esc", false, !selection_.empty())) selection_.clear();
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    if (ImGui::MenuItem("Frame All", "F")) frame_all();
    if (ImGui::MenuItem("Frame Selection", "Shift+F", false, !selection_.empty()))
      frame_selection();
    ImGui::Separator();
    if (ImGui::MenuItem("Front", "1")) set_preset(ViewPreset::Front);
    if (ImGui::MenuItem("Right", "3")) set_preset(ViewPreset::Right);
    if (ImGui::MenuItem("Top", "7")) set_preset(ViewPreset::Top);
    if (ImGui::MenuItem("Iso", "0")) set_preset(ViewPreset::Iso);
    ImGui::MenuItem("Orthographic", "5", &camera_.orthographic);
    ImGui::Separator();
    bool compare = compare_;
    if (ImGui::MenuItem("Compare Gregory | GB", "C", &compare, doc_.scene().network.has_value())) {
      compare_ = compare;
      rebuild_views();
      frame_all();  // the panels' aspect changed
    }
    ImGui::MenuItem("Difference Colouring", "D", &difference_, compare_);
    ImGui::MenuItem("Probe Under Cursor", nullptr, &prefs_.show_probe);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Help")) {
    ImGui::MenuItem("Mouse and Keys", "F1", &show_help_);
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();
}

void Editor::draw_side_panel() {
  const ImGuiIO& io = ImGui::GetIO();
  const float w = kSidePanelWidth * ui_scale_;
  const float top = ImGui::GetFrameHeight();
  const float bottom = ImGui::GetFrameHeight() + 6 * ui_scale_;
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - w, top));
  ImGui::SetNextWindowSize(ImVec2(w, io.DisplaySize.y - top - bottom));
  ImGui::Begin("##side", nullptr,
               ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings);
  // Widgets take what is left after a label column of fixed width, so labels never clip.
  ImGui::PushItemWidth(-110 * ui_scale_);
  if (ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) draw_display_section();
  if (ImGui::CollapsingHeader("Selection", ImGuiTreeNodeFlags_DefaultOpen))
    draw_selection_section();
  if (doc_.scene().network && ImGui::CollapsingHeader("Comparison", ImGuiTreeNodeFlags_DefaultOpen))
    draw_comparison_section();
  if (ImGui::CollapsingHeader("Continuity", ImGuiTreeNodeFlags_DefaultOpen))
    draw_continuity_section();
  ImGui::PopItemWidth();
  ImGui::End();
}

void Editor::draw_display_section() {
  DisplaySettings& d = prefs_.display;
  static const char* modes[] = {"Shaded", "Isophotes", "Zebra", "Curvature"};
  int base = static_cast<int>(d.base);
  ImGui::SetNextItemWidth(-1);
  if (ImGui::Combo("##mode", &base, modes, 4)) {
    d.base = static_cast<BaseMode>(base);
    if (d.base == BaseMode::Isophotes) d.isophote_lines = true;
  }
  if (d.base == BaseMode::Curvature) {
    static const char* kinds[] = {"Gaussian K", "Mean H", "k min", "k max"};
    int k = static_cast<int>(d.curvature);
    if (ImGui::Combo("Curvature", &k, kinds, 4)) d.curvature = static_cast<CurvatureKind>(k);
    bool fixed = d.range.has_value();
    if (ImGui::Checkbox("Fixed range", &fixed)) {
      if (fixed)
        d.range = current_range();
      else
        d.range.reset();
    }
    if (d.range) {
      float hi = float(d.range->hi);
      if (ImGui::DragFloat("+/- range", &hi, std::max(1e-4f, hi * 0.01f), 1e-6f, 1e6f, "%.4g"))
        d.range = ColorRange{-std::max(1e-9, double(hi)), std::max(1e-9, double(hi))};
    } else {
      float p = float(d.range_percentile);
      if (ImGui::SliderFloat("Percentile", &p, 50, 100, "%.1f %%")) d.range_percentile = p;
    }
    ImGui::Checkbox("Lit colours", &d.curvature_lighting);
  }
  if (d.base == BaseMode::Zebra) {
    ImGui::SliderInt("Stripes", &d.zebra_count, 2, 60);
    float w = float(d.zebra_width);
    if (ImGui::SliderFloat("Dark fraction", &w, 0.05f, 0.95f)) d.zebra_width = w;
  }
  ImGui::Checkbox("Isophote lines", &d.isophote_lines);
  if (d.base == BaseMode::Isophotes) d.isophote_lines = true;
  if (d.isophote_lines) {
    ImGui::SliderInt("Isophotes", &d.isophote_count, 2, 60);
    float w = float(d.isophote_width_px);
    if (ImGui::SliderFloat("Line width", &w, 0.5f, 5.0f, "%.1f px")) d.isophote_width_px = w;
  }
  ImGui::Checkbox("Control net", &d.control_net);
  ImGui::SameLine(ImGui::GetContentRegionAvail().x * 0.5f);
  ImGui::Checkbox("Curves", &d.network_curves);
  ImGui::Checkbox("Patch borders", &d.borders);
  ImGui::SameLine(ImGui::GetContentRegionAvail().x * 0.5f);
  ImGui::Checkbox("Probe", &prefs_.show_probe);
  ImGui::Checkbox("Curvature combs", &d.combs);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Teeth of length proportional to the curvature, away from the centre of\n"
        "curvature, on the curves and borders shown (on the curves if neither is)");
  if (d.combs) {
    float scale = float(d.comb_scale);
    if (ImGui::SliderFloat("Comb scale", &scale, float(kMinCombScale), float(kMaxCombScale),
                           "%.2f x", ImGuiSliderFlags_Logarithmic))
      d.comb_scale = scale;
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "Multiplies the automatic tooth length (the 90th-percentile curvature\n"
          "gets 6 %% of the scene diagonal; teeth are capped at 3 times that)");
    // A new count resamples the combs only (the views follow it each frame, no re-evaluation).
    ImGui::SliderInt("Comb teeth", &d.comb_teeth, kMinCombTeeth, kMaxCombTeeth);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Teeth per curve");
  }
  int densities[2] = {prefs_.coarse_density, prefs_.fine_density};
  if (ImGui::SliderInt2("Density", densities, 4, 96)) {
    prefs_.coarse_density = densities[0];
    prefs_.fine_density = densities[1];
  }
  if (ImGui::IsItemDeactivatedAfterEdit()) rebuild_views();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Samples per boundary curve while dragging / at rest");
}

void Editor::draw_selection_section() {
  if (selection_.empty()) {
    ImGui::TextDisabled("Click a control point to select it;");
    ImGui::TextDisabled("Shift-click adds to the selection.");
    return;
  }
  std::vector<PointRef> present;
  for (const PointRef& r : selection_)
    if (point_exists(doc_.scene(), r)) present.push_back(r);
  if (present.empty()) return;
  Vec3 centre(0);
  for (const PointRef& r : present) centre += point_position(doc_.scene(), r);
  centre /= double(present.size());
  if (present.size() == 1)
    ImGui::Text("%s", describe(present[0]).c_str());
  else
    ImGui::Text("%zu points (centre shown)", present.size());
  // Typed coordinates: applied as one command when the field is left or Enter is pressed.
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
      for (const PointRef& r : present) positions.push_back(point_position(doc_.scene(), r) + d);
      doc_.execute(std::make_unique<MovePointsCommand>(present, positions));
    }
  }
  ImGui::TextDisabled("Drag in the view; hold X/Y/Z for an axis.");
  ImGui::TextDisabled("Arrows nudge (Shift x10, Alt x0.1).");
}

void Editor::draw_comparison_section() {
  bool compare = compare_;
  if (ImGui::Checkbox("Gregory | GB side by side  (C)", &compare)) {
    compare_ = compare;
    rebuild_views();
    frame_all();  // the panels' aspect changed
  }
  if (!compare_) return;
  ImGui::Checkbox("Colour GB by distance  (D)", &difference_);
  if (difference_)
    ImGui::TextWrapped(
        "Signed distance of each GB sample to the nearest point of the Gregory "
        "tessellation; max |d| = %.3g",
        difference_max_);
}

void Editor::draw_continuity_section() {
  if (report_.edges.empty()) {
    ImGui::TextDisabled("No shared edges.");
    return;
  }
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingStretchProp;
  const float h = std::min(ImGui::GetTextLineHeightWithSpacing() * (report_.edges.size() + 1.6f),
                           ImGui::GetContentRegionAvail().y);
  if (!ImGui::BeginTable("continuity", 4, flags, ImVec2(0, h))) return;
  ImGui::TableSetupScrollFreeze(0, 1);
  ImGui::TableSetupColumn("edge");
  ImGui::TableSetupColumn("G0 gap");
  ImGui::TableSetupColumn("G1 deg");
  ImGui::TableSetupColumn("H jump");
  ImGui::TableHeadersRow();
  for (int i = 0; i < int(report_.edges.size()); ++i) {
    const EdgeReport& e = report_.edges[i];
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    const bool worst = i == worst_edge_;
    char label[64];
    std::snprintf(label, sizeof label, "%s%d (%d|%d)", worst ? "! " : "", e.edge, e.faces[0],
                  e.faces[1]);
    if (worst) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.42f, 1));
    if (ImGui::Selectable(label, highlighted_edge_ == e.edge, ImGuiSelectableFlags_SpanAllColumns))
      highlighted_edge_ = highlighted_edge_ == e.edge ? -1 : e.edge;
    ImGui::TableNextColumn();
    ImGui::Text("%.2e", e.max_gap);
    ImGui::TableNextColumn();
    ImGui::Text("%.3f", e.max_normal_angle_deg);
    ImGui::TableNextColumn();
    ImGui::Text("%.3g", e.max_mean_curvature_jump);
    if (worst) ImGui::PopStyleColor();
  }
  ImGui::EndTable();
  ImGui::TextDisabled("Red: the edge with the largest normal angle.");
}

void Editor::draw_status_bar() {
  const ImGuiIO& io = ImGui::GetIO();
  const float h = ImGui::GetFrameHeight() + 6 * ui_scale_;
  ImGui::SetNextWindowPos(ImVec2(0, io.DisplaySize.y - h));
  ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, h));
  ImGui::PushStyleColor(ImGuiCol_WindowBg, ImGui::GetStyleColorVec4(ImGuiCol_MenuBarBg));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(8 * ui_scale_, 3 * ui_scale_));
  ImGui::Begin("##status", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoBringToFrontOnFocus);
  std::vector<double> sorted(frame_ms_.begin(), frame_ms_.end());
  std::sort(sorted.begin(), sorted.end());
  const double median = sorted.empty() ? 0 : sorted[sorted.size() / 2];
  const bool coarse = main_view_ && !main_view_->settled();
  ImGui::Text("eval %.1f ms (%s)  |  frame %.1f ms  |  settle %.0f ms  |  %zu selected",
              last_eval_ms_, coarse ? "coarse" : "fine", median, last_settle_ms_,
              selection_.size());
  const bool recent = std::chrono::duration<double>(Clock::now() - status_time_).count() < 8;
  if (!status_message_.empty() && recent) {
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(1.0f, 0.7f, 0.4f, 1), "  |  %s", status_message_.c_str());
  }
  ImGui::End();
  ImGui::PopStyleVar();
  ImGui::PopStyleColor();
}

void Editor::draw_probe_window() {
  if (!prefs_.show_probe || !probe_) return;
  // A small read-out that follows the cursor, offset so it never hides what is probed.
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(io.MousePos.x + 18 * ui_scale_, io.MousePos.y + 18 * ui_scale_));
  ImGui::SetNextWindowBgAlpha(0.85f);
  ImGui::Begin("##probe", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
  const ProbeHit& p = *probe_;
  const auto& meshes =
      main_view_ ? main_view_->shown().draw().surfaces : std::vector<SurfaceMesh>{};
  if (p.surface >= 0 && p.surface < int(meshes.size()))
    ImGui::TextDisabled("%s", meshes[p.surface].name.c_str());
  ImGui::Text("p   %8.4f %8.4f %8.4f", p.position.x, p.position.y, p.position.z);
  ImGui::Text("n   %8.4f %8.4f %8.4f", p.normal.x, p.normal.y, p.normal.z);
  ImGui::Text("k1  %10.4g   k2 %10.4g", p.k1, p.k2);
  ImGui::Text("K   %10.4g   H  %10.4g", p.gaussian, p.mean);
  ImGui::End();
}

void Editor::draw_help_window() {
  ImGui::SetNextWindowSize(ImVec2(600 * ui_scale_, 0), ImGuiCond_Appearing);
  ImGui::SetNextWindowPos(ImVec2(60 * ui_scale_, 80 * ui_scale_), ImGuiCond_Appearing);
  if (!ImGui::Begin("Mouse and keys", &show_help_, ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::End();
    return;
  }
  static const char* rows[][2] = {
      {"Left-drag on empty space", "orbit (turntable; about the selection if any)"},
      {"Right- or middle-drag", "pan"},
      {"Wheel", "zoom towards the cursor"},
      {"Click a point", "select (Shift: add)"},
      {"Drag a point", "move in the view plane"},
      {"  ... holding X / Y / Z", "move along that axis"},
      {"Arrows, PgUp/PgDn", "nudge (Shift x10, Alt x0.1)"},
      {"Esc", "cancel drag / clear selection"},
      {"F / Shift+F", "frame all / selection"},
      {"1 3 7 0", "front, right, top, iso view"},
      {"5", "orthographic on/off"},
      {"C / D", "compare Gregory | GB / distance colours"},
      {"Ctrl+Z, Ctrl+Shift+Z, Ctrl+Y", "undo, redo"},
      {"Ctrl+O, Ctrl+S, Ctrl+Shift+S", "open, save, save as"},
      {"Drop a file on the window", "open it (.json, .gbp)"},
      {"Display > Curvature combs", "teeth ~ curvature on curves / borders (scale, teeth)"},
  };
  if (ImGui::BeginTable("help", 2, ImGuiTableFlags_RowBg)) {
    for (const auto& r : rows) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(r[0]);
      ImGui::TableNextColumn();
      ImGui::TextDisabled("%s", r[1]);
    }
    ImGui::EndTable();
  }
  ImGui::End();
}

}  // namespace pl
