// The window's side of authoring: the active tool's feedback and the selected vertices' tangent
// planes drawn over the view, and the popup where F2 names the selected face or edge.
#include <imgui.h>

#include "app/editor/editor.hpp"
#include "app/editor/logic/plane_handles.hpp"
#include "app/editor/viewport_overlays.hpp"

namespace pl {

void Editor::draw_tool_feedback() {
  if (!model_.views().ready()) return;
  ToolContext ctx = model_.tool_context();
  const ToolPreview preview = model_.tools().active().preview(ctx);
  const auto rects = model_.layout().panels(model_.views().panels());
  const Camera& camera = model_.nav().camera();
  const ImGuiIO& io = ImGui::GetIO();
  const Vec2 mouse(io.MousePos.x, io.MousePos.y);
  // The tangent-plane discs and their knobs belong to the select tool, which drags the knobs.
  const bool planes = model_.tools().active_index() == 0;
  for (std::size_t i = 0; i < rects.size(); ++i) {
    std::vector<PlaneHandle> handles;
    if (planes)
      handles =
          plane_handles(model_.doc().scene(), model_.selection(), camera, rects[i], ui_scale_);
    const int hot = int(i) == model_.mouse().panel
                        ? pick_knob(handles, camera, rects[i], mouse, kKnobPickRadiusPx * ui_scale_)
                        : -1;
    draw_tool_overlays(rects[i], camera, preview, handles, hot, ui_scale_);
  }
}

void Editor::ask_name(const SelectionItem& item, const std::string& current) {
  rename_.open(item, current);
}

void Editor::draw_rename() {
  if (const auto done = rename_.draw(ui_scale_)) model_.rename(done->first, done->second);
}

}  // namespace pl
