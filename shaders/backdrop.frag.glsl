#version 330 core
// Studio backdrop: a soft vertical gradient with a gentle vignette. Computed from the
// viewport's own pixel coordinates so tiled renders join seamlessly.
uniform vec4 u_viewport;  // x, y, width, height in framebuffer pixels
out vec4 frag_color;

void main() {
  vec2 uv = (gl_FragCoord.xy - u_viewport.xy) / u_viewport.zw;
  vec3 top = vec3(0.985, 0.985, 0.99);
  vec3 bottom = vec3(0.86, 0.87, 0.89);
  vec3 c = mix(bottom, top, smoothstep(0.0, 1.0, uv.y));
  float r = length((uv - vec2(0.5, 0.55)) * vec2(1.0, 0.8));
  c *= 1.0 - 0.08 * smoothstep(0.35, 0.9, r);
  frag_color = vec4(c, 1.0);
}
