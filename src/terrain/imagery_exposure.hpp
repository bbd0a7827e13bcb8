// Imagery as photographed: a draped photo is lit only within its own range (its highlights are
// its own Sun's, so the terrain's light never pushes a colour past the photo's), and a dark photo
// is given an exposure that keeps it readable. terrain.frag evaluates the same formulas per
// fragment; these are their reference, for tests and for choosing each layer's exposure.
#pragma once

#include <cstdint>
#include <span>

namespace globe::terrain {

// A layer's median luminance (Rec. 709 luma of the sRGB-coded values, 0..1) maps at least to
// this: the Blue Marble's land is ~0.1 (its forests ~0.06), black on black once shaded.
inline constexpr double kReadableMedianLuminance = 0.3;
// The strongest exposure given: darks at most this many times as bright.
inline constexpr double kMaximumExposure = 3.0;

// Median luma of the opaque texels (alpha 255) of straight-alpha RGBA8 pixels; NaN if none.
double medianOpaqueLuminance(std::span<const uint8_t> rgba);

// The exposure k of a layer whose median luminance is `median`: 1 (none) when it is readable
// already or unknown (NaN), else the k that lifts the median to kReadableMedianLuminance, at most
// kMaximumExposure.
double exposureForMedianLuminance(double median);

// The exposure curve on a 0..1 value: 1 − (1 − c)^k, a film-like response: darks × ~k, white
// stays white, monotone, so nothing clips and order is kept.
double exposedValue(double value, double exposure);

// The multiplier on level ground's light for a slope whose relief light (land light over level
// ground's) is `relief`, where level ground gets `levelLight` (0..1): shadowed slopes (relief <=
// 1) darken by relief; lit slopes brighten by relief at first and saturate at 1 / levelLight, so
// the lit colour never exceeds the photo's: levelLight · multiplier <= 1.
double reliefLightMultiplier(double relief, double levelLight);

}  // namespace globe::terrain
