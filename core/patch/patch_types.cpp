#include "core/patch/patch_types.hpp"

namespace pl {

void throw_unregistered_patch_type(const Patch& patch) {
  throw std::logic_error("patch type \"" + patch.type() +
                         "\" is not registered in core/patch/patch_types.hpp");
}

std::vector<std::string> patch_type_names() {
  std::vector<std::string> names;
  for_each_patch_type([&]<class T>() { names.emplace_back(T::kType); });
  return names;
}

}  // namespace pl
