#include "app/editor/logic/tool.hpp"

namespace pl {

namespace {

// Lends a command to the document (which consumes what it executes) while the caller keeps it.
class SharedCommand final : public Command {
 public:
  explicit SharedCommand(std::shared_ptr<Command> c) : c_(std::move(c)) {}
  void apply(Scene& scene) override { c_->apply(scene); }
  std::string label() const override { return c_->label(); }
  std::string merge_key() const override { return c_->merge_key(); }

 private:
  std::shared_ptr<Command> c_;
};

}  // namespace

bool run_command(Document& doc, const std::function<void(const std::string&)>& say,
                 std::shared_ptr<Command> command) {
  try {
    const std::string label = doc.execute(std::make_unique<SharedCommand>(std::move(command)));
    if (say) say(label);
    return true;
  } catch (const EditRefused& e) {
    if (say) say(std::string("refused: ") + e.what());
    return false;
  }
}

bool run_command(ToolContext& ctx, std::shared_ptr<Command> command) {
  return run_command(ctx.doc, ctx.say, std::move(command));
}

std::optional<Snapped> snapping(const ToolContext& ctx, const PointerEvent& e) {
  if (!ctx.work_plane.snap || e.alt) return std::nullopt;
  if (auto s =
          snap_to_scene(ctx.doc.scene(), ctx.camera, e.rect, e.pixel, kSnapRadiusPx * ctx.ui_scale))
    return s;
  if (e.under && e.under->surface) return std::nullopt;  // on a surface: that point
  return snap_to_grid(ctx.work_plane, ctx.camera, e.rect, e.pixel);
}

std::optional<Vec3> placement(const ToolContext& ctx, const PointerEvent& e) {
  return placement(ctx, e, snapping(ctx, e));
}

std::optional<Vec3> placement(const ToolContext& ctx, const PointerEvent& e,
                              const std::optional<Snapped>& snapped) {
  if (snapped) return snapped->point;
  if (e.under && e.under->surface) return e.under->surface->position;
  return ctx.work_plane.hit(ctx.camera, window_ray(ctx.camera, e.rect, e.pixel));
}

int vertex_under(const PointerEvent& e) {
  if (!e.under || !e.under->item) return -1;
  const SelectionItem& i = *e.under->item;
  return i.kind == SelectionItem::Kind::Point && i.point.kind == PointRef::Kind::NetworkVertex
             ? i.point.index
             : -1;
}

void ToolBox::add(std::unique_ptr<Tool> tool) {
  tools_.push_back(std::move(tool));
}

bool ToolBox::activate(std::size_t i, ToolContext& ctx) {
  if (i >= tools_.size()) return false;
  if (i != active_) active().cancel(ctx);
  active_ = i;
  return true;
}

}  // namespace pl
