#version 330 core
// Expands each control point into a screen-space square: u_size pixels wide for an editable
// point, u_derived_scale times that for a derived one.
layout(points) in;
layout(triangle_strip, max_vertices = 4) out;
uniform vec2 u_viewport_size;
uniform float u_size;
uniform float u_derived_scale;
in float g_tag[];
flat out float f_tag;
flat out float f_size;  // pixels
out vec2 f_uv;          // -1 .. 1 over the square

void main() {
  vec4 p = gl_in[0].gl_Position;
  if (p.w <= 0.0) return;
  float size = g_tag[0] >= 7.5 ? u_size * u_derived_scale : u_size;
  // Half the size plus a pixel of feather, and room for the triangle's corners.
  vec2 r = vec2(0.8 * size + 1.0) / u_viewport_size * 2.0 * p.w;
  for (int i = 0; i < 4; ++i) {
    vec2 c = vec2(i % 2 == 0 ? -1.0 : 1.0, i < 2 ? -1.0 : 1.0);
    gl_Position = p + vec4(c * r, 0.0, 0.0);
    f_uv = c;
    f_tag = g_tag[0];
    f_size = size;
    EmitVertex();
  }
  EndPrimitive();
}
