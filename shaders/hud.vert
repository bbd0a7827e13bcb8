// HUD vertex shader: window pixels (origin top-left, y down) to clip space; colour passed on.
#version 330 core
layout(location = 0) in vec2 a_positionPixels;
layout(location = 1) in vec4 a_rgba;
uniform vec2 u_viewportPixels;
out vec4 v_rgba;
void main() {
  vec2 ndc = a_positionPixels / u_viewportPixels * 2.0 - 1.0;
  gl_Position = vec4(ndc.x, -ndc.y, 0.0, 1.0);
  v_rgba = a_rgba;
}
