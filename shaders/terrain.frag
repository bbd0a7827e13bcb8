// Terrain fragment shader: the interpolated lit land or sea colour (terrain.vert), by the sea flag
// (or, with GLOBE_WATER_MASK, where a water mask decides, by the mask),
// times the draped imagery when GLOBE_IMAGERY is defined, then GLOBE_LAYERS (1..4) tiled imagery
// layers composited over it, bottom first (with GLOBE_LIGHT_IMAGERY each lit by its own weight of
// the terrain's light), and the logarithmic depth (per
// fragment, or per vertex in terrain.vert when GLOBE_VERTEX_LOG_DEPTH is defined).
#version 330 core

// GLOBE_OPAQUE_BASE: the bottom layer covers the tile opaquely (terrain.vert).
#if !defined(GLOBE_OPAQUE_BASE) || defined(GLOBE_LIGHT_IMAGERY)
#define GLOBE_SEA_FLAG 1
#endif
#ifndef GLOBE_OPAQUE_BASE
in vec3 v_landColor;
in vec3 v_seaColor;
#endif
#ifdef GLOBE_SEA_FLAG
in float v_sea;
#endif
#if defined(GLOBE_IMAGERY) && !defined(GLOBE_OPAQUE_BASE)
in vec2 v_imageryUv;
uniform sampler2D u_imagery;   // global equirectangular, row 0 at +90 deg
#endif
#ifdef GLOBE_LAYERS
in vec2 v_layerUv[GLOBE_LAYERS];  // imagery uv of each layer (terrain.vert)
#ifdef GLOBE_LIGHT_IMAGERY
in vec2 v_light;                  // land light, sea light: --lighting shades the imagery too
// The light splits into level ground's (the sea light: the globe's own shading) and the relief's
// (land light / level ground's, 1 on level ground and water). Level ground's is applied at
// u_levelLight to every layer; the relief at each layer's weight w (terrain/relief_shading.hpp,
// at the tile's corners on the CPU, interpolated in terrain.vert): by how much coarser its texel
// is than the terrain's samples. Where w changes (where the sources do) it changes across a
// tile, and level ground and water keep their brightness: no step.
uniform float u_levelLight;
in vec4 v_layerLight;
#endif
// Imagery tiles, premultiplied alpha (render/imagery_textures.cpp), row 0 = v 0. Four samplers
// rather than an array: GLSL 3.30 indexes sampler arrays only with constant expressions.
// The count is compiled in (one program per count): llvmpipe runs texture fetches under uniform
// branches anyway, so "if (count > k)" cost as much as drawing every layer.
uniform sampler2D u_layer0;
#if GLOBE_LAYERS > 1
uniform sampler2D u_layer1;
#endif
#if GLOBE_LAYERS > 2
uniform sampler2D u_layer2;
#endif
#if GLOBE_LAYERS > 3
uniform sampler2D u_layer3;
#endif
uniform float u_layerOpacity[GLOBE_LAYERS];
uniform float u_layerExposure[GLOBE_LAYERS];  // 1: the photo as it is
uniform float u_layerNight[GLOBE_LAYERS];     // 1: night lights, shown where the Sun has set
#endif
#ifdef GLOBE_WATER_MASK
// Premultiplied (water fraction · a, a): a = 0 where no land polygons decide (outside the mask's
// layers), so the sea flag stays.
uniform sampler2D u_waterMask;
in vec2 v_maskUv;
in float v_maskWeight;
#endif
in float v_logDepth;
in float v_fog;          // terrain.vert: distance fog towards the horizon's colour
in float v_day;          // terrain.vert: the daylight under the real Sun, 1 otherwise
uniform vec3 u_fogColor;
// Aerial perspective under the physical sky (terrain.vert), instead of the fog.
uniform bool u_aerial;
in vec3 v_transmittance;
in vec3 v_inscatter;

uniform float u_logDepthScale; // 1 / log2(1 + far)

out vec4 o_color;

