#include "app/editor/viewport_painter.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "app/editor/gpu_view_copy.hpp"
#include "app/editor/logic/selection_properties.hpp"
#include "app/editor/theme.hpp"
#include "app/editor/viewport_overlays.hpp"
#include "render/depth_probe.hpp"
#include "render/frame.hpp"
#include "render/gl.hpp"

namespace pl {

namespace {

// The selection in the accent colour; what is under the cursor (what a click would select) in a
// fainter tint of it and white lines; the grid faint, its axes in the axis triad's colours.
// In the curvature colours neither is tinted (SceneRenderer::draw_selection): the outlines
// alone mark them, so a selected surface's outline is its border (a face's edges).
constexpr SelectionStyle kSelected = {{kAccent[0], kAccent[1], kAccent[2], 0.30f},
                                      {kAccent[0], kAccent[1], kAccent[2], 1.0f},
                                      3.5f,
                                      true};
constexpr SelectionStyle kHovered = {
    {kAccent[0], kAccent[1], kAccent[2], 0.13f}, {1.0f, 1.0f, 1.0f, 0.85f}, 3.0f, false};
constexpr std::array<float, 4> kGridLine = {0.42f, 0.44f, 0.50f, 0.55f};
// How far the grid reaches (in cells from its centre; its step: shown_grid_step).
constexpr int kGridHalfCells = 24;

// The colour of the world axis `a` points along (x red, y green, z blue, as the axis triad).
std::array<float, 4> axis_colour(const Vec3& a) {
  if (std::abs(a.x) > 0.5) return {0.85f, 0.25f, 0.25f, 0.8f};
  if (std::abs(a.y) > 0.5) return {0.3f, 0.7f, 0.3f, 0.8f};
  return {0.25f, 0.45f, 0.9f, 0.8f};
}

void append_segments(const Polyline& line, std::vector<Vec3>& out) {
  for (std::size_t k = 1; k < line.size(); ++k) {
    out.push_back(line[k - 1]);
    out.push_back(line[k]);
  }
}

// The key of what a panel's highlight arrays were built from: the live evaluation shown (coarse
// and fine have their own curves), its revision and the selection (or hover) state.
uint64_t guide_key(const LiveSurfaces& live, uint64_t state) {
  const auto p = reinterpret_cast<std::uintptr_t>(&live);
  return (static_cast<uint64_t>(p) * 0x9E3779B97F4A7C15ull) ^ (live.synced_revision() << 20) ^
         state;
}

uint64_t item_key(const std::optional<SelectionItem>& item) {
  if (!item) return 0;
  return (uint64_t(item->kind) + 1) << 56 ^ uint64_t(uint32_t(item->index)) << 24 ^
         uint64_t(uint32_t(item->point.object)) << 8 ^ uint64_t(uint32_t(item->point.index));
}

}  // namespace

void ViewportPainter::update_guides(const ViewportFrame& f, int panel, bool colour_mode) {
  PanelGuides& g = guides_[panel];
  const LiveSurfaces& live = f.model->views().panel(panel).shown();
  // Per surface, its border polylines (per domain side): the outline of a selected patch, and
  // of the surface under the cursor where it gets no tint.
  const auto& borders = f.model->views().panel(panel).curves().borders();
  auto append_borders = [&](int s, std::vector<Vec3>& out) {
    if (s >= 0 && s < int(borders.size()))
      for (const CurvatureComb& side : borders[s]) append_segments(side.points, out);
  };
  const Scene& scene = f.model->doc().scene();
  const auto& curves = live.draw().network_curves;
  const auto& free_curves = live.draw().free_curves;
  // Which face or patch each surface draws (built only when a highlight changes).
  std::vector<SelectionItem> items;
  auto surface_item = [&](std::size_t s) -> const SelectionItem& {
    if (items.empty()) items = surface_items(live.surfaces());
    return items[s];
  };
  const std::size_t surfaces = live.surfaces().surfaces.size();

  // The outlines depend on the display (a colour mode outlines the hovered surface too).
  const uint64_t mode_key = colour_mode ? 0x5bd1e995ull : 0;
  const uint64_t selected_key = guide_key(live, f.model->selection().serial()) ^ mode_key;
  if (selected_key != g.selected_key) {
    g.selected_key = selected_key;
    std::vector<Vec3> lines;
    std::vector<int> edges = f.model->selection().of_kind(SelectionItem::Kind::Edge);
    const std::vector<int> faces = f.model->selection().of_kind(SelectionItem::Kind::Face);
    if (scene.network)
      for (const std::vector<int>& sides : face_edges(*scene.network, faces))
        edges.insert(edges.end(), sides.begin(), sides.end());
    for (int e : edges)
      if (e >= 0 && e < int(curves.size())) append_segments(curves[e], lines);
    for (int c : f.model->selection().of_kind(SelectionItem::Kind::Curve))
      if (c >= 0 && c < int(free_curves.size())) append_segments(free_curves[c], lines);
    g.selected_surfaces.clear();
    const std::set<int> faces_set(faces.begin(), faces.end());
    const std::vector<int> patches = f.model->selection().of_kind(SelectionItem::Kind::Patch);
    const std::set<int> patch_set(patches.begin(), patches.end());
    if (!faces_set.empty() || !patch_set.empty())
      for (std::size_t s = 0; s < surfaces; ++s) {
        const SelectionItem& i = surface_item(s);
        if ((i.kind == SelectionItem::Kind::Face ? faces_set : patch_set).count(i.index)) {
          g.selected_surfaces.push_back(int(s));
          // A face is outlined by its edges (above); a patch by its border.
          if (i.kind == SelectionItem::Kind::Patch) append_borders(int(s), lines);
        }
      }
    if (!lines.empty() || !g.selected.empty()) g.selected.set(lines, {});
  }

  const std::optional<SelectionItem> hovered =
      panel == f.model->mouse().panel ? f.model->mouse().under.item : std::nullopt;
  const uint64_t hovered_key =
      guide_key(live, item_key(hovered)) ^ mode_key ^ (f.model->selection().serial() << 40);
  if (hovered_key != g.hovered_key) {
    g.hovered_key = hovered_key;
    std::vector<Vec3> lines;
    g.hovered_surface = -1;
    if (hovered && hovered->kind == SelectionItem::Kind::Edge &&
        hovered->index < int(curves.size()))
      append_segments(curves[hovered->index], lines);
    if (hovered && hovered->kind == SelectionItem::Kind::Curve &&
        hovered->index < int(free_curves.size()))
      append_segments(free_curves[hovered->index], lines);
    if (hovered && hovered->kind != SelectionItem::Kind::Point)
      for (std::size_t s = 0; s < surfaces; ++s)
        if (surface_item(s) == *hovered) g.hovered_surface = int(s);
    // A selected surface keeps its selection's outline alone.
    if (colour_mode && std::find(g.selected_surfaces.begin(), g.selected_surfaces.end(),
                                 g.hovered_surface) == g.selected_surfaces.end())
      append_borders(g.hovered_surface, lines);
    if (!lines.empty() || !g.hovered.empty()) g.hovered.set(lines, {});
  }

  if (f.model->work_plane().shown) {
    // Sized to the view at the camera's target, centred where the target meets the plane.
    const Camera& c = f.model->nav().camera();
    const PlaneFrame plane = f.model->work_plane().frame(c);
    const double step = shown_grid_step(c);
    // Within the clipping planes, which hug the scene (2 scene radii about the target).
    const int half_cells = std::clamp(int(1.8 * c.scene_radius / step), 1, kGridHalfCells);
    g.grid.set(grid_segments(plane, c.target, step, half_cells), {});
    const double reach = half_cells * step;
    const Vec2 centre = plane_coordinates(plane, c.target);
    // The plane's own axes through its origin (a view-aligned plane has none worth showing).
    std::vector<Vec3> u, v;
    if (f.model->work_plane().kind != WorkPlaneKind::View) {
      u = {plane.origin + (centre.x - reach) * plane.u,
           plane.origin + (centre.x + reach) * plane.u};
      v = {plane.origin + (centre.y - reach) * plane.v,
           plane.origin + (centre.y + reach) * plane.v};
    }
    g.axis_u.set(u, {});
    g.axis_v.set(v, {});
  }
}

void ViewportPainter::draw_panel_gl(const ViewportFrame& f, int panel, const ColorRange& range,
                                    const DisplaySettings& display) {
  const ViewRect& r = f.panels[panel];
  const auto [fbw, fbh] = f.window->framebuffer_size();
  const auto [ww, wh] = f.window->window_size();
  const double sx = ww > 0 ? double(fbw) / ww : 1.0;
  Viewport v;
  v.x = int(std::lround(r.x * sx));
  v.y = int(std::lround((wh - r.y - r.height) * sx));
  v.width = std::max(1, int(std::lround(r.width * sx)));
  v.height = std::max(1, int(std::lround(r.height * sx)));
  v.pixel_scale = sx * f.ui_scale;
  // While something moves and full-resolution frames would not hold the frame rate, the view is
  // drawn smaller and stretched onto the window (logic/draw_budget.hpp).
  const Viewport window_rect = v;
  const double scale = f.model->draw_budget().scale();
  bool reduced = false;
  if (scale < 1) {
    v = {0, 0, std::max(1, int(std::lround(v.width * scale))),
         std::max(1, int(std::lround(v.height * scale))), v.pixel_scale * scale};
    try {
      reduced_.bind(v.width, v.height);
      reduced = true;
    } catch (const std::exception&) {
      v = window_rect;  // the driver refused it: full resolution, as at rest
    }
  }
  glEnable(GL_SCISSOR_TEST);
  glScissor(v.x, v.y, v.width, v.height);
  glClear(GL_DEPTH_BUFFER_BIT);
  const SceneRenderer& renderer = *f.renderer;
  renderer.draw_backdrop(v);
  const Camera& camera = f.model->nav().camera();
  const GpuScene& gpu = gpu_of(f.model->views().panel(panel).copy());
  const ViewCopy* difference_copy =
      f.model->views().difference_scene(f.model->doc().revision(), panel);
  const GpuScene* difference = difference_copy ? &gpu_of(*difference_copy) : nullptr;
  DisplaySettings shown = display;
  if (difference) {
    shown.base = BaseMode::Curvature;
    shown.curvature = CurvatureKind::Mean;  // the field that holds the distance
    shown.curvature_lighting = true;
    const double m = f.model->views().difference_range();
    renderer.draw(*difference, camera, shown, {-m, m}, v);
  } else {
    renderer.draw(gpu, camera, display, range, v);
  }

  update_guides(f, panel, colours_carry_values(shown));
  const PanelGuides& g = guides_[panel];
  if (f.model->work_plane().shown) {
    renderer.draw_guides(g.grid, camera, kGridLine, 1.0f, true, v);
    const PlaneFrame plane = f.model->work_plane().frame(camera);
    renderer.draw_guides(g.axis_u, camera, axis_colour(plane.u), 1.6f, true, v);
    renderer.draw_guides(g.axis_v, camera, axis_colour(plane.v), 1.6f, true, v);
  }
  // Tints use the triangles of what was drawn: the difference copy has the same ones.
  const GpuScene& drawn = difference ? *difference : gpu;
  renderer.draw_selection(drawn, g.selected_surfaces, g.selected, camera, shown, kSelected, v);
  const bool hover_selected = std::find(g.selected_surfaces.begin(), g.selected_surfaces.end(),
                                        g.hovered_surface) != g.selected_surfaces.end();
  const int one[1] = {g.hovered_surface};
  renderer.draw_selection(drawn,
                          g.hovered_surface >= 0 && !hover_selected ? std::span<const int>(one)
                                                                    : std::span<const int>(),
                          g.hovered, camera, shown, kHovered, v);
  // The curve marks (knot ticks, joint labels) are drawn in 2D over the views later: which of
  // them a surface hides is read from this panel's depth now, while it is bound.
  const std::vector<Vec3> marks = curve_mark_points(f.model->curve_marks());
  guides_[panel].marks_seen = points_seen(camera, v, marks);
  if (reduced) {
    const Viewport& w = window_rect;
    glScissor(w.x, w.y, w.width, w.height);
    reduced_.blit_to_window(w.x, w.y, w.width, w.height);
  }
  glDisable(GL_SCISSOR_TEST);
}

void ViewportPainter::draw_progress(const ViewportFrame& f) {
  // A small opaque panel in the middle of the view: what is being done and how far it is.
  const float s = f.ui_scale;
  const ViewRect& r = f.viewport;
  const float w = float(std::min(420.0 * s, 0.8 * r.width));
  ImGui::SetNextWindowPos(ImVec2(float(r.x + r.width / 2), float(r.y + r.height / 2)),
                          ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(w, 0));
  ImGui::Begin("##loading", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoNav);
  const std::string& name = f.model->session().title();
  ImGui::TextUnformatted(("Opening " + name).c_str());
  const double fraction = f.model->views().load_fraction();
  char overlay[96];
  std::snprintf(overlay, sizeof overlay, "%.0f %%", 100 * fraction);
  ImGui::ProgressBar(float(fraction), ImVec2(-1, 0), overlay);
  ImGui::TextDisabled("%s ...", f.model->views().load_stage().c_str());
  ImGui::End();
}

void ViewportPainter::paint(const ViewportFrame& f, const ColorRange& range) {
  const auto [fbw, fbh] = f.window->framebuffer_size();
  glViewport(0, 0, fbw, fbh);
  glDisable(GL_SCISSOR_TEST);
  glClearColor(0.155f, 0.160f, 0.175f, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (f.model->views().loading()) {
    draw_progress(f);
    return;
  }
  if (!f.model->views().ready()) {
    draw_error_text(f.viewport, "Cannot show this scene:\n" + f.model->views().error());
    return;
  }
  // One comb scale for side-by-side panels, as one colour range.
  std::vector<const GpuScene*> scenes;
  for (int i = 0; i < f.model->views().panels(); ++i)
    scenes.push_back(&gpu_of(f.model->views().panel(i).copy()));
  const DisplaySettings display = common_comb_length(f.model->prefs().display, scenes);
  for (int i = 0; i < f.model->views().panels(); ++i) draw_panel_gl(f, i, range, display);

  for (int i = 0; i < f.model->views().panels(); ++i) {
    OverlayFrame o{f.panels[i],
                   f.model->nav().camera(),
                   f.model->views().panel(i).shown(),
                   f.model->prefs(),
                   f.model->selection(),
                   &f.model->continuity(),
                   i == f.model->mouse().panel ? &f.model->mouse().under : nullptr,
                   &f.model->mouse().probe,
                   f.ui_scale,
                   i,
                   &f.model->curve_marks(),
                   &guides_[i].marks_seen};
    draw_curve_marks(o);
    draw_point_overlays(o);
    if (f.model->views().panels() > 1) {
      const CompareSetup& setup = f.model->views().setup();
      draw_panel_label(
          o,
          compare_pane_title(
              setup.schemes[i], i == setup.base_pane(), f.model->views().showing_difference(),
              setup.base, o.rect.width - 24 * f.ui_scale,
              [](const std::string& t) { return double(ImGui::CalcTextSize(t.c_str()).x); }),
          f.viewport);
    }
    draw_axis_triad(o);
  }
}

}  // namespace pl
