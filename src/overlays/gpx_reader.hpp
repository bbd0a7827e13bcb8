// GPX 1.0 and 1.1 to the overlay model: each <trk> a placemark with one LineString per
// <trkseg>, each <rte> a LineString, each <wpt> a Point; all clamped to the ground, <ele> kept as
// heightMeters.
#pragma once

#include <filesystem>
#include <string_view>

#include "core/result.hpp"
#include "overlays/overlay_model.hpp"

namespace globe::overlays {

// Reads GPX text; `file` names it in errors and in the document (named by <metadata><name> or
// GPX 1.0's <name>, else the file's name). Segments and routes of fewer than two points are
// skipped. Errors: not XML, not GPX, a point without a valid lat/lon (naming its line).
Result<OverlayDocument> readGpxText(std::string_view text, const std::filesystem::path& file);

}  // namespace globe::overlays
