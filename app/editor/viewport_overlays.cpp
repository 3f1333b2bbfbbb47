#include "app/editor/viewport_overlays.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <unordered_set>

#include "app/editor/logic/editor_layout.hpp"
#include "app/editor/theme.hpp"
#include "render/palette.hpp"
#include "render/point_key.hpp"

namespace pl {

namespace {

ImU32 rgba(float r, float g, float b, float a = 1) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(r, g, b, a));
}

ImVec2 im(const Vec2& p) {
  return ImVec2(float(p.x), float(p.y));
}

// One number per PointRef, for a set of the selected points.
uint64_t point_key(const PointRef& r) {
  return uint64_t(r.kind) << 62 ^ uint64_t(uint32_t(r.object)) << 30 ^ uint64_t(uint32_t(r.index));
}

}  // namespace

void draw_point_overlays(const OverlayFrame& o) {
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  const ImVec2 lo(float(o.rect.x), float(o.rect.y)),
      hi(float(o.rect.x + o.rect.width), float(o.rect.y + o.rect.height));
  dl->PushClipRect(lo, hi, true);
  auto screen = [&](const Vec3& p) { return project_to_window(o.camera, o.rect, p); };
  const float s = o.ui_scale;
  const DisplaySettings& d = o.prefs.display;

  // The worst edge of this panel's filling, when it is over the user's warning threshold: a
  // warning, so drawn with the curves hidden too, outlined dark to stand out on light surfaces.
  const auto& curves = o.live.draw().network_curves;
  const int worst =
      o.continuity ? o.continuity->warned_edge(o.panel, o.prefs.continuity_threshold_deg) : -1;
  if (worst >= 0 && worst < int(curves.size())) {
    std::vector<ImVec2> line;
    for (const Vec3& p : curves[worst])
      if (const auto q = screen(p)) line.push_back(im(*q));
    const Rgb h = palette::kHighlight;
    dl->AddPolyline(line.data(), int(line.size()), rgba(0.1f, 0.1f, 0.1f, 0.85f), 0, 6.5f * s);
    dl->AddPolyline(line.data(), int(line.size()), rgba(h[0], h[1], h[2]), 0, 4.0f * s);
  }

  const ScenePoints& pts = o.live.points();
  if (d.control_net) {
    std::unordered_set<uint64_t> selected;
    for (const PointRef& r : o.selection.points()) selected.insert(point_key(r));
    if (!selected.empty())
      for (std::size_t i = 0; i < pts.refs.size(); ++i) {
        if (!pts.refs[i] || !selected.count(point_key(*pts.refs[i]))) continue;
        if (const auto q = screen(pts.positions[i])) {
          dl->AddCircleFilled(im(*q), 6.5f * s, rgba(kAccent[0], kAccent[1], kAccent[2]));
          dl->AddCircle(im(*q), 8.5f * s, rgba(0.1f, 0.1f, 0.1f, 0.9f), 0, 1.5f * s);
        }
      }
    if (o.hover && o.hover->point >= 0 && o.hover->point < int(pts.positions.size())) {
      const int i = o.hover->point;
      if (const auto q = screen(pts.positions[i])) {
        if (!o.hover->derived_point) {
          dl->AddCircle(im(*q), 10.0f * s, rgba(1, 1, 1, 0.95f), 0, 2.0f * s);
          ImGui::SetTooltip("%s (%s point)", describe(*pts.refs[i]).c_str(),
                            point_kind_name(pts.kinds[i]));
        } else {
          dl->AddCircle(im(*q), 10.0f * s, rgba(0.7f, 0.7f, 0.7f, 0.8f), 0, 1.5f * s);
          ImGui::SetTooltip("derived %s point (follows the network; not editable)",
                            point_kind_name(pts.kinds[i]));
        }
      }
    }
  }
  if (o.hover && o.probe && *o.probe && o.prefs.show_probe)
    if (const auto q = screen((*o.probe)->position))
      dl->AddCircle(im(*q), 4.0f * s, rgba(0.05f, 0.05f, 0.05f, 0.9f), 0, 1.5f * s);
  dl->PopClipRect();
}

void draw_panel_label(const OverlayFrame& o, const std::string& label, const ViewRect& whole) {
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  const float s = o.ui_scale;
  const ImVec2 lo(float(o.rect.x), float(o.rect.y)),
      hi(float(o.rect.x + o.rect.width), float(o.rect.y + o.rect.height));
  dl->AddText(ImVec2(lo.x + 12 * s, lo.y + 10 * s), rgba(0.12f, 0.13f, 0.16f), label.c_str());
  // The panes' borders with their left and upper neighbours.
  if (o.rect.x > whole.x)
    dl->AddLine(ImVec2(lo.x, lo.y), ImVec2(lo.x, hi.y), rgba(0.1f, 0.1f, 0.12f), 2 * s);
  if (o.rect.y > whole.y)
    dl->AddLine(ImVec2(lo.x, lo.y), ImVec2(hi.x, lo.y), rgba(0.1f, 0.1f, 0.12f), 2 * s);
}

void draw_axis_triad(const OverlayFrame& o) {
  // Bottom-left corner: which way x, y, z point from this camera.
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  const float s = o.ui_scale;
  const ImVec2 origin(float(o.rect.x) + 34 * s, float(o.rect.y + o.rect.height) - 34 * s);
  const Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const ImU32 colors[3] = {rgba(0.85f, 0.25f, 0.25f), rgba(0.3f, 0.7f, 0.3f),
                           rgba(0.25f, 0.45f, 0.9f)};
  const char* names[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    const ImVec2 e(origin.x + float(glm::dot(axes[a], o.camera.right())) * 22 * s,
                   origin.y - float(glm::dot(axes[a], o.camera.up())) * 22 * s);
    dl->AddLine(origin, e, colors[a], 2.0f * s);
    dl->AddText(ImVec2(e.x + 2 * s, e.y - 7 * s), colors[a], names[a]);
  }
}

