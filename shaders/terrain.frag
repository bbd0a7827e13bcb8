// Terrain fragment shader: the interpolated lit land or sea colour (terrain.vert), by the sea flag,
// times the draped imagery when GLOBE_IMAGERY is defined, and the logarithmic depth (per fragment,
// or per vertex in terrain.vert when GLOBE_VERTEX_LOG_DEPTH is defined).
#version 330 core

in vec3 v_landColor;
in vec3 v_seaColor;
in float v_sea;
#ifdef GLOBE_IMAGERY
in vec2 v_imageryUv;
uniform sampler2D u_imagery;   // global equirectangular, row 0 at +90 deg
#endif
in float v_logDepth;

uniform float u_logDepthScale; // 1 / log2(1 + far)

out vec4 o_color;

void main() {
  vec3 color = v_sea > 0.5 ? v_seaColor : v_landColor;
#ifdef GLOBE_IMAGERY
  color *= texture(u_imagery, v_imageryUv).rgb;
#endif
  o_color = vec4(color, 1.0);
#ifndef GLOBE_VERTEX_LOG_DEPTH
  gl_FragDepth = log2(v_logDepth) * u_logDepthScale;
#endif
}
