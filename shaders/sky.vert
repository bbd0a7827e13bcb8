// Sky pass vertex shader: one triangle that covers the screen; the fragment shader turns each
// pixel into a view direction.
#version 330 core

out vec2 v_ndc;  // normalised device coordinates of the pixel

void main() {
  vec2 corner = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
  v_ndc = corner;
  gl_Position = vec4(corner, 0.0, 1.0);
}