void draw_error_text(const ViewRect& r, const std::string& text) {
  ImGui::GetBackgroundDrawList()->AddText(ImVec2(float(r.x + 20), float(r.y + 20)),
                                          rgba(1, 0.55f, 0.5f), text.c_str());
}

namespace {

// A dashed line: dashes and gaps of `dash` pixels.
void dashed_line(ImDrawList* dl, const Vec2& a, const Vec2& b, ImU32 colour, float width,
                 float dash) {
  const double length = glm::length(b - a);
  if (!(length > 0)) return;
  const Vec2 step = (b - a) / length;
  for (double s = 0; s < length; s += 2 * dash)
    dl->AddLine(im(a + s * step), im(a + std::min(s + dash, length) * step), colour, width);
}

}  // namespace

void draw_tool_overlays(const ViewRect& rect, const Camera& camera, const ToolPreview& preview,
                        const std::vector<PlaneHandle>& planes, int hot, float s) {
  if (preview.empty() && planes.empty()) return;
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  dl->PushClipRect(ImVec2(float(rect.x), float(rect.y)),
                   ImVec2(float(rect.x + rect.width), float(rect.y + rect.height)), true);
  const WindowProjector screen(camera, rect);
  const ImU32 accent = rgba(kAccent[0], kAccent[1], kAccent[2]);
  const ImU32 ink = rgba(0.08f, 0.08f, 0.1f, 0.9f);

  for (std::size_t i = 0; i < planes.size(); ++i) {
    const PlaneHandle& h = planes[i];
    // The disc: a circle in the plane, filled faintly so its tilt reads at a glance.
    const Vec3 a = std::abs(h.normal.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    const Vec3 u = glm::normalize(glm::cross(h.normal, a)), v = glm::cross(h.normal, u);
    std::vector<ImVec2> rim;
    constexpr int kRim = 48;
    for (int k = 0; k < kRim; ++k) {
      const double t = 2 * M_PI * k / kRim;
      if (const auto q = screen(h.centre + h.radius * (std::cos(t) * u + std::sin(t) * v)))
        rim.push_back(im(*q));
    }
    const auto c = screen(h.centre), knob = screen(h.knob);
    if (rim.size() == kRim && c) {
      const ImU32 fill = h.fixed ? rgba(kAccent[0], kAccent[1], kAccent[2], 0.22f)
                                 : rgba(0.45f, 0.62f, 0.9f, 0.22f);
      // An ellipse on screen: convex; ImGui's anti-aliased fill wants it clockwise (y down).
      double area = 0;
      for (int k = 0; k < kRim; ++k)
        area += double(rim[k].x) * rim[(k + 1) % kRim].y - double(rim[(k + 1) % kRim].x) * rim[k].y;
      if (area < 0) std::reverse(rim.begin(), rim.end());
      dl->AddConvexPolyFilled(rim.data(), kRim, fill);
      dl->AddPolyline(rim.data(), kRim, h.fixed ? accent : rgba(0.45f, 0.62f, 0.9f, 0.95f),
                      ImDrawFlags_Closed, 1.8f * s);
    }
    if (c && knob) {
      dl->AddLine(im(*c), im(*knob), ink, 2.0f * s);
      const bool is_hot = int(i) == hot;
      dl->AddCircleFilled(im(*knob), (is_hot ? 7.0f : 5.5f) * s, is_hot ? rgba(1, 1, 1) : accent);
      dl->AddCircle(im(*knob), (is_hot ? 7.0f : 5.5f) * s, ink, 0, 1.5f * s);
      if (is_hot)
        ImGui::SetTooltip("vertex %d: drag to turn its tangent plane (%s)", h.vertex,
                          h.fixed ? "fixed" : "fitted; dragging fixes it");
    }
  }

  for (const std::vector<Vec3>& line : preview.lines) {
    std::vector<ImVec2> pts;
    for (const Vec3& p : line)
      if (const auto q = screen(p)) pts.push_back(im(*q));
    dl->AddPolyline(pts.data(), int(pts.size()), accent, 0, 3.0f * s);
  }
  for (const auto& [a, b] : preview.pending) {
    const auto qa = screen(a), qb = screen(b);
    if (qa && qb) dashed_line(dl, *qa, *qb, ink, 1.8f * s, 6.0f * s);
  }
  // Picked points: white rings (the selection is filled), numbered in the order picked.
  for (std::size_t i = 0; i < preview.picked.size(); ++i)
    if (const auto q = screen(preview.picked[i])) {
      dl->AddCircleFilled(im(*q), 7.5f * s, rgba(1, 1, 1));
      dl->AddCircle(im(*q), 7.5f * s, accent, 0, 3.0f * s);
      if (preview.picked.size() > 1)
        dl->AddText(ImVec2(float(q->x) + 9 * s, float(q->y) - 19 * s), ink,
                    std::to_string(i + 1).c_str());
    }
  if (preview.target)
    if (const auto q = screen(*preview.target)) {
      // A ring with a cross: where a click adds or splits.
      const ImVec2 m = im(*q);
      const float r = 7.0f * s;
      dl->AddCircle(m, r, ink, 0, 2.0f * s);
      dl->AddLine(ImVec2(m.x - 1.6f * r, m.y), ImVec2(m.x + 1.6f * r, m.y), ink, 1.2f * s);
      dl->AddLine(ImVec2(m.x, m.y - 1.6f * r), ImVec2(m.x, m.y + 1.6f * r), ink, 1.2f * s);
    }
  dl->PopClipRect();
}

}  // namespace pl
