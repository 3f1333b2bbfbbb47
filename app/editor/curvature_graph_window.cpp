#include "app/editor/curvature_graph_window.hpp"

#include <imgui.h>

#include <algorithm>
#include <string>
#include <vector>

#include "app/editor/logic/curvature_graph.hpp"

namespace pl {

bool draw_curvature_graph_window(bool* open, const Scene& scene, std::optional<int> curve,
                                 float ui_scale) {
  ImGui::SetNextWindowSize(ImVec2(420 * ui_scale, 260 * ui_scale), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Curvature Graph", open)) {
    const bool focused = ImGui::IsWindowFocused(ImGuiFocusedFlags_RootAndChildWindows);
    ImGui::End();
    return focused;  // collapsed, still closable with Esc
  }
  const bool focused = ImGui::IsWindowFocused(ImGuiFocusedFlags_RootAndChildWindows);
  if (!curve || *curve < 0 || *curve >= int(scene.curves.size())) {
    ImGui::TextDisabled("Select a point of a curve to see its curvature against t.");
    ImGui::End();
    return focused;
  }
  const SceneCurve& c = scene.curves[*curve];
  const CurvatureGraph g = curvature_graph(c, 64);
  ImGui::Text("%s: curvature from %.6g to %.6g", curve_name(c, *curve).c_str(), g.kappa_min,
              g.kappa_max);
  // Drawn in t (spans of different lengths keep their proportions), from κ = 0 so that a constant
  // curvature reads as a level line above the axis.
  const ImVec2 size(ImGui::GetContentRegionAvail().x,
                    ImGui::GetContentRegionAvail().y - ImGui::GetTextLineHeightWithSpacing());
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("##kappa", size);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y),
                    ImGui::GetColorU32(ImGuiCol_FrameBg));
  const double a = c.t_min(), b = c.t_max();
  const double top = g.kappa_max > 0 ? 1.1 * g.kappa_max : 1.0;
  auto at = [&](double t, double k) {
    return ImVec2(origin.x + size.x * float((t - a) / (b - a)),
                  origin.y + size.y * float(1 - k / top));
  };
  std::vector<ImVec2> line;
  for (std::size_t i = 0; i < g.t.size(); ++i) line.push_back(at(g.t[i], g.kappa[i]));
  dl->AddPolyline(line.data(), int(line.size()), ImGui::GetColorU32(ImGuiCol_PlotLines), 0,
                  2.0f * ui_scale);
  for (double k : g.knots) {
    const float x = at(k, 0).x;
    dl->AddLine(ImVec2(x, origin.y + size.y - 6 * ui_scale), ImVec2(x, origin.y + size.y),
                ImGui::GetColorU32(ImGuiCol_Text), 1.5f * ui_scale);
  }
  if (ImGui::IsItemHovered()) {
    const double t = a + (b - a) * (ImGui::GetIO().MousePos.x - origin.x) / size.x;
    const std::size_t i = std::lower_bound(g.t.begin(), g.t.end(), t) - g.t.begin();
    if (i < g.t.size()) ImGui::SetTooltip("t %.4g  curvature %.6g", g.t[i], g.kappa[i]);
  }
  ImGui::Text("t from %.4g to %.4g; %zu knot ticks", a, b, g.knots.size());
  ImGui::End();
  return focused;
}

}  // namespace pl
