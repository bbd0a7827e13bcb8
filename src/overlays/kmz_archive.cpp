#include "overlays/kmz_archive.hpp"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_string.h>
#include <cpl_vsi.h>

#include <algorithm>
#include <cctype>

#include "overlays/quiet_gdal.hpp"

namespace globe::overlays {
namespace {

bool endsWithKml(const std::string& name) {
  if (name.size() < 4) return false;
  std::string tail = name.substr(name.size() - 4);
  std::transform(tail.begin(), tail.end(), tail.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return tail == ".kml";
}

std::vector<std::string> listing(char** list) {
  std::vector<std::string> names;
  for (char** name = list; name != nullptr && *name != nullptr; ++name) names.emplace_back(*name);
  CSLDestroy(list);
  return names;
}

}  // namespace

std::string kmzEntryPath(const KmzArchive& archive, const std::string& entry) {
  return "/vsizip/" + archive.file.string() + "/" + entry;
}

Result<KmzArchive> openKmz(const std::filesystem::path& file) {
  const QuietGdal quiet;
  std::error_code ec;
  KmzArchive archive{std::filesystem::absolute(file, ec), {}};
  if (ec) return makeError(file.string() + ": " + ec.message());
  const std::string root = "/vsizip/" + archive.file.string();
  // (Stat says "not a folder" for a zip of one file, which GDAL then opens as that file.)
  const std::vector<std::string> names = listing(VSIReadDir(root.c_str()));
  if (names.empty()) {
    return makeError(file.string() + ": not a KMZ (the file is not a zip archive)");
  }
  if (std::find(names.begin(), names.end(), "doc.kml") != names.end()) {
    archive.kmlEntry = "doc.kml";
    return archive;
  }
  // KMZ: without doc.kml, the first .kml file at the root.
  for (const std::string& name : names) {
    if (endsWithKml(name)) {
      archive.kmlEntry = name;
      return archive;
    }
  }
  return makeError(file.string() + ": a zip archive with no .kml file at its root, not a KMZ");
}

Result<std::optional<std::vector<std::byte>>> readKmzEntry(const KmzArchive& archive,
                                                           const std::string& entry,
                                                           uint64_t maxBytes) {
  const QuietGdal quiet;
  const std::string path = kmzEntryPath(archive, entry);
  VSIStatBufL stat;
  if (VSIStatL(path.c_str(), &stat) != 0 || !VSI_ISREG(stat.st_mode)) {
    return std::optional<std::vector<std::byte>>();
  }
  if (stat.st_size < 0 || static_cast<uint64_t>(stat.st_size) > maxBytes) {
    return makeError(path + ": " + std::to_string(stat.st_size) + " bytes, more than the " +
                     std::to_string(maxBytes) + " allowed");
  }
  VSILFILE* in = VSIFOpenL(path.c_str(), "rb");
  if (in == nullptr) return makeError(path + ": cannot open (" + CPLGetLastErrorMsg() + ")");
  std::vector<std::byte> bytes(static_cast<size_t>(stat.st_size));
  const size_t read = VSIFReadL(bytes.data(), 1, bytes.size(), in);
  VSIFCloseL(in);
  if (read != bytes.size()) {
    return makeError(path + ": read " + std::to_string(read) + " of " +
                     std::to_string(bytes.size()) + " bytes (a damaged archive)");
  }
  return std::optional<std::vector<std::byte>>(std::move(bytes));
}

}  // namespace globe::overlays
