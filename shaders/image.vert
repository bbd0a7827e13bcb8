// Image overlay vertex shader: the rectangle's corner for this vertex (a strip of four, no vertex
// buffer), window pixels (origin top-left, y down) to clip space; texture rows top-down.
#version 330 core
uniform vec4 u_rectPixels;  // left, top, width, height
uniform vec2 u_viewportPixels;
out vec2 v_uv;
void main() {
  vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
  vec2 ndc = (u_rectPixels.xy + corner * u_rectPixels.zw) / u_viewportPixels * 2.0 - 1.0;
  gl_Position = vec4(ndc.x, -ndc.y, 0.0, 1.0);
  v_uv = corner;
}
