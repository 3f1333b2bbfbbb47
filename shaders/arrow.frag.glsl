#version 330 core
// Arrows coloured by kind (ArrowKind order: tangent, twist); the shaft antialiased across like a
// line, the head by multisampling.
uniform vec3 u_colors[2];
uniform float u_alpha;
uniform float u_width;
flat in float f_tag;
in float f_across;
out vec4 frag_color;

void main() {
  float h = 0.5 * u_width + 1.0;
  float d = abs(f_across) * h;
  float a = 1.0 - smoothstep(0.5 * u_width - 0.5, 0.5 * u_width + 0.5, d);
  if (a <= 0.0) discard;
  frag_color = vec4(u_colors[clamp(int(f_tag + 0.5), 0, 1)], a * u_alpha);
}
