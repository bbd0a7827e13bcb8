// Overlays at an altitude: flat colour, the terrain's logarithmic depth pulled a hair towards the
// camera so a line lying on the ground is not lost in it.
#version 330 core

in vec4 v_rgba;
in float v_logDepth;

uniform float u_logDepthScale;  // 1 / log2(1 + far)

out vec4 fragColor;

void main() {
  gl_FragDepth = log2(v_logDepth * 0.9995) * u_logDepthScale;
  fragColor = v_rgba;
}
