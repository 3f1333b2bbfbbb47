// The view's camera and the mouse gestures that move it: orbit (left drag where the active tool
// does not take the press: a turntable about a pivot), pan (right or middle drag), zoom (wheel,
// towards the cursor), framing and the preset views. A press and release that barely moved is
// a click, not a gesture: end() says so, and the editor hands the click to the active tool (or
// opens the context menu for the right button). GUI-free and unit-tested.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "app/editor/logic/camera_control.hpp"
#include "render/draw_scene.hpp"

namespace pl {

class ViewNavigator {
 public:
  enum class Gesture { None, Orbit, Pan };

  const Camera& camera() const { return camera_; }
  Camera& camera() { return camera_; }

  // Until framed, the editor frames the scene on the next frame it draws (a new document).
  bool framed() const { return framed_; }
  void unframe() { framed_ = false; }
  // What a view frames when nothing is drawn (a new scene): the cube [-1, 1]^3 about the origin,
  // where the work plane's new points go.
  static Box empty_scene_box() { return Box{Vec3(-1), Vec3(1)}; }
  // Frame All's room around the scene: a point farthest out projects at most 1 / kFrameMargin of
  // the way from the view's centre to its edge (6 % of the view's width and height to spare).
  static constexpr double kFrameMargin = 1.12;

  // Shows all of `box` from the current direction; an empty box: empty_scene_box().
  void frame(const Box& box, double aspect);
  // Frame All (F): `points` (everything drawn, the combs' tips too when shown) from the current
  // direction, every one inside the view with kFrameMargin to spare, in perspective as in
  // orthographic views. No points: empty_scene_box().
  void frame_all(std::span<const Vec3> points, double aspect);
  // Shows `box` closely (Shift+F), at least 8 % of the scene radius across, keeping the clipping
  // planes sized for the whole scene.
  void frame_closely(const Box& box, double aspect);
  // A preset direction framing `scene` (empty: empty_scene_box(), so a new scene can be seen
  // from the top before anything is drawn); keeps orthographic or perspective.
  void preset(ViewPreset preset, const Box& scene, double aspect);
  // The view a document opens with: default_camera of the scenes drawn side by side, which
  // faces a single patch's front (a .gbp seen from behind would show its back) and frames what
  // is drawn tightly at this panel aspect, so each half of the comparison is filled. With
  // nothing drawn (a new scene): the iso view of the cube [-1, 1]^3, where new points go.
  void open_view(std::span<const DrawScene* const> scenes, double aspect);
  // Frames what the scenes draw tightly (Camera::frame_points) from the current direction.
  void frame_tightly(std::span<const DrawScene* const> scenes, double aspect);

  // Called every frame with the window size, the number of panes shown (1, or the comparison's)
  // and the width of the first panel. When the panel width changed while the window and the
  // split did not (the
  // legend column came or went), zooms so the panel keeps showing the same width of the world:
  // a model framed across it is not cut by the new column, and comes back to its size when the
  // column goes. A window resize keeps the vertical extent, as every view does.
  void follow_panel(const Vec2& window, int panes, double width);

  // Gestures: begin at the press, move with every cursor position, end at the release. An
  // orbit keeps the model (`model`: a sample of its points, orbit_sample) on screen about any
  // pivot (keep_in_view).
  void begin(Gesture gesture, const Vec2& pixel, const Vec3& pivot, std::vector<Vec3> model = {});
  void move(const Vec2& pixel, const ViewRect& rect);
  // Ends the gesture. True when it was a click: the cursor never went further than the slop
  // from where it was pressed.
  bool end();
  Gesture gesture() const { return gesture_; }
  void wheel(const ViewRect& rect, const Vec2& pixel, double notches);

  static constexpr double kClickSlopPx = 3.0;
  static constexpr double kWheelZoom = 1.15;  // per notch

 private:
  // Framed at the panel as it is now: the next follow_panel only records its width.
  void mark_framed() {
    framed_ = true;
    panel_.width = 0;
  }

  Camera camera_;
  bool framed_ = false;
  struct PanelShape {
    Vec2 window{0.0};
    int panes = 1;
    double width = 0;
  } panel_;
  Gesture gesture_ = Gesture::None;
  Vec3 pivot_{0.0};
  std::vector<Vec3> model_;         // kept on screen while orbiting
  std::optional<ScreenBox> start_;  // where it was on screen when the orbit began
  Vec2 press_{0.0}, last_{0.0};
  double travel_ = 0;  // furthest distance from the press
};

// At most `most` of the points the scenes draw (surface samples, net points, curve points),
// evenly spread: what an orbit keeps on screen, cheap to project at every mouse move.
std::vector<Vec3> orbit_sample(std::span<const DrawScene* const> scenes, std::size_t most = 4096);

}  // namespace pl
