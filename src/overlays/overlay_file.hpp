// Overlay files (KML, KMZ, GeoJSON, GPX) read into the overlay model, whatever their kind.
#pragma once

#include <cstdint>
#include <filesystem>

#include "core/result.hpp"
#include "overlays/overlay_model.hpp"

namespace globe::overlays {

// Larger files are refused before reading (a KMZ's KML counts its uncompressed size).
inline constexpr uint64_t kMaxOverlayFileBytes = uint64_t{512} << 20;

// Reads a KML, KMZ, GeoJSON (.geojson/.json) or GPX file, chosen by its content (and extension
// for KMZ zip). Errors name the file and what is wrong.
Result<OverlayDocument> readOverlayFile(const std::filesystem::path& file);

// Makes every placemark and ground overlay visible (KML's <visibility>0</visibility> and hidden
// Folders ignored), for users who want all a file holds without ticking items one by one.
void showEverything(OverlayDocument& document);

}  // namespace globe::overlays
