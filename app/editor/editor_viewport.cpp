// Drawing the 3D view: one panel, or Gregory | GB side by side with one camera and one colour
// range; then the overlays drawn with ImGui's background list (hover, selection, worst edge,
// labels, axes, legend), which stay crisp and need no extra GL programs.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "app/editor/editor.hpp"
#include "app/editor/logic/surface_difference.hpp"
#include "app/editor/theme.hpp"
#include "render/frame.hpp"
#include "render/gl.hpp"
#include "render/legend.hpp"

namespace pl {

namespace {

constexpr float kSidePanelWidth = 340.0f;  // at UI scale 1

ImU32 rgba(float r, float g, float b, float a = 1) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(r, g, b, a));
}

}  // namespace

ViewRect Editor::viewport_rect() const {
  const ImGuiIO& io = ImGui::GetIO();
  const double menu = ImGui::GetFrameHeight();
  const double status = ImGui::GetFrameHeight() + 6 * ui_scale_;
  const double side = kSidePanelWidth * ui_scale_;
  return {0, menu, std::max(1.0, io.DisplaySize.x - side),
          std::max(1.0, io.DisplaySize.y - menu - status)};
}

std::vector<ViewRect> Editor::panel_rects() const {
  const ViewRect r = viewport_rect();
  if (!compare_) return {r};
  const double half = std::floor(r.width / 2);
  return {{r.x, r.y, half, r.height}, {r.x + half, r.y, r.width - half, r.height}};
}

const EvaluatedView& Editor::panel_view(int panel) const {
  if (compare_ && compare_views_[panel]) return *compare_views_[panel];
  return *main_view_;
}

int Editor::panel_at(const Vec2& pixel) const {
  const auto rects = panel_rects();
  for (std::size_t i = 0; i < rects.size(); ++i)
    if (rects[i].contains(pixel)) return static_cast<int>(i);
  return -1;
}

ColorRange Editor::current_range() const {
  if (prefs_.display.range) return *prefs_.display.range;
  std::vector<const SurfaceMesh*> meshes;
  const int panels = compare_ ? 2 : 1;
  for (int i = 0; i < panels; ++i)
    for (const SurfaceMesh& m : panel_view(i).shown().draw().surfaces) meshes.push_back(&m);
  // One range for every panel, so equal colours mean equal curvature across the comparison.
  return automatic_range(meshes, prefs_.display.curvature, prefs_.display.range_percentile);
}

void Editor::refresh_difference() {
  if (!compare_ || !compare_views_[0] || !compare_views_[1]) return;
  const uint64_t key = doc_.revision() * 2 + (compare_views_[1]->settled() ? 1 : 0);
  if (difference_gpu_ && key == difference_revision_) return;
  difference_revision_ = key;
  const DrawScene& gregory = compare_views_[0]->shown().draw();
  DrawScene d = compare_views_[1]->shown().draw();
  difference_max_ = 0;
  static uint64_t upload = 0;  // unique revisions force the re-upload of every surface
  for (std::size_t i = 0; i < d.surfaces.size() && i < gregory.surfaces.size(); ++i) {
    d.surfaces[i].mean = signed_distance_to(d.surfaces[i], gregory.surfaces[i]);
    for (double v : d.surfaces[i].mean) difference_max_ = std::max(difference_max_, std::abs(v));
    d.surfaces[i].revision = ++upload + (1ull << 40);
  }
  if (!difference_gpu_)
    difference_gpu_ = std::make_unique<GpuScene>(d);
  else
    difference_gpu_->update(d);
}

