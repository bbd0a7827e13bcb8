// Terrain vertex shader: camera-relative transform (modelView made in double on the CPU), the
// colour and the light per vertex, and the eye distance for the logarithmic depth written in
// terrain.frag. With GLOBE_VERTEX_LOG_DEPTH defined (the renderer's variant for tiles far from the
// camera), the same logarithmic depth is written per vertex into gl_Position.z instead, so the
// fragment shader keeps early depth testing. With GLOBE_IMAGERY defined (imagery draped), the
// colours are the light only and the image gives the colour in terrain.frag. With GLOBE_LAYERS = n
// (n tiled imagery layers, composited over that colour in terrain.frag), each layer's imagery uv
// travels as a varying, and with GLOBE_LIGHT_IMAGERY (--lighting) the land and sea light too.
// With GLOBE_WATER_MASK, the water mask's uv and weight (terrain.frag decides land and water).
//
// Colour and light are computed here, not per fragment: llvmpipe shades several fragments per
// vertex even near the ground, and the normals are per vertex anyway, so per-fragment lighting
// bought little but cost a fifth of the frame (docs/performance/performance-render.md). The land and the sea
// colour both travel, with the sea flag, so the coastline stays sharp (the fragment picks one)
// instead of blending across a grid cell. Few varyings keep llvmpipe's per-triangle set-up cheap.
#version 330 core
// Tiles of one level share u_modelView, and a shared edge vertex's u_tileOrigin + a_offset is the
// same exact sum in both tiles: invariant keeps every program variant computing it alike, so the
// rasteriser sees the same vertex and the seam is watertight.
invariant gl_Position;

layout(location = 0) in vec3 a_offset;  // metres from the tile centre, ECEF axes
layout(location = 1) in vec3 a_normal;  // unit, ECEF axes
layout(location = 2) in float a_height; // metres: land height, or under water the sea floor's
                                        // (0 = unknown), whether water or floor is drawn
layout(location = 3) in float a_sea;    // 1 = water (land below sea level is land)
layout(location = 4) in vec2 a_uv;      // tile-local: (0,0) north-west, (1,1) south-east
layout(location = 5) in vec3 a_coarseNormal;  // on edges: the next coarser level's normal
layout(location = 6) in float a_sunlight;     // 0..1 of the Sun's disc seen (shadows); else 1

uniform mat4 u_modelView;        // view · translate(the eye on the level's quantum), from double
uniform vec3 u_tileOrigin;       // tile centre − that eye: exact in float (terrain_renderer.hpp)
uniform mat4 u_projection;
uniform vec3 u_tileCenterEcef;   // only used for a direction ("up"), so float is plenty
uniform vec4 u_imageryRect;      // global equirectangular uv = xy + a_uv · zw
uniform float u_logDepthScale;   // 1 / log2(1 + far)
uniform vec3 u_sunDirection;     // unit, towards the sun, ECEF axes (zero: ambient only)
uniform float u_ambient;         // light on faces turned away from the sun
uniform bool u_daylight;         // the real Sun (--time): the night side dark (render/sky_model.hpp)
uniform vec3 u_daylightBand;     // night's light, night's and day's sun-up cosines (daylightBand())
uniform bool u_hillShading;      // false: light with the ellipsoid "up" only
uniform vec4 u_coarserEdges;     // north, south, west, east: 1 where that neighbour is coarser
uniform float u_fogDensity;      // per metre (render/sky_model.hpp)
uniform float u_fogMaximum;      // 0: no fog

