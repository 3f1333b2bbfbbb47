#version 330 core
// Expands each segment into a screen-space quad `u_width` pixels wide: core profiles do not
// guarantee wide lines.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;
uniform vec2 u_viewport_size;  // pixels
uniform float u_width;         // pixels
uniform float u_depth_bias;    // in NDC depth: pulls lines in front of the surface they lie on
out float f_across;            // -1 .. 1 across the line, for antialiasing

void main() {
  vec4 a = gl_in[0].gl_Position;
  vec4 b = gl_in[1].gl_Position;
  if (a.w <= 0.0 || b.w <= 0.0) return;  // behind the eye: not worth clipping for overlays
  vec2 sa = a.xy / a.w * u_viewport_size;
  vec2 sb = b.xy / b.w * u_viewport_size;
  vec2 d = sb - sa;
  float len = length(d);
  vec2 dir = len > 1e-6 ? d / len : vec2(1.0, 0.0);
  // Half width plus one pixel of feather, extended along the line to close joints.
  float h = 0.5 * u_width + 1.0;
  vec2 normal = vec2(-dir.y, dir.x) * h / u_viewport_size * 2.0;
  vec2 along = dir * h / u_viewport_size;
  a.z -= u_depth_bias * a.w;
  b.z -= u_depth_bias * b.w;
  gl_Position = a + vec4((normal - along) * a.w, 0.0, 0.0); f_across = 1.0; EmitVertex();
  gl_Position = a + vec4((-normal - along) * a.w, 0.0, 0.0); f_across = -1.0; EmitVertex();
  gl_Position = b + vec4((normal + along) * b.w, 0.0, 0.0); f_across = 1.0; EmitVertex();
  gl_Position = b + vec4((-normal + along) * b.w, 0.0, 0.0); f_across = -1.0; EmitVertex();
  EndPrimitive();
}
