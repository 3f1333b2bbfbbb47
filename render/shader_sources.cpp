#include "render/shader_sources.hpp"

#include <stdexcept>
#include <string>

namespace pl {

std::string_view shader_source(std::string_view name) {
  for (const EmbeddedShader& s : embedded_shaders())
    if (s.name == name) return s.source;
  throw std::runtime_error("shader " + std::string(name) + " is not embedded in this build");
}

}  // namespace pl
