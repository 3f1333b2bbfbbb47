// The editor's glue for authoring: the selection, the active tool and the hover state follow
// structural edits (an undone split or delete renumbers the network: what they held is dropped),
// the active tool's feedback and the selected vertices' tangent planes are drawn over the view,
// and F2 names the selected face or edge.
#include <imgui.h>

#include "app/document/network_commands.hpp"
#include "app/editor/editor.hpp"
#include "app/editor/logic/plane_handles.hpp"
#include "app/editor/viewport_overlays.hpp"

namespace pl {

void Editor::follow_structure() {
  const Selection::Followed f = selection_.follow(session_.doc().scene());
  // What was picked under the mouse came from the network as it was.
  if (selection_.structure_serial() != mouse_.structure) {
    mouse_.structure = selection_.structure_serial();
    mouse_.under = {};
    mouse_.pressed = {};
  }
  // Indices may name other objects now: the tool's picks go too.
  if (f == Selection::Followed::Cleared) {
    ToolContext ctx = tool_context();
    tools_.active().cancel(ctx);
  }
}

void Editor::draw_tool_feedback() {
  if (!views_.ready()) return;
  ToolContext ctx = tool_context();
  const ToolPreview preview = tools_.active().preview(ctx);
  const auto rects = layout().panels(views_.panels());
  const ImGuiIO& io = ImGui::GetIO();
  const Vec2 mouse(io.MousePos.x, io.MousePos.y);
  // The tangent-plane discs and their knobs belong to the select tool, which drags the knobs.
  const bool planes = tools_.active_index() == 0;
  for (std::size_t i = 0; i < rects.size(); ++i) {
    std::vector<PlaneHandle> handles;
    if (planes)
      handles =
          plane_handles(session_.doc().scene(), selection_, nav_.camera(), rects[i], ui_scale_);
    const int hot = int(i) == mouse_.panel ? pick_knob(handles, nav_.camera(), rects[i], mouse,
                                                       kKnobPickRadiusPx * ui_scale_)
                                           : -1;
    draw_tool_overlays(rects[i], nav_.camera(), preview, handles, hot, ui_scale_);
  }
}

void Editor::start_rename() {
  const Scene& scene = session_.doc().scene();
  if (selection_.size() != 1 || !scene.network) return;
  const SelectionItem& item = selection_.items()[0];
  if (!item_exists(scene, item)) return;
  if (item.kind == SelectionItem::Kind::Face)
    rename_.open(item, scene.network->faces[item.index].name);
  else if (item.kind == SelectionItem::Kind::Edge)
    rename_.open(item, scene.network->edges[item.index].name);
}

void Editor::draw_rename() {
  const auto done = rename_.draw(ui_scale_);
  if (!done) return;
  const auto& [item, name] = *done;
  const Scene& scene = session_.doc().scene();
  if (!item_exists(scene, item)) return;  // gone meanwhile
  const bool face = item.kind == SelectionItem::Kind::Face;
  if (name ==
      (face ? scene.network->faces[item.index].name : scene.network->edges[item.index].name))
    return;  // unchanged: no undo step
  std::shared_ptr<Command> c;
  if (face)
    c = std::make_shared<SetFaceNameCommand>(item.index, name);
  else
    c = std::make_shared<SetEdgeNameCommand>(item.index, name);
  run_command(
      session_.doc(), [this](const std::string& m) { status_.say(m); }, c);
}

}  // namespace pl
