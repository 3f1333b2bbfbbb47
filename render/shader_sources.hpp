// The GLSL sources of shaders/, embedded at build time (render/embed_shaders.cmake).
#pragma once

#include <span>
#include <string_view>

namespace pl {

struct EmbeddedShader {
  std::string_view name;  // file name, e.g. "surface.frag.glsl"
  std::string_view source;
};

std::span<const EmbeddedShader> embedded_shaders();

// The source of one shader file; throws std::runtime_error naming it when it is not embedded.
std::string_view shader_source(std::string_view name);

}  // namespace pl
