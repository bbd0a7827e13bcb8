// Overlays at an altitude (KML lines and polygons not clamped to the ground, extruded walls):
// lines widened to their width in pixels across the screen, triangles as they are; positions in
// metres from the camera (made in double on the CPU), the terrain's logarithmic depth.
#version 330 core

layout(location = 0) in vec3 a_start;         // metres from the camera, ECEF axes
layout(location = 1) in vec3 a_end;           // the segment's other end (triangles: = a_start)
layout(location = 2) in float a_t;            // 0: this vertex is at the start, 1: at the end
layout(location = 3) in float a_side;         // -1 / +1 across a line; 0 for triangles
layout(location = 4) in vec4 a_rgba;          // straight alpha
layout(location = 5) in float a_widthPixels;

uniform mat4 u_view;  // the camera's rotation (positions are camera-relative already)
uniform mat4 u_projection;
uniform vec2 u_viewportPixels;

out vec4 v_rgba;
out float v_logDepth;  // 1 + eye distance w

const float kNearW = 0.05;  // the near plane's w (terrain/render_view.hpp)

void main() {
  vec4 s = u_projection * (u_view * vec4(a_start, 1.0));
  vec4 e = u_projection * (u_view * vec4(a_end, 1.0));
  v_rgba = a_rgba;
  if (s.w < kNearW && e.w < kNearW) {  // wholly behind the camera
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    v_logDepth = 1.0;
    return;
  }
  // A segment reaching behind the camera keeps its part in front (clip space is linear).
  if (s.w < kNearW) s = mix(s, e, (kNearW - s.w) / (e.w - s.w));
  if (e.w < kNearW) e = mix(e, s, (kNearW - e.w) / (s.w - e.w));
  vec4 p = a_t < 0.5 ? s : e;
  if (a_side != 0.0) {
    vec2 halfViewport = 0.5 * u_viewportPixels;
    vec2 direction = e.xy / e.w * halfViewport - s.xy / s.w * halfViewport;
    float length = length(direction);
    vec2 along = length > 1e-6 ? direction / length : vec2(1.0, 0.0);
    vec2 across = vec2(-along.y, along.x);
    // Half a width past each end too: consecutive segments overlap at the joins.
    vec2 offsetPixels = 0.5 * a_widthPixels * (across * a_side + along * (a_t < 0.5 ? -1.0 : 1.0));
    p.xy += offsetPixels / halfViewport * p.w;
  }
  gl_Position = p;
  v_logDepth = 1.0 + max(p.w, 0.0);
}
