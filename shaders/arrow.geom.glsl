#version 330 core
// A derivative arrow from its base point to its tip: a shaft u_width pixels wide and a solid head
// u_head pixels long at the tip, both in screen space so arrows read the same at any zoom. A head
// never takes more than 60 % of a short arrow; an arrow shorter than a pixel is not drawn.
layout(lines) in;
layout(triangle_strip, max_vertices = 7) out;
uniform vec2 u_viewport_size;  // pixels
uniform float u_width;         // pixels
uniform float u_head;          // pixels
uniform float u_depth_bias;    // NDC depth, as for lines
in float g_tag[];
flat out float f_tag;
out float f_across;  // -1 .. 1 across the shaft, 0 on the head

void main() {
  vec4 a = gl_in[0].gl_Position;
  vec4 b = gl_in[1].gl_Position;
  if (a.w <= 0.0 || b.w <= 0.0) return;
  a.z -= u_depth_bias * a.w;
  b.z -= u_depth_bias * b.w;
  vec2 sa = a.xy / a.w * 0.5 * u_viewport_size;
  vec2 sb = b.xy / b.w * 0.5 * u_viewport_size;
  float len = length(sb - sa);
  if (len < 1.0) return;
  vec2 dir = (sb - sa) / len;
  vec2 nrm = vec2(-dir.y, dir.x);
  float head = min(u_head, 0.6 * len);
  float t = 1.0 - head / len;  // where the head starts (screen-space fraction, close enough)
  vec4 c = mix(a, b, t);
  f_tag = g_tag[0];
  // Shaft: half width plus a pixel of feather.
  float h = 0.5 * u_width + 1.0;
  vec2 off_a = nrm * h / u_viewport_size * 2.0;
  gl_Position = a + vec4(off_a * a.w, 0.0, 0.0); f_across = 1.0; EmitVertex();
  gl_Position = a - vec4(off_a * a.w, 0.0, 0.0); f_across = -1.0; EmitVertex();
  gl_Position = c + vec4(off_a * c.w, 0.0, 0.0); f_across = 1.0; EmitVertex();
  gl_Position = c - vec4(off_a * c.w, 0.0, 0.0); f_across = -1.0; EmitVertex();
  EndPrimitive();
  // Head: a triangle 0.9 head lengths wide.
  vec2 wing = nrm * 0.45 * head / u_viewport_size * 2.0;
  gl_Position = c + vec4(wing * c.w, 0.0, 0.0); f_across = 0.0; EmitVertex();
  gl_Position = c - vec4(wing * c.w, 0.0, 0.0); f_across = 0.0; EmitVertex();
  gl_Position = b; f_across = 0.0; EmitVertex();
  EndPrimitive();
}
