// 3D models: their colour lit by the frame's light (Lambert, both faces, with an ambient share so
// a wall in shadow still reads), the terrain's logarithmic depth.
#version 330 core

in vec3 v_normal;
in float v_logDepth;

uniform vec3 u_rgb;
uniform vec3 u_sunDirection;  // unit, ECEF, towards the light
uniform float u_logDepthScale;

out vec4 fragColor;

void main() {
  gl_FragDepth = log2(v_logDepth) * u_logDepthScale;
  float lit = abs(dot(normalize(v_normal), u_sunDirection));
  fragColor = vec4(u_rgb * (0.35 + 0.65 * lit), 1.0);
}
