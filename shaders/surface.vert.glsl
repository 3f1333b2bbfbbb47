#version 330 core
// Surface vertices in model (= world) space with the core's exact normal and curvatures.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_curvature;  // gaussian, mean, kmin, kmax

uniform mat4 u_view_projection;
uniform int u_curvature_index;  // which component of a_curvature the map shows

out vec3 v_position;
out vec3 v_normal;
out float v_curvature;

void main() {
  v_position = a_position;
  v_normal = a_normal;
  v_curvature = a_curvature[u_curvature_index];
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
