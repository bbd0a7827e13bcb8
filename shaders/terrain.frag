// Terrain fragment shader: hypsometric colour ramp (or draped imagery), hill-shading from the mesh
// normals and the sun, flat-lit blue sea with a depth tint, logarithmic depth (per fragment, or
// per vertex in terrain.vert when GLOBE_VERTEX_LOG_DEPTH is defined).
#version 330 core

in vec3 v_normal;
in vec3 v_up;
in float v_height;
in float v_sea;
in vec2 v_imageryUv;
in float v_logDepth;

uniform vec3 u_sunDirection;   // unit, towards the sun, ECEF axes (zero: ambient only)
uniform float u_ambient;       // light on faces turned away from the sun
uniform bool u_hillShading;    // false: light with the ellipsoid "up" only
uniform bool u_useImagery;
uniform sampler2D u_imagery;   // global equirectangular, row 0 at +90 deg
uniform float u_logDepthScale; // 1 / log2(1 + far)

out vec4 o_color;

// Height (m) → colour: lowland greens, tan and browns, greys, then snow.
const int kStops = 7;
const float kStopHeights[kStops] = float[](0.0, 300.0, 800.0, 1500.0, 2500.0, 3500.0, 4500.0);
const vec3 kStopColors[kStops] = vec3[](
    vec3(0.30, 0.52, 0.27), vec3(0.47, 0.63, 0.33), vec3(0.75, 0.71, 0.45),
    vec3(0.62, 0.46, 0.30), vec3(0.50, 0.41, 0.35), vec3(0.64, 0.63, 0.62),
    vec3(0.96, 0.96, 0.98));

vec3 hypsometric(float heightMeters) {
  if (heightMeters <= kStopHeights[0]) return kStopColors[0];
  for (int k = 1; k < kStops; ++k) {
    if (heightMeters < kStopHeights[k]) {
      float t = (heightMeters - kStopHeights[k - 1]) / (kStopHeights[k] - kStopHeights[k - 1]);
      return mix(kStopColors[k - 1], kStopColors[k], t);
    }
  }
  return kStopColors[kStops - 1];
}

// Shallow (and no-data) sea is mid blue, 6 km deep is dark blue.
vec3 seaColor(float heightMeters) {
  float depth = clamp(-heightMeters / 6000.0, 0.0, 1.0);
  return mix(vec3(0.16, 0.36, 0.72), vec3(0.03, 0.10, 0.38), sqrt(depth));
}

void main() {
  bool sea = v_sea > 0.5;
  vec3 base;
  if (u_useImagery) {
    base = texture(u_imagery, v_imageryUv).rgb;
  } else {
    base = sea ? seaColor(v_height) : hypsometric(v_height);
  }
  vec3 up = normalize(v_up);
  vec3 n = (sea || !u_hillShading) ? up : normalize(v_normal);
  float diffuse = max(dot(n, u_sunDirection), 0.0);
  o_color = vec4(base * (u_ambient + (1.0 - u_ambient) * diffuse), 1.0);
#ifndef GLOBE_VERTEX_LOG_DEPTH
  gl_FragDepth = log2(v_logDepth) * u_logDepthScale;
#endif
}