// GLOBE_OPAQUE_BASE: the bottom layer is opaque over the whole tile, so the terrain's own colour
// is never seen: it is neither computed nor interpolated (fewer varyings, cheaper triangles).
#if !defined(GLOBE_OPAQUE_BASE) || defined(GLOBE_LIGHT_IMAGERY)
#define GLOBE_SEA_FLAG 1
#endif
#ifndef GLOBE_OPAQUE_BASE
out vec3 v_landColor;  // lit (the light only, with imagery)
out vec3 v_seaColor;   // lit with "up" (the light only, with imagery)
#endif
out float v_day;       // 1 by day, the night's floor by night (1 without u_daylight)
#ifdef GLOBE_SEA_FLAG
out float v_sea;       // 1 = sea; the fragment thresholds it at 0.5
#endif
#if defined(GLOBE_IMAGERY) && !defined(GLOBE_OPAQUE_BASE)
out vec2 v_imageryUv;
#endif
#ifdef GLOBE_LAYERS
uniform vec4 u_layerTransform[GLOBE_LAYERS];  // imagery uv = xy + tile uv · zw
out vec2 v_layerUv[GLOBE_LAYERS];  // per vertex: a varying is cheaper than the FMA per fragment
#ifdef GLOBE_LIGHT_IMAGERY
out vec2 v_light;                  // land light, sea light
// Each layer's weight of the relief's light (terrain.frag) at the tile's corners: north-west,
// north-east, south-west, south-east; interpolated across the tile, one component per layer.
uniform vec4 u_layerLight[GLOBE_LAYERS];
out vec4 v_layerLight;
#endif
#endif
#ifdef GLOBE_WATER_MASK
uniform vec4 u_waterMaskTransform;  // water-mask uv = xy + tile uv · zw
uniform vec4 u_waterMaskWeight;     // the mask's weight at the corners NW, NE, SW, SE
out vec2 v_maskUv;
out float v_maskWeight;             // 0: the sea flag decides, 1: the mask (terrain.frag)
#endif
out float v_logDepth;  // 1 + eye distance w
out float v_fog;       // how much of the fog colour covers the terrain here
// Aerial perspective under the physical sky (--time; atmosphere/aerial_perspective.hpp): the air
// between the eye and the vertex lets v_transmittance of its colour through, per channel, and
// scatters in v_inscatter: the sky's horizon colour in that direction (its image, as the sky
// pass draws it: azimuth from the Sun's vertical, 0..1 for 0..180°) times what the air takes, lit
// by the daylight there. Otherwise the fog (v_fog) does.
uniform bool u_aerial;
uniform vec3 u_rayleighPerMeter;
uniform float u_mieExtinctionPerMeter;
uniform vec2 u_scaleHeightsMeters;  // Rayleigh, Mie
uniform float u_cameraHeightMeters;
uniform sampler2D u_hazeSkyView;
uniform vec3 u_hazeUpEye;          // eye space
uniform vec3 u_hazeSunAcrossEye;   // eye space; zero: the Sun has no azimuth (zenith or nadir)
uniform float u_hazeRow;           // the image's row at the horizon
out vec3 v_transmittance;
out vec3 v_inscatter;

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

// Shallow sea (and water of unknown depth) is mid blue, a 6 km deep floor is dark blue.
vec3 seaColor(float heightMeters) {
  float depth = clamp(-heightMeters / 6000.0, 0.0, 1.0);
  return mix(vec3(0.16, 0.36, 0.72), vec3(0.03, 0.10, 0.38), sqrt(depth));
}

// ∫ exp(−h/H) ds over the straight path from height h0 to h1 (AerialPerspective's closed form).
float exponentialPath(float h0, float h1, float lengthMeters, float scaleHeight) {
  h0 = max(h0, 0.0);
  h1 = max(h1, 0.0);
  float rise = h1 - h0;
  if (abs(rise) < 1e-3 * scaleHeight) return lengthMeters * exp(-0.5 * (h0 + h1) / scaleHeight);
  return lengthMeters * scaleHeight * (exp(-h0 / scaleHeight) - exp(-h1 / scaleHeight)) / rise;
}

vec3 hazeColor(vec3 directionEye) {
  vec3 across = directionEye - u_hazeUpEye * dot(directionEye, u_hazeUpEye);
  float azimuth = 0.5;
  if (dot(across, across) > 1e-10 && dot(u_hazeSunAcrossEye, u_hazeSunAcrossEye) > 0.5) {
    azimuth = acos(clamp(dot(normalize(across), u_hazeSunAcrossEye), -1.0, 1.0)) / 3.14159265;
  }
  return textureLod(u_hazeSkyView, vec2(azimuth, u_hazeRow), 0.0).rgb;
}

