// KML (2.0–2.2 and Google's gx: extensions) to the overlay model: Documents and Folders with
// their visibility, Placemarks with every geometry kind, GroundOverlays with LatLonBox, and the
// style cascade. NetworkLink, Model, ScreenOverlay, PhotoOverlay and Tour are ignored.
#pragma once

#include <filesystem>
#include <string_view>

#include "core/result.hpp"
#include "overlays/overlay_images.hpp"
#include "overlays/overlay_model.hpp"

namespace globe::overlays {

// Documents and Folders, and MultiGeometries, nest at most this deep (a hostile file's recursion).
inline constexpr int kMaxKmlNesting = 64;

// Reads KML text; `file` names it in errors and in the document. Icon and overlay hrefs resolve
// through `images`. Errors: not XML, not KML, bad coordinates (naming the placemark and its
// line), nesting too deep. Placemarks without a drawable geometry are skipped; a LineString
// needs two positions, a Polygon's outer ring three distinct corners (holes that have fewer are
// dropped); a standalone LinearRing is read as a closed LineString.
Result<OverlayDocument> readKmlText(std::string_view text, const std::filesystem::path& file,
                                    OverlayImages& images);

}  // namespace globe::overlays