#ifdef GLOBE_LAYERS
// "Over" with a premultiplied texel: colour·(1 − a) + rgb, a = alpha · opacity, which is
// mix(colour, straight rgb, a). Premultiplied so that filtering next to transparent texels does
// not bleed their (meaningless) colour in. The photo is exposed first (dark imagery lifted:
// 1 − (1 − c)^k, terrain/imagery_exposure.hpp), then lit within its own range.
// level: level ground's light (1 without --lighting), relief: the relief's light.
// A night layer (u_layerNight) adds its light to `glow` instead and covers nothing.
vec3 drape(vec3 color, sampler2D layer, int k, float level, float relief, inout vec3 glow) {
  vec4 texel = texture(layer, v_layerUv[k]) * u_layerOpacity[k];
  if (u_layerNight[k] > 0.5) {
    glow += texel.rgb;
    return color;
  }
  vec3 straight = clamp(texel.rgb / max(texel.a, 1e-3), 0.0, 1.0);
  vec3 photo = 1.0 - pow(1.0 - straight, vec3(u_layerExposure[k]));
#ifdef GLOBE_LIGHT_IMAGERY
  // Shadowed slopes darken by the relief; lit ones brighten and saturate at the photo's own
  // colour (its highlights are its own Sun's): level · multiplier <= 1
  // (terrain::reliefLightMultiplier).
  float headroom = 1.0 / max(level, 1e-3) - 1.0;
  float lift = headroom > 0.0 ? 1.0 + headroom * (1.0 - exp(-(relief - 1.0) / headroom)) : 1.0;
  float multiplier = relief > 1.0 ? lift : max(relief, 0.0);
  float light = level * mix(1.0, multiplier, v_layerLight[k]);
  return photo * (light * texel.a) + color * (1.0 - texel.a);
#else
  return photo * (level * texel.a) + color * (1.0 - texel.a);
#endif
}
#endif

#ifdef GLOBE_SEA_FLAG
// How much of the fragment is water, 0 or 1: the sea flag thresholded at 1/2. With a water mask,
// the flag and the mask's water fraction mixed by the mask's weight, thresholded over about a
// pixel: coasts as sharp as the screen allows when near, a mip level's coverage when far.
float seaAmount() {
#ifdef GLOBE_WATER_MASK
  vec4 mask = texture(u_waterMask, v_maskUv);
  float sea = v_sea * (1.0 - v_maskWeight * mask.a) + v_maskWeight * mask.r;
  float width = max(fwidth(sea), 1e-3);
  return clamp((sea - 0.5) / width + 0.5, 0.0, 1.0);
#else
  return v_sea > 0.5 ? 1.0 : 0.0;
#endif
}
#endif

void main() {
#ifdef GLOBE_SEA_FLAG
  float sea = seaAmount();
#endif
#ifdef GLOBE_OPAQUE_BASE
  vec3 color = vec3(0.0);  // covered by layer 0 (alpha 1, opacity 1) in every fragment
#else
  vec3 color = mix(v_landColor, v_seaColor, sea);
#endif
#if defined(GLOBE_IMAGERY) && !defined(GLOBE_OPAQUE_BASE)
  color *= texture(u_imagery, v_imageryUv).rgb;
#endif
  vec3 glow = vec3(0.0);  // night lights' premultiplied light (drape)
#ifdef GLOBE_LAYERS
#ifdef GLOBE_LIGHT_IMAGERY
  float level = mix(1.0, v_light.y, u_levelLight);
  float relief = mix(v_light.x / max(v_light.y, 1e-3), 1.0, sea);
#else
  float level = 1.0;  // imagery keeps its own (baked-in) shading
  float relief = 1.0;
#endif
  color = drape(color, u_layer0, 0, level, relief, glow);
#if GLOBE_LAYERS > 1
  color = drape(color, u_layer1, 1, level, relief, glow);
#endif
#if GLOBE_LAYERS > 2
  color = drape(color, u_layer2, 2, level, relief, glow);
#endif
#if GLOBE_LAYERS > 3
  color = drape(color, u_layer3, 3, level, relief, glow);
#endif
#endif
  // Night lights shine where the day has gone (v_day: 1 by day, the night's floor by night).
  vec3 lit = color * v_day + glow * (1.0 - v_day);
  o_color = vec4(u_aerial ? lit * v_transmittance + v_inscatter : mix(lit, u_fogColor, v_fog), 1.0);
#ifndef GLOBE_VERTEX_LOG_DEPTH
  gl_FragDepth = log2(v_logDepth) * u_logDepthScale;
#endif
}
