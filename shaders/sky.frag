// Sky pass fragment shader (render/sky_model.hpp): inside the air, a gradient from the horizon
// haze to the zenith above the (dipping) horizon; from space, black with a glow where the view
// ray grazes the air around the globe (under the real Sun only where that air is lit); the two
// blended by the camera's height.
#version 330 core

in vec4 v_near;  // sky.vert: the pixel's point on the near plane, homogeneous

uniform vec3 u_up;                     // unit, from the globe's centre through the camera
uniform float u_cameraRadius;          // metres from the globe's centre
uniform float u_globeRadius;           // metres
uniform float u_atmosphereHeight;      // metres: the glow's thickness
uniform vec3 u_zenith;
uniform vec3 u_horizon;
uniform vec3 u_glow;
uniform float u_spaceBlend;
uniform float u_horizonCosine;
uniform bool u_daylight;      // the real Sun (--time): the glow only where its air is lit
uniform vec3 u_sunDirection;  // unit, towards the Sun (the same axes as u_up)
uniform vec3 u_daylightBand;  // night's light, night's and day's sun-up cosines (daylightBand())
// The physically based sky (atmosphere/sky_view.hpp): azimuth from the Sun's vertical across,
// elevation up with rows crowded around the horizon at u_horizonElevation (radians).
uniform bool u_physical;
uniform sampler2D u_skyView;
uniform float u_horizonElevation;

const float kHalfPi = 1.5707963;

// atmosphere::skyViewRow.
float skyViewRow(float elevation, float horizon) {
  if (elevation < horizon) {
    return 0.5 * (1.0 - sqrt(clamp((horizon - elevation) / (horizon + kHalfPi), 0.0, 1.0)));
  }
  return 0.5 * (1.0 + sqrt(clamp((elevation - horizon) / (kHalfPi - horizon), 0.0, 1.0)));
}

vec3 physicalSky(vec3 direction, float mu) {
  vec3 across = direction - u_up * mu;
  vec3 sunAcross = u_sunDirection - u_up * dot(u_sunDirection, u_up);
  float azimuth = 0.0;
  if (dot(across, across) > 1e-12 && dot(sunAcross, sunAcross) > 1e-12) {
    azimuth = acos(clamp(dot(normalize(across), normalize(sunAcross)), -1.0, 1.0)) / 3.14159265;
  }
  float elevation = asin(clamp(mu, -1.0, 1.0));
  return texture(u_skyView, vec2(azimuth, skyViewRow(elevation, u_horizonElevation))).rgb;
}

out vec4 o_color;

void main() {
  vec3 direction = normalize(v_near.xyz / v_near.w);
  float mu = dot(direction, u_up);  // cosine of the ray's zenith angle
  float above = clamp((mu - u_horizonCosine) / (1.0 - u_horizonCosine), 0.0, 1.0);
  vec3 air = mix(u_horizon, u_zenith, pow(above, 0.45));

  // Closest approach of the ray to the globe's centre, in units of the air's thickness above
  // the surface: 0 at the surface, 1 at the top of the air.
  float along = u_cameraRadius * mu;
  float closest = along < 0.0 ? sqrt(max(u_cameraRadius * u_cameraRadius - along * along, 0.0))
                              : u_cameraRadius;
  float x = (closest - u_globeRadius) / u_atmosphereHeight;
  float fade = max(1.0 - x, 0.0);
  float glow = x <= 0.0 ? 1.0 : fade * fade;
  if (u_daylight) {
    // The air the ray grazes (its point nearest the centre) lit as the ground under it is.
    vec3 grazed = normalize(u_up * u_cameraRadius + direction * max(-along, 0.0));
    glow *= smoothstep(u_daylightBand.y, u_daylightBand.z, dot(grazed, u_sunDirection));
  }
  vec3 space = u_glow * glow;

  o_color = u_physical ? vec4(physicalSky(direction, mu), 1.0)
                       : vec4(mix(air, space, u_spaceBlend), 1.0);
}
