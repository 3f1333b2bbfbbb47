// The small window F2 (or Rename in a menu) opens to name the selected face or edge: the current
// name typed in and selected, Enter applies it, Esc or a click elsewhere leaves it. What a name
// means is the editor's (a SetFaceNameCommand or SetEdgeNameCommand). ImGui code.
#pragma once

#include <optional>
#include <string>

#include "app/editor/logic/selection.hpp"

namespace pl {

class RenamePopup {
 public:
  void open(const SelectionItem& item, const std::string& name);
  // Draws it while open; returns the item and the name typed once Enter is pressed.
  std::optional<std::pair<SelectionItem, std::string>> draw(float ui_scale);

 private:
  SelectionItem item_;
  char name_[256] = {};
  bool open_request_ = false;
};

}  // namespace pl
