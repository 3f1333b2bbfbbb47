#version 330 core
// A control point: its shape says its kind (boundary square, inner disc, twin diamond, central
// triangle, curve hexagon, free interior pentagon), its fill whether it is editable (filled with the kind's colour, dark outline) or
// derived (a ring of the kind's colour around a light centre). Shapes are signed distances in
// pixels, antialiased over one pixel.
uniform vec3 u_kind_colors[8];  // ControlPointKind order (the kinds there are)
uniform vec3 u_outline;
uniform vec3 u_derived_fill;
uniform float u_alpha;
flat in float f_tag;
flat in float f_size;
in vec2 f_uv;
out vec4 frag_color;

// Equilateral triangle pointing up, centred on its centroid, with inradius q: the largest distance
// past its three edges (exact inside and along the edges, which is what antialiasing needs).
float triangle(vec2 p, float q) {
  float e = max(-p.y, max(dot(p, vec2(0.8660254, 0.5)), dot(p, vec2(-0.8660254, 0.5))));
  return e - q;
}

// Signed distance to the outline of `kind` with nominal radius r (shapes of about equal area).
float shape(int kind, vec2 p, float r) {
  if (kind == 0) {
    vec2 d = abs(p) - vec2(0.86 * r);
    return length(max(d, 0.0)) + min(max(d.x, d.y), 0.0);
  }
  if (kind == 2) return (abs(p.x) + abs(p.y) - 1.2 * r) * 0.70710678;
  if (kind == 3) return triangle(p, 0.75 * r);
  // Hexagon, two vertices on the vertical, inradius 0.93 r (about the square's area).
  if (kind == 4) {
    vec2 q = abs(p);
    return max(dot(q, vec2(0.5, 0.8660254)), q.x) - 0.93 * r;
  }
  // Regular pentagon pointing up (a GB face's free point), inradius 0.86 r.
  if (kind == 5) {
    float e = max(-p.y, max(dot(p, vec2(0.9510565, -0.3090170)),
                            dot(p, vec2(-0.9510565, -0.3090170))));
    e = max(e, max(dot(p, vec2(0.5877853, 0.8090170)), dot(p, vec2(-0.5877853, 0.8090170))));
    return e - 0.86 * r;
  }
  return length(p) - r;
}

void main() {
  int tag = int(f_tag + 0.5);
  int kind = clamp(tag % 8, 0, 7);  // kPointStyleKinds
  bool derived = tag >= 8;
  float h = 0.8 * f_size + 1.0;
  vec2 p = f_uv * h;  // pixels from the centre
  float r = 0.5 * f_size;
  float d = shape(kind, p, r);
  float a = 1.0 - smoothstep(-0.5, 0.5, d);
  if (a <= 0.0) discard;
  vec3 kind_color = u_kind_colors[kind];
  float rim = clamp(0.18 * r, 0.8, 1.6);  // the dark outline
  vec3 c;
  if (derived) {
    float ring = max(1.0, 0.25 * r);  // the coloured band inside the outline
    c = mix(u_derived_fill, kind_color, smoothstep(-rim - ring - 0.5, -rim - ring + 0.5, d));
  } else {
    c = kind_color;
  }
  c = mix(c, u_outline, smoothstep(-rim - 0.5, -rim + 0.5, d));
  frag_color = vec4(c, a * u_alpha);
}
