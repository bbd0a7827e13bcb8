// How strongly the terrain's hill-shading darkens a draped imagery layer. Imagery carries its own
// shadows only at its own resolution: Blue Marble's 7 km texels over Mount Fuji's 90 m samples
// show no relief at all unless the terrain's light is applied, while 30 m Landsat over the same
// samples already has its shadows and would look doubly shaded. So the light is weighted by how
// much finer the terrain is than the imagery texel drawn on it (as Google Earth does).
#pragma once

#include <optional>
#include <string_view>

namespace globe::terrain {

// --lighting: Auto weighs the light by resolution (reliefShadingWeight), On applies it fully
// (weight 1), Off leaves the imagery's own shading alone (weight 0).
enum class ImageryLighting { Off, Auto, On };

std::optional<ImageryLighting> parseImageryLighting(std::string_view text);  // auto | on | off
std::string_view toString(ImageryLighting lighting);
ImageryLighting nextImageryLighting(ImageryLighting lighting);  // auto → on → off → auto

// Full shading where the imagery texel is at least this many terrain samples across...
inline constexpr double kFullReliefTexelRatio = 4.0;
// ...the gentle floor where it is no larger than one sample: the imagery's own shadows show
// there, the terrain's light only rounds the landforms a little.
inline constexpr double kGentleReliefTexelRatio = 1.0;
inline constexpr double kGentleReliefWeight = 0.3;

// The weight w of the terrain's light on a layer (drawn light = mix(1, light, w)) for imagery
// texels imageryTexelMeters across over terrain samples terrainSpacingMeters apart:
// kGentleReliefWeight at a ratio <= 1, 1 at >= 4, linear in log(ratio) between. 1 where the
// ratio is not a positive finite number (no known texel: shade rather than flatten).
double reliefShadingWeight(double imageryTexelMeters, double terrainSpacingMeters);

// How much of level ground's light (the globe's own shading, apart from the relief's) imagery
// takes: Off 0, On 1, Auto kGentleReliefWeight everywhere, so that it never steps between tiles.
double levelGroundLightWeight(ImageryLighting lighting);

// The relief's weight for a mode: Off 0, On 1, Auto reliefShadingWeight.
double imageryLightWeight(ImageryLighting lighting, double imageryTexelMeters,
                          double terrainSpacingMeters);

}  // namespace globe::terrain