void aerialPerspective(vec3 eye) {
  if (!u_aerial) {
    v_transmittance = vec3(1.0);
    v_inscatter = vec3(0.0);
    return;
  }
  float lengthMeters = length(eye);
  float rayleigh = exponentialPath(u_cameraHeightMeters, a_height, lengthMeters,
                                   u_scaleHeightsMeters.x);
  float mie = exponentialPath(u_cameraHeightMeters, a_height, lengthMeters, u_scaleHeightsMeters.y);
  v_transmittance = exp(-(u_rayleighPerMeter * rayleigh + u_mieExtinctionPerMeter * mie));
  v_inscatter = (1.0 - v_transmittance) * hazeColor(eye / max(lengthMeters, 1e-3)) * v_day;
}

void main() {
  vec4 eye = u_modelView * vec4(u_tileOrigin + a_offset, 1.0);
  gl_Position = u_projection * eye;
  v_logDepth = 1.0 + max(gl_Position.w, 0.0);
  float fogDepth = max(gl_Position.w, 0.0) * u_fogDensity;
  v_fog = u_fogMaximum * (1.0 - exp(-fogDepth * fogDepth));
#ifdef GLOBE_VERTEX_LOG_DEPTH
  // Window depth log2(1 + w) / log2(1 + far) at the vertex, linear in screen space in between.
  gl_Position.z = (log2(max(1e-6, 1.0 + gl_Position.w)) * 2.0 * u_logDepthScale - 1.0) *
                  gl_Position.w;
#endif
  // Sea is lit with the geocentric "up", whether the water surface at 0 m or the sea floor is
  // drawn: water stays flat, and the floor's colour (its depth) shows its relief.
  vec3 up = normalize(u_tileCenterEcef + a_offset);
  float upLight = u_ambient + (1.0 - u_ambient) * max(dot(up, u_sunDirection), 0.0) * a_sunlight;
  // The Sun from 6° below the horizon (night) to 4° above (day): render/sky_model.cpp daylight().
  v_day = u_daylight ? mix(u_daylightBand.x, 1.0,
                           smoothstep(u_daylightBand.y, u_daylightBand.z, dot(up, u_sunDirection)))
                     : 1.0;
  aerialPerspective(eye.xyz);
  // An edge that faces a coarser neighbour is lit with that level's normals, so the lighting does
  // not step at the level change (terrain/tile_mesh.hpp). uv is exactly 0 or 1 on the edges.
  vec4 onEdge = vec4(a_uv.y == 0.0, a_uv.y == 1.0, a_uv.x == 0.0, a_uv.x == 1.0);
  vec3 normal = dot(onEdge, u_coarserEdges) > 0.0 ? a_coarseNormal : a_normal;
  float landLight = u_hillShading
                        ? u_ambient + (1.0 - u_ambient) * max(dot(normal, u_sunDirection), 0.0) *
                                          a_sunlight
                        : upLight;
#if defined(GLOBE_OPAQUE_BASE)
#elif defined(GLOBE_IMAGERY)
  v_landColor = vec3(landLight);
  v_seaColor = vec3(upLight);
  v_imageryUv = u_imageryRect.xy + a_uv * u_imageryRect.zw;
#else
  v_landColor = hypsometric(a_height) * landLight;
  v_seaColor = seaColor(a_height) * upLight;
#endif
#ifdef GLOBE_LAYERS
  for (int k = 0; k < GLOBE_LAYERS; ++k) {
    v_layerUv[k] = u_layerTransform[k].xy + a_uv * u_layerTransform[k].zw;
  }
#ifdef GLOBE_LIGHT_IMAGERY
  v_light = vec2(landLight, upLight);
  v_layerLight = vec4(1.0);
  for (int k = 0; k < GLOBE_LAYERS; ++k) {
    vec4 c = u_layerLight[k];
    v_layerLight[k] = mix(mix(c.x, c.y, a_uv.x), mix(c.z, c.w, a_uv.x), a_uv.y);
  }
#endif
#endif
#ifdef GLOBE_SEA_FLAG
  v_sea = a_sea;
#endif
#ifdef GLOBE_WATER_MASK
  v_maskUv = u_waterMaskTransform.xy + a_uv * u_waterMaskTransform.zw;
  vec4 w = u_waterMaskWeight;
  v_maskWeight = mix(mix(w.x, w.y, a_uv.x), mix(w.z, w.w, a_uv.x), a_uv.y);
#endif
}
