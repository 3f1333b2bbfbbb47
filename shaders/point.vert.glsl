#version 330 core
// Control points. A point's sprite is flat and faces the eye, and points often lie on the surface
// they control: tested at its own depth, the triangles around it would cut the disc. So the whole
// sprite is pulled towards the eye by u_depth_push radii (world units at the point's distance),
// keeping points on or just under the surface whole, while a point well behind a surface still
// fails the depth test and is drawn in the faded pass.
layout(location = 0) in vec3 a_position;
layout(location = 1) in float a_tag;  // point style: kind + 8 * role
uniform mat4 u_view;
uniform mat4 u_projection;
uniform vec2 u_viewport_size;  // pixels
uniform float u_size;          // pixels, an editable point's width
uniform float u_depth_push;    // radii
out float g_tag;

void main() {
  g_tag = a_tag;
  vec4 v = u_view * vec4(a_position, 1.0);
  vec4 p = u_projection * v;
  bool perspective = u_projection[3][3] == 0.0;
  // World units per pixel at this depth: the view height there is 2 w / P[1][1].
  float per_pixel = 2.0 * p.w / (u_projection[1][1] * u_viewport_size.y);
  float push = u_depth_push * 0.5 * u_size * per_pixel;
  if (perspective) push = min(push, 0.5 * -v.z);  // never through the eye
  vec4 q = u_projection * (v + vec4(0.0, 0.0, push, 0.0));
  // Same place on screen, nearer depth.
  gl_Position = vec4(p.xy, q.z / q.w * p.w, p.w);
}
