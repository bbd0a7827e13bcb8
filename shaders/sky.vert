// Sky pass vertex shader: one triangle that covers the screen at the far depth (drawn after the
// terrain with LEQUAL: only where nothing else is), and each corner's point on the near plane
// (camera-relative ECEF, homogeneous): linear across the screen, so the fragment shader gets its
// pixel's view direction from the interpolated point without a matrix product of its own.
#version 330 core

uniform mat4 u_inverseViewProjection;  // clip → camera-relative ECEF directions (no translation)

out vec4 v_near;  // the pixel's point on the near plane, before the division by w

void main() {
  vec2 corner = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
  // The camera sits at the origin of this space, so the near plane's point gives the direction
  // (the far plane's w cancels to nothing in float when far/near is large).
  v_near = u_inverseViewProjection * vec4(corner, -1.0, 1.0);
  gl_Position = vec4(corner, 1.0, 1.0);
}
