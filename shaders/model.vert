// 3D models (3D Tiles' contents): positions as float offsets from their set's origin, the
// origin's place relative to the camera given each frame (made in double on the CPU); the
// terrain's logarithmic depth.
#version 330 core

layout(location = 0) in vec3 a_offset;  // metres from the set's origin, ECEF axes
layout(location = 1) in vec3 a_normal;  // unit, ECEF: the model's, or the triangle's own
layout(location = 2) in vec2 a_uv;      // the base colour texture's coordinates

uniform vec3 u_originFromCamera;  // the set's origin − the camera, metres
uniform mat4 u_view;              // the camera's rotation
uniform mat4 u_projection;

out vec3 v_normal;
out vec2 v_uv;
out float v_logDepth;  // 1 + eye distance w

void main() {
  vec4 p = u_projection * (u_view * vec4(u_originFromCamera + a_offset, 1.0));
  gl_Position = p;
  v_normal = a_normal;
  v_uv = a_uv;
  v_logDepth = 1.0 + max(p.w, 0.0);
}
