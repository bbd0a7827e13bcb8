// A KMZ: a zip holding a KML (doc.kml, else the first .kml at the root) and the images it
// references, read in place through GDAL's /vsizip/ (nothing is extracted to disk).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/result.hpp"

namespace globe::overlays {

struct KmzArchive {
  std::filesystem::path file;  // absolute
  std::string kmlEntry;        // "doc.kml", or the KML the archive holds instead
};

// Opens the zip and finds its KML. Errors name the file: not a zip, no .kml inside.
Result<KmzArchive> openKmz(const std::filesystem::path& file);

// "/vsizip/<absolute file>/<entry>": what GDAL opens, and how the model names such a file.
std::string kmzEntryPath(const KmzArchive& archive, const std::string& entry);

// An entry's bytes (its uncompressed size checked against maxBytes before reading); nullopt
// when the archive has no such entry. Errors: too large, unreadable.
Result<std::optional<std::vector<std::byte>>> readKmzEntry(const KmzArchive& archive,
                                                           const std::string& entry,
                                                           uint64_t maxBytes);

}  // namespace globe::overlays
