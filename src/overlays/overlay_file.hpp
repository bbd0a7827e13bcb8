// Overlay files (KML, KMZ, GeoJSON, GPX) read into the overlay model, whatever their kind.
#pragma once

#include <cstdint>
#include <filesystem>

#include "core/result.hpp"
#include "overlays/overlay_model.hpp"

namespace globe::overlays {

// Larger files are refused before reading (a KMZ's KML counts its uncompressed size). The
// readers parse a whole document first, at ~8-12 bytes of memory per byte of GeoJSON and ~13 per
// byte of XML (measured: docs/robustness.md), so these keep one file's parse within ~1 GB; the
// readers then count placemarks and vertices (overlay_budget.hpp).
inline constexpr uint64_t kMaxOverlayFileBytes = uint64_t{80} << 20;
inline constexpr uint64_t kMaxOverlayXmlBytes = uint64_t{64} << 20;  // KML (in a KMZ too), GPX

// Reads a KML, KMZ, GeoJSON (.geojson/.json) or GPX file, chosen by its content (and extension
// for KMZ zip). Errors name the file and what is wrong.
Result<OverlayDocument> readOverlayFile(const std::filesystem::path& file);

// Makes every placemark and ground overlay visible (KML's <visibility>0</visibility> and hidden
// Folders ignored), for users who want all a file holds without ticking items one by one.
void showEverything(OverlayDocument& document);

}  // namespace globe::overlays
