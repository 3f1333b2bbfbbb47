// The free curves' marks over a view panel (ImGui's background list, like the point overlays):
// knot ticks across the curves, and the joints of concatenated curves labelled with their class
// and figures. The geometry is CurveMarks' (GUI-free); this only projects and draws it. Marks
// behind a surface (the painter reads the view's depth: points_seen) are drawn faintly, as the
// curves there are, and their labels not at all.
#include <imgui.h>

#include <optional>
#include <set>

#include "app/editor/viewport_overlays.hpp"
#include "render/palette.hpp"
#include "render/scene_renderer.hpp"

namespace pl {

namespace {

ImVec2 im(const Vec2& p) {
  return ImVec2(float(p.x), float(p.y));
}

ImU32 rgba(const Rgb& c, float a = 1) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(c[0], c[1], c[2], a));
}

// Joint classes: G2 green, G1 the curves' blue, G0 (a corner) the warning yellow on dark.
Rgb joint_colour(int g) {
  return g == 2   ? Rgb{0.13f, 0.55f, 0.27f}
         : g == 1 ? palette::kNetworkCurve
                  : Rgb{0.55f, 0.35f, 0.0f};
}

}  // namespace

std::vector<Vec3> curve_mark_points(const CurveMarks& marks) {
  std::vector<Vec3> points;
  for (const std::vector<KnotTick>& curve : marks.ticks())
    for (const KnotTick& k : curve) points.push_back(k.point);
  for (const JointReport& j : marks.joints()) points.push_back(j.position);
  return points;
}

void draw_curve_marks(const OverlayFrame& o) {
  if (!o.curve_marks) return;
  const CurveMarks& marks = *o.curve_marks;
  if (marks.ticks().empty()) return;
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  dl->PushClipRect(ImVec2(float(o.rect.x), float(o.rect.y)),
                   ImVec2(float(o.rect.x + o.rect.width), float(o.rect.y + o.rect.height)), true);
  const WindowProjector project(o.camera, o.rect);
  const float s = o.ui_scale;
  const ImU32 ink = rgba(palette::kInk), halo = rgba(palette::kPanel, 0.85f);
  const ImU32 faint_ink = rgba(palette::kInk, kHiddenAlpha),
              faint_halo = rgba(palette::kPanel, 0.85f * kHiddenAlpha);
  // Whether the n-th point of curve_mark_points is seen.
  std::size_t index = 0;
  auto seen = [&o](std::size_t n) {
    return !o.marks_seen || n >= o.marks_seen->size() || (*o.marks_seen)[n] != 0;
  };
  // Curve ends at a joint get the joint's ring instead of their ticks.
  std::set<std::pair<int, bool>> joined;
  for (const JointReport& j : marks.joints())
    for (int k = 0; k < 2; ++k) joined.emplace(j.curves[k], j.at_start[k]);
  for (std::size_t c = 0; c < marks.ticks().size(); ++c) {
    std::optional<Vec2> last;  // the last tick drawn on this curve
    for (const KnotTick& k : marks.ticks()[c]) {
      const bool visible = seen(index++);
      if (k.end && joined.count({int(c), k.t == marks.ticks()[c].front().t})) continue;
      const auto t = tick_on_screen(project, k, tick_length_px(k, 11.0 * s));
      if (!t) continue;
      // A long spline seen small: simple knots closer than a few pixels to the last tick are
      // left out (a solid band of ticks says nothing); ends and multiple knots always show.
      if (!k.end && k.multiplicity == 1 && last && glm::length(t->centre - *last) < 5.0 * s)
        continue;
      last = t->centre;
      const float w = (k.end ? 2.4f : 1.6f) * s;
      dl->AddLine(im(t->a), im(t->b), visible ? halo : faint_halo, w + 2.0f * s);
      dl->AddLine(im(t->a), im(t->b), visible ? ink : faint_ink, w);
      if (visible && !k.end && k.multiplicity > 1) {
        const std::string label = std::to_string(k.multiplicity) + "x";
        const ImVec2 size = ImGui::CalcTextSize(label.c_str());
        const Vec2 at = t->b + 4.0 * s * t->across;
        // Beyond the tick's end, on the side it points to.
        const ImVec2 corner(float(at.x + (t->across.x < 0 ? -size.x : 0.0)),
                            float(at.y + (t->across.y < 0 ? -size.y : 0.0)));
        dl->AddRectFilled(ImVec2(corner.x - 2 * s, corner.y - 1 * s),
                          ImVec2(corner.x + size.x + 2 * s, corner.y + size.y + 1 * s), halo,
                          3 * s);
        dl->AddText(corner, ink, label.c_str());
      }
    }
  }
  // Joints: a ring on the joint and its label at the upper right.
  for (const JointReport& j : marks.joints()) {
    const bool visible = seen(index++);
    const auto p = project(j.position);
    if (!p) continue;
    const int g = joint_continuity(j, marks.size());
    const float alpha = visible ? 1.0f : kHiddenAlpha;
    const ImU32 colour = rgba(joint_colour(g), alpha);
    dl->AddCircle(im(*p), 7.0f * s, visible ? halo : faint_halo, 0, 4.0f * s);
    dl->AddCircle(im(*p), 7.0f * s, colour, 0, 2.0f * s);
    if (!visible) continue;  // the label of a joint behind a surface would read as in front
    const std::string label = joint_label(j, marks.size());
    const ImVec2 size = ImGui::CalcTextSize(label.c_str());
    const ImVec2 corner(float(p->x + 12 * s), float(p->y - 12 * s - size.y));
    dl->AddRectFilled(ImVec2(corner.x - 4 * s, corner.y - 2 * s),
                      ImVec2(corner.x + size.x + 4 * s, corner.y + size.y + 2 * s),
                      rgba(palette::kPanel, 0.92f), 4 * s);
    dl->AddRect(ImVec2(corner.x - 4 * s, corner.y - 2 * s),
                ImVec2(corner.x + size.x + 4 * s, corner.y + size.y + 2 * s), colour, 4 * s, 0,
                1.5f * s);
    dl->AddText(corner, ink, label.c_str());
  }
  dl->PopClipRect();
}

}  // namespace pl
