// The New Curve tool: each click puts a point on the work plane (or on the surface under the
// cursor); Enter makes a free curve of the chosen type through/with the points (AddCurveCommand:
// a Bézier of the points, a clamped cubic B-spline or NURBS, the interpolating cubic of four
// points, the Hermite curve from the first to the last point); Esc drops the points. The new
// curve's last point is selected, so the Selection section shows the curve. GUI-free and
// unit-tested.
#pragma once

#include "app/editor/logic/tool.hpp"

namespace pl {

class NewCurveTool final : public ClickTool {
 public:
  NewCurveTool() : ClickTool("New Curve", "B") {}
  std::string hint() const override;
  void click(ToolContext& ctx, const PointerEvent& e) override;
  void hover(ToolContext& ctx, const PointerEvent& e) override { cursor_ = placement(ctx, e); }
  void cancel(ToolContext&) override { points_.clear(); }
  bool capturing() const override { return !points_.empty(); }
  bool can_finish(const ToolContext& ctx) const override;
  void finish(ToolContext& ctx) override;
  ToolPreview preview(const ToolContext& ctx) const override;
  bool places_on_work_plane() const override { return true; }

  CurveType type() const { return type_; }
  void set_type(CurveType t) { type_ = t; }
  const std::vector<Vec3>& points() const { return points_; }
  // The points the type needs at least (interpolating: exactly 4).
  std::size_t points_needed() const;

 private:
  bool enough_points() const;
  CurveType type_ = CurveType::BSpline;
  std::vector<Vec3> points_;
};

}  // namespace pl
