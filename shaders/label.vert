// Label vertex shader: window pixels (origin top-left, y down) to clip space; texel coordinates
// and the text and halo colours passed on.
#version 330 core
layout(location = 0) in vec2 a_positionPixels;
layout(location = 1) in vec2 a_texel;
layout(location = 2) in vec4 a_rgba;
layout(location = 3) in vec4 a_haloRgba;
uniform vec2 u_viewportPixels;
out vec2 v_texel;
out vec4 v_rgba;
out vec4 v_haloRgba;
void main() {
  vec2 ndc = a_positionPixels / u_viewportPixels * 2.0 - 1.0;
  gl_Position = vec4(ndc.x, -ndc.y, 0.0, 1.0);
  v_texel = a_texel;
  v_rgba = a_rgba;
  v_haloRgba = a_haloRgba;
}
