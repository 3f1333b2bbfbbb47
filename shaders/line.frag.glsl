#version 330 core
uniform vec4 u_color;  // sRGB + alpha
uniform float u_width;
in float f_across;
out vec4 frag_color;

void main() {
  float h = 0.5 * u_width + 1.0;
  float d = abs(f_across) * h;  // pixels from the centre line
  float a = 1.0 - smoothstep(0.5 * u_width - 0.5, 0.5 * u_width + 0.5, d);
  if (a <= 0.0) discard;
  frag_color = vec4(u_color.rgb, u_color.a * a);
}
