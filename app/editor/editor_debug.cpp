// What scripts and the end-to-end tests read back from a running editor (--debug-point): where
// objects are on screen, the selection after each change, the context menu's items, the saves.
// Lines on stdout:
//   debug-point X Y window WX WY world-per-pixel S right RX RY RZ up UX UY UZ   (a point)
//   debug-face NAME X Y window WX WY      (a pixel that selects the face, patch or edge NAME;
//   debug-edge NAME X Y window WX WY       NAME as "face 1", "edge 3", "patch 0")
//   selection: ITEM, ITEM, ...            (after every change; "selection: none" when empty)
//   menu-item LABEL X Y window WX WY      (the centre of each context-menu item, once laid out)
//   saved PATH revision N
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdio>
#include <iostream>

#include "app/editor/editor.hpp"

namespace pl {

void Editor::report_debug_items() {
  if (!debugging() || debug_.positions || !views_.ready()) return;
  const auto rects = layout().panels(views_.compare());
  const Camera& camera = nav_.camera();
  int wx = 0, wy = 0;
  glfwGetWindowPos(window_.handle(), &wx, &wy);
  for (const SelectionItem& item : options_.debug_items) {
    if (!item_exists(session_.doc().scene(), item)) {
      std::cout << "debug-missing " << describe(item) << std::endl;
      continue;
    }
    if (item.kind == SelectionItem::Kind::Point) {
      const Vec3 p = point_position(session_.doc().scene(), item.point);
      const auto s = project_to_window(camera, rects[0], p);
      if (!s) return;  // not in view yet: try again next frame
      const double wpp = world_per_pixel(camera, rects[0], p);
      const Vec3 r = camera.right(), u = camera.up();
      std::printf(
          "debug-point %.3f %.3f window %d %d world-per-pixel %.17g right %.17g %.17g %.17g "
          "up %.17g %.17g %.17g\n",
          s->x, s->y, wx, wy, wpp, r.x, r.y, r.z, u.x, u.y, u.z);
      continue;
    }
    std::vector<SelectionItem> items;
    const DisplaySettings& d = prefs_.display;
    const auto px = find_pixel_for(pickers_[0], pick_scene(0, items), camera, rects[0], item,
                                   {d.control_net, d.network_curves});
    const char* kind = item.kind == SelectionItem::Kind::Edge ? "debug-edge" : "debug-face";
    if (px)
      std::printf("%s %s %.3f %.3f window %d %d\n", kind, describe(item).c_str(), px->x, px->y, wx,
                  wy);
    else
      std::printf("%s %s hidden\n", kind, describe(item).c_str());
  }
  std::fflush(stdout);
  debug_.positions = true;
}

void Editor::report_selection_change() {
  if (selection_.serial() == debug_.selection) return;
  debug_.selection = selection_.serial();
  std::cout << "selection: " << (selection_.empty() ? "none" : describe(selection_, 64))
            << std::endl;
}

void Editor::report_menu_item(const std::string& label, float x0, float y0, float x1, float y1) {
  int wx = 0, wy = 0;
  glfwGetWindowPos(window_.handle(), &wx, &wy);
  std::printf("menu-item %s %.1f %.1f window %d %d\n", label.c_str(), 0.5 * (x0 + x1),
              0.5 * (y0 + y1), wx, wy);
  std::fflush(stdout);
}

}  // namespace pl
