#include "app/editor/logic/new_curve_tool.hpp"

#include "render/draw_scene_builder.hpp"
#include "app/document/curve_commands.hpp"

namespace pl {

std::string NewCurveTool::hint() const {
  return "click the points of a new curve on the work plane; Enter makes it, Esc drops the points";
}

std::size_t NewCurveTool::points_needed() const {
  return type_ == CurveType::Interpolating ? 4 : 2;
}

bool NewCurveTool::enough_points() const {
  return type_ == CurveType::Interpolating ? points_.size() == 4
                                           : points_.size() >= points_needed();
}

void NewCurveTool::click(ToolContext& ctx, const PointerEvent& e) {
  const std::optional<Vec3> at = placement(ctx, e);
  if (!at) {
    ctx.say("no work plane under the cursor: turn the view or move the plane");
    return;
  }
  points_.push_back(*at);
  ctx.say(std::string(curve_type_name(type_)) + " curve with " + std::to_string(points_.size()) +
          (points_.size() >= points_needed() ? " points: Enter makes it"
                                             : " points: click the next one"));
}

bool NewCurveTool::can_finish(const ToolContext&) const {
  return enough_points();
}

void NewCurveTool::finish(ToolContext& ctx) {
  if (!can_finish(ctx)) {
    ctx.say(type_ == CurveType::Interpolating ? "an interpolating cubic takes exactly 4 points"
                                              : "a curve needs at least 2 points");
    return;
  }
  auto command = std::make_shared<AddCurveCommand>(type_, points_);
  if (!run_command(ctx, command)) return;  // the points stay, to be put right
  points_.clear();
  const int c = command->curve();
  const int last = int(ctx.doc.scene().curves[c].points.size()) - 1;
  ctx.selection.set({SelectionItem::of_point(PointRef::curve_point(c, last))});
}

ToolPreview NewCurveTool::preview(const ToolContext&) const {
  ToolPreview p;
  p.picked = points_;
  if (points_.size() > 1) p.lines.push_back(points_);
  if (!points_.empty() && cursor_) p.pending.push_back({points_.back(), *cursor_});
  p.target = cursor_;
  // The curve Enter would make, drawn with the points' polygon.
  if (enough_points()) {
    Scene scratch;
    try {
      AddCurveCommand(type_, points_).apply(scratch);
      p.lines.push_back(free_curve_polyline(scratch.curves.front()));
    } catch (const EditRefused&) {
      // Nothing to show: Enter will say why.
    }
  }
  return p;
}

}  // namespace pl
