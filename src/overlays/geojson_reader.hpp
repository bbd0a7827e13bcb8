// GeoJSON (RFC 7946) to the overlay model: a FeatureCollection, a Feature or a bare geometry;
// every geometry type, GeometryCollections flattened; simplestyle-spec properties as the style.
#pragma once

#include <filesystem>
#include <string_view>

#include "core/result.hpp"
#include "overlays/overlay_model.hpp"

namespace globe::overlays {

// GeometryCollections nest at most this deep, JSON arrays and objects 4 times as deep.
inline constexpr int kMaxGeoJsonNesting = 64;

// Reads GeoJSON text; `file` names it in errors and in the document. A feature's name is its
// properties' "name" (else "title", "NAME", "name_en"), its description "description"; stroke,
// stroke-width, stroke-opacity, fill, fill-opacity and marker-color set the style, what is
// absent keeps Google Earth's defaults. Geometries are clamped to the ground; a third coordinate
// is kept as heightMeters. Features without a geometry are skipped. Errors: not JSON, not
// GeoJSON, malformed or out-of-range coordinates (naming the feature), nesting too deep.
Result<OverlayDocument> readGeoJsonText(std::string_view text, const std::filesystem::path& file);

}  // namespace globe::overlays
