#version 330 core
// A round dot with a dark rim, coloured by control point kind.
uniform float u_size;
uniform float u_alpha;
uniform vec3 u_kind_colors[4];  // Boundary, Inner, Twin, Central (core ControlPointKind order)
flat in float f_tag;
in vec2 f_uv;
out vec4 frag_color;

void main() {
  float h = 0.5 * u_size + 1.0;
  float d = length(f_uv) * h;  // pixels from the centre
  float r = 0.5 * u_size;
  float a = 1.0 - smoothstep(r - 0.5, r + 0.5, d);
  if (a <= 0.0) discard;
  vec3 c = u_kind_colors[clamp(int(f_tag + 0.5), 0, 3)];
  // A dark rim a quarter of the radius wide (at most 1.5 px) keeps small dots coloured.
  float rim = min(0.25 * r, 1.5);
  c = mix(c, vec3(0.08), smoothstep(r - rim - 0.5, r - rim + 0.5, d));
  frag_color = vec4(c, a * u_alpha);
}