void Editor::draw_viewport() {
  int fbw = 0, fbh = 0, ww = 0, wh = 0;
  glfwGetFramebufferSize(window_.handle(), &fbw, &fbh);
  glfwGetWindowSize(window_.handle(), &ww, &wh);
  glViewport(0, 0, fbw, fbh);
  glDisable(GL_SCISSOR_TEST);
  glClearColor(0.155f, 0.160f, 0.175f, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (!main_view_) {
    const ViewRect r = viewport_rect();
    ImGui::GetBackgroundDrawList()->AddText(ImVec2(float(r.x + 20), float(r.y + 20)),
                                            rgba(1, 0.55f, 0.5f),
                                            ("Cannot show this scene:\n" + view_error_).c_str());
    return;
  }
  if (!camera_framed_) {
    camera_ = preset_camera(ViewPreset::Iso, main_view_->shown().draw().bounds(),
                            panel_rects()[0].aspect());
    camera_framed_ = true;
  }
  const double sx = ww > 0 ? double(fbw) / ww : 1.0;
  const auto rects = panel_rects();
  const ColorRange range = current_range();
  if (compare_ && difference_) refresh_difference();
  // One comb scale for side-by-side panels, as one colour range.
  std::vector<const GpuScene*> scenes;
  for (std::size_t i = 0; i < rects.size(); ++i) scenes.push_back(&panel_view(int(i)).gpu());
  const DisplaySettings display = common_comb_length(prefs_.display, scenes);
  for (std::size_t i = 0; i < rects.size(); ++i) {
    const ViewRect& r = rects[i];
    Viewport v;
    v.x = int(std::lround(r.x * sx));
    v.y = int(std::lround((wh - r.y - r.height) * sx));
    v.width = std::max(1, int(std::lround(r.width * sx)));
    v.height = std::max(1, int(std::lround(r.height * sx)));
    v.pixel_scale = sx * ui_scale_;
    glEnable(GL_SCISSOR_TEST);
    glScissor(v.x, v.y, v.width, v.height);
    glClear(GL_DEPTH_BUFFER_BIT);
    renderer_.draw_backdrop(v);
    if (compare_ && difference_ && i == 1 && difference_gpu_) {
      DisplaySettings d = display;
      d.base = BaseMode::Curvature;
      d.curvature = CurvatureKind::Mean;  // the field that holds the distance
      d.curvature_lighting = true;
      const double m = difference_max_ > 0 ? difference_max_ : 1e-12;
      renderer_.draw(*difference_gpu_, camera_, d, {-m, m}, v);
    } else {
      renderer_.draw(panel_view(int(i)).gpu(), camera_, display, range, v);
    }
    glDisable(GL_SCISSOR_TEST);
  }
  for (std::size_t i = 0; i < rects.size(); ++i) draw_overlays(rects[i], panel_view(int(i)));
  const ViewRect whole = viewport_rect();
  if (compare_ && difference_) {
    const double m = difference_max_ > 0 ? difference_max_ : 1e-12;
    draw_legend(whole, {-m, m}, "distance GB - Gregory");
  } else if (prefs_.display.base == BaseMode::Curvature) {
    draw_legend(whole, range, std::string(curvature_name(prefs_.display.curvature)) + " curvature");
  }
}

void Editor::draw_overlays(const ViewRect& rect, const EvaluatedView& view) {
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  const ImVec2 lo(float(rect.x), float(rect.y)),
      hi(float(rect.x + rect.width), float(rect.y + rect.height));
  dl->PushClipRect(lo, hi, true);
  auto screen = [&](const Vec3& p) { return project_to_window(camera_, rect, p); };
  auto im = [](const Vec2& p) { return ImVec2(float(p.x), float(p.y)); };
  const float s = ui_scale_;

  // The edge the continuity table points at (picked row, else the worst one).
  const int edge = highlighted_edge_ >= 0 ? highlighted_edge_
                   : worst_edge_ >= 0     ? report_.edges[worst_edge_].edge
                                          : -1;
  const auto& curves = view.shown().draw().network_curves;
  if (edge >= 0 && edge < int(curves.size()) && prefs_.display.network_curves) {
    std::vector<ImVec2> line;
    for (const Vec3& p : curves[edge])
      if (const auto q = screen(p)) line.push_back(im(*q));
    dl->AddPolyline(line.data(), int(line.size()), rgba(0.93f, 0.22f, 0.25f, 0.9f), 0, 4.0f * s);
  }

  const ScenePoints& pts = view.shown().points();
  if (prefs_.display.control_net) {
    for (const PointRef& r : selection_) {
      const int i = pts.find(r);
      if (i < 0) continue;
      if (const auto q = screen(pts.positions[i])) {
        dl->AddCircleFilled(im(*q), 6.5f * s, rgba(kAccent[0], kAccent[1], kAccent[2]));
        dl->AddCircle(im(*q), 8.5f * s, rgba(0.1f, 0.1f, 0.1f, 0.9f), 0, 1.5f * s);
      }
    }
    if (hover_) {
      const int i = pts.find(*hover_);
      if (i >= 0)
        if (const auto q = screen(pts.positions[i])) {
          dl->AddCircle(im(*q), 10.0f * s, rgba(1, 1, 1, 0.95f), 0, 2.0f * s);
          ImGui::SetTooltip("%s", describe(*hover_).c_str());
        }
    } else if (hover_derived_ >= 0 && hover_derived_ < int(pts.positions.size())) {
      static const char* kinds[] = {"boundary", "inner", "twin", "central"};
      if (const auto q = screen(pts.positions[hover_derived_]))
        dl->AddCircle(im(*q), 10.0f * s, rgba(0.7f, 0.7f, 0.7f, 0.8f), 0, 1.5f * s);
      ImGui::SetTooltip("derived %s point (follows the network; not editable)",
                        kinds[int(pts.kinds[hover_derived_])]);
    }
  }
  if (probe_ && !doc_.dragging())
    if (const auto q = screen(probe_->position)) {
      dl->AddCircle(im(*q), 4.0f * s, rgba(0.05f, 0.05f, 0.05f, 0.9f), 0, 1.5f * s);
    }

  // Panel label in the comparison.
  if (compare_) {
    const char* label = view.scheme() == FaceScheme::Gregory ? "Gregory"
                        : difference_ ? "Generalized Bezier (coloured by distance to Gregory)"
                                      : "Generalized Bezier";
    dl->AddText(ImVec2(lo.x + 12 * s, lo.y + 10 * s), rgba(0.12f, 0.13f, 0.16f), label);
    if (rect.x > viewport_rect().x)
      dl->AddLine(ImVec2(lo.x, lo.y), ImVec2(lo.x, hi.y), rgba(0.1f, 0.1f, 0.12f), 2 * s);
  }

  // Axis triad in the bottom-left corner: which way x, y, z point from this camera.
  const ImVec2 o(lo.x + 34 * s, hi.y - 34 * s);
  const Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const ImU32 colors[3] = {rgba(0.85f, 0.25f, 0.25f), rgba(0.3f, 0.7f, 0.3f),
                           rgba(0.25f, 0.45f, 0.9f)};
  const char* names[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    const ImVec2 e(o.x + float(glm::dot(axes[a], camera_.right())) * 22 * s,
                   o.y - float(glm::dot(axes[a], camera_.up())) * 22 * s);
    dl->AddLine(o, e, colors[a], 2.0f * s);
    dl->AddText(ImVec2(e.x + 2 * s, e.y - 7 * s), colors[a], names[a]);
  }
  dl->PopClipRect();
}

void Editor::draw_legend(const ViewRect& rect, const ColorRange& range, const std::string& title) {
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  const float s = ui_scale_;
  const float bar_w = 16 * s, bar_h = float(std::min(rect.height * 0.5, 320.0 * s));
  const float x1 = float(rect.x + rect.width) - 70 * s, x0 = x1 - bar_w;
  const float y0 = float(rect.y + rect.height * 0.5) - bar_h / 2, y1 = y0 + bar_h;
  dl->AddRectFilled(ImVec2(x0 - 12 * s, y0 - 30 * s), ImVec2(x1 + 64 * s, y1 + 12 * s),
                    rgba(1, 1, 1, 0.72f), 4 * s);
  constexpr int kSteps = 64;
  for (int i = 0; i < kSteps; ++i) {
    // Top is hi: t runs from 1 at the top to 0 at the bottom.
    const double t0 = 1 - double(i) / kSteps, t1 = 1 - double(i + 1) / kSteps;
    const Rgb a = color_map(t0), b = color_map(t1);
    dl->AddRectFilledMultiColor(ImVec2(x0, y0 + bar_h * i / kSteps),
                                ImVec2(x1, y0 + bar_h * (i + 1) / kSteps), rgba(a[0], a[1], a[2]),
                                rgba(a[0], a[1], a[2]), rgba(b[0], b[1], b[2]),
                                rgba(b[0], b[1], b[2]));
  }
  dl->AddRect(ImVec2(x0, y0), ImVec2(x1, y1), rgba(0.2f, 0.2f, 0.22f), 0, 0, 1.0f);
  const ImU32 ink = rgba(0.12f, 0.13f, 0.16f);
  const double ticks[5] = {range.hi, range.hi / 2, 0, range.lo / 2, range.lo};
  for (int i = 0; i < 5; ++i) {
    const float y = y0 + bar_h * i / 4;
    dl->AddLine(ImVec2(x1, y), ImVec2(x1 + 4 * s, y), ink, 1.0f);
    dl->AddText(ImVec2(x1 + 7 * s, y - 7 * s), ink, format_tick(ticks[i]).c_str());
  }
  const ImVec2 ts = ImGui::CalcTextSize(title.c_str());
  dl->AddText(ImVec2(std::min(x0 - 6 * s, x1 + 60 * s - ts.x), y0 - 24 * s), ink, title.c_str());
}

}  // namespace pl
