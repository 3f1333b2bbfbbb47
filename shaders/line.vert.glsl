#version 330 core
// Overlay lines and points: positions in model space, a per-vertex tag (point kind).
layout(location = 0) in vec3 a_position;
layout(location = 1) in float a_tag;
uniform mat4 u_view_projection;
out float g_tag;

void main() {
  g_tag = a_tag;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
