#version 330 core
// Every surface display mode in one pass, so overlays (isophote lines) combine with any base.
in vec3 v_position;
in vec3 v_normal;
in float v_curvature;

uniform int u_base;  // 0 shaded, 1 isophotes, 2 zebra, 3 curvature
uniform vec3 u_eye;
uniform vec3 u_key_light;   // unit, towards the light; fixed to the camera (studio lighting)
uniform vec3 u_fill_light;
uniform vec3 u_shade_light;  // unit: the shaded mode's key, more oblique for contrast
uniform vec3 u_camera_up;
uniform vec3 u_camera_forward;

uniform bool u_isophote_lines;  // the overlay (the isophote mode always draws its lines)
uniform vec3 u_isophote_direction;  // unit, fixed in the model
uniform float u_isophote_count;
uniform float u_isophote_width;  // pixels

uniform float u_zebra_count;
uniform float u_zebra_width;  // dark fraction of a period

uniform sampler2D u_color_map;  // 1 row, t in [0, 1] across
uniform float u_range_lo;       // < 0
uniform float u_range_hi;       // > 0
uniform bool u_curvature_lit;

out vec4 frag_color;

const vec3 kFront = vec3(0.74, 0.77, 0.81);  // cool clay
const vec3 kBack = vec3(0.80, 0.52, 0.34);   // warm terracotta: the other side reads at a glance

vec3 to_linear(vec3 c) { return pow(c, vec3(2.2)); }
vec3 to_srgb(vec3 c) { return pow(clamp(c, 0.0, 1.0), vec3(1.0 / 2.2)); }

// Soft studio light: hemisphere ambient, a key with a gentle highlight and a dim fill.
vec3 lit(vec3 albedo_linear, vec3 n, vec3 view, float specular) {
  float hemi = 0.5 + 0.5 * dot(n, u_camera_up);
  vec3 ambient = mix(vec3(0.20, 0.20, 0.22), vec3(0.36, 0.37, 0.40), hemi);
  float key = max(dot(n, u_key_light), 0.0);
  float fill = max(dot(n, u_fill_light), 0.0);
  vec3 h = normalize(u_key_light + view);
  float spec = pow(max(dot(n, h), 0.0), 60.0) * specular;
  return albedo_linear * (ambient + 0.85 * key + 0.25 * fill) + vec3(spec);
}

// The plain shaded mode: a dark ambient and an oblique key, so that a gently curved patch facing
// the camera still shows a clear gradient (a light from the eye would make it uniform grey), and
// a sharper highlight that follows the curvature.
vec3 shaded(vec3 albedo_linear, vec3 n, vec3 view) {
  float hemi = 0.5 + 0.5 * dot(n, u_camera_up);
  vec3 ambient = mix(vec3(0.05, 0.05, 0.06), vec3(0.17, 0.18, 0.20), hemi);
  float key = max(dot(n, u_shade_light), 0.0);
  float fill = max(dot(n, u_fill_light), 0.0);
  vec3 h = normalize(u_shade_light + view);
  float spec = pow(max(dot(n, h), 0.0), 48.0) * 0.35;
  return albedo_linear * (ambient + 1.05 * key + 0.22 * fill) + vec3(spec);
}

// Antialiased coverage of lines at the integers of s, `width` pixels wide.
float line_coverage(float s, float width) {
  float d = abs(fract(s + 0.5) - 0.5) / max(fwidth(s), 1e-6);
  return 1.0 - smoothstep(0.5 * width - 0.5, 0.5 * width + 0.5, d);
}

void main() {
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;  // two-sided: light the side we see
  vec3 view = normalize(u_eye - v_position);
  vec3 albedo = gl_FrontFacing ? kFront : kBack;
  vec3 color;

  if (u_base == 3) {
    float k = v_curvature;
    float t = k < 0.0 ? 0.5 - 0.5 * k / u_range_lo : 0.5 + 0.5 * k / u_range_hi;
    vec3 c = texture(u_color_map, vec2(clamp(t, 0.0, 1.0), 0.5)).rgb;
    if (u_curvature_lit) {
      vec3 l = lit(to_linear(c), n, view, 0.15) * 0.95 + 0.12 * to_linear(c);
      color = to_srgb(l);
    } else {
      color = c;
    }
    if (!gl_FrontFacing) color *= 0.55;
  } else if (u_base == 2) {
    vec3 r = reflect(-view, n);
    // Light tubes at infinity running along the camera's right axis, as in a car-body
    // inspection tunnel that moves with the viewer: the stripe parameter is the angle of the
    // reflected ray around that axis.
    float s = atan(dot(r, u_camera_up), -dot(r, u_camera_forward)) / 3.14159265 * u_zebra_count;
    // Distance (in periods) to the centre of the nearest dark stripe, antialiased over a pixel.
    float g = abs(fract(s - 0.5 * u_zebra_width + 0.5) - 0.5);
    float w = 0.5 * max(fwidth(s), 1e-6);
    float dark = 1.0 - smoothstep(0.5 * u_zebra_width - w, 0.5 * u_zebra_width + w, g);
    vec3 base = to_srgb(lit(to_linear(albedo), n, view, 0.0) * 0.35 + 0.65);
    color = mix(base, vec3(0.06, 0.07, 0.09), dark);
  } else if (u_base == 1) {
    // Isophotes: the bands between the lines in steps of grey from light (normal towards the
    // light direction) to dark, unlit by the camera, so the picture is the light pattern alone
    // and reads differently from the shaded mode; every other band a little darker, so that
    // neighbouring bands stay apart.
    float angle = acos(clamp(dot(n, u_isophote_direction), -1.0, 1.0));
    float band = floor(angle / 3.14159265 * u_isophote_count);
    float t = (band + 0.5) / u_isophote_count;
    vec3 light = gl_FrontFacing ? vec3(0.98, 0.98, 0.99) : vec3(0.99, 0.90, 0.83);
    vec3 dark = gl_FrontFacing ? vec3(0.28, 0.31, 0.37) : vec3(0.42, 0.24, 0.16);
    color = mix(light, dark, t) * (mod(band, 2.0) == 1.0 ? 0.93 : 1.0);
  } else {
    color = to_srgb(shaded(to_linear(albedo), n, view));
  }

  if (u_base == 1 || u_isophote_lines) {
    float angle = acos(clamp(dot(n, u_isophote_direction), -1.0, 1.0));
    float s = angle / 3.14159265 * u_isophote_count;
    float a = line_coverage(s, u_isophote_width);
    // Levels 0 and count are single points (normal exactly along or against the light), not
    // lines: leave them out instead of drawing a blot.
    a *= smoothstep(0.25, 0.5, s) * smoothstep(0.25, 0.5, u_isophote_count - s);
    color = mix(color, vec3(0.05, 0.05, 0.07), a * 0.9);
  }
  frag_color = vec4(color, 1.0);
}
