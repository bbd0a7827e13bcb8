// Terrain vertex shader: camera-relative transform (modelView made in double on the CPU) and the
// eye distance for the logarithmic depth written in terrain.frag. With GLOBE_VERTEX_LOG_DEPTH
// defined (the renderer's variant for tiles far from the camera), the same logarithmic depth is
// written per vertex into gl_Position.z instead, so the fragment shader keeps early depth testing.
#version 330 core

layout(location = 0) in vec3 a_offset;  // metres from the tile centre, ECEF axes
layout(location = 1) in vec3 a_normal;  // unit, ECEF axes
layout(location = 2) in float a_height; // metres, sea (no data) = 0
layout(location = 3) in float a_sea;    // 1 = sea (no data or below 0 m)
layout(location = 4) in vec2 a_uv;      // tile-local: (0,0) north-west, (1,1) south-east

uniform mat4 u_modelView;        // view · translate(tile centre), cast from double
uniform mat4 u_projection;
uniform vec3 u_tileCenterEcef;   // only used for a direction ("up"), so float is plenty
uniform vec4 u_imageryRect;      // global equirectangular uv = xy + a_uv · zw
uniform float u_logDepthScale;   // 1 / log2(1 + far)

out vec3 v_normal;
out vec3 v_up;
out float v_height;
out float v_sea;
out vec2 v_imageryUv;
out float v_logDepth;  // 1 + eye distance w

void main() {
  gl_Position = u_projection * (u_modelView * vec4(a_offset, 1.0));
  v_logDepth = 1.0 + max(gl_Position.w, 0.0);
#ifdef GLOBE_VERTEX_LOG_DEPTH
  // Window depth log2(1 + w) / log2(1 + far) at the vertex, linear in screen space in between.
  gl_Position.z = (log2(max(1e-6, 1.0 + gl_Position.w)) * 2.0 * u_logDepthScale - 1.0) *
                  gl_Position.w;
#endif
  v_normal = a_normal;
  v_up = u_tileCenterEcef + a_offset;
  v_height = a_height;
  v_sea = a_sea;
  v_imageryUv = u_imageryRect.xy + a_uv * u_imageryRect.zw;
}
