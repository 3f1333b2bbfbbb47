#version 330 core
// Overlay lines and points: positions in model space, a per-vertex tag (point kind) and offset
// (comb teeth: the vertex is drawn at position + u_offset_scale * offset, so a new comb scale
// costs a uniform, not an upload; other lines and points have no offset array and read the
// constant 0). Teeth are shortened on the CPU before the float conversion (GpuCombs), so
// length(o) stays finite.
layout(location = 0) in vec3 a_position;
layout(location = 1) in float a_tag;
layout(location = 2) in vec3 a_offset;
uniform mat4 u_view_projection;
uniform float u_offset_scale;
uniform float u_offset_max;  // longest drawn offset in model units; <= 0: no cap
out float g_tag;

void main() {
  g_tag = a_tag;
  vec3 o = u_offset_scale * a_offset;
  float len = length(o);
  if (u_offset_max > 0.0 && len > u_offset_max) o *= u_offset_max / len;
  gl_Position = u_view_projection * vec4(a_position + o, 1.0);
}
