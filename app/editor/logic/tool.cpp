#include "app/editor/logic/tool.hpp"

namespace pl {

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
