#include "overlays/overlay_file.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <string>
#include <string_view>

#include "overlays/geojson_reader.hpp"
#include "overlays/gpx_reader.hpp"
#include "overlays/kml_reader.hpp"
#include "overlays/kmz_archive.hpp"
#include "overlays/overlay_images.hpp"
#include "transport/atomic_file.hpp"

namespace globe::overlays {
namespace {

bool startsWithZipSignature(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  char head[4] = {};
  return in.read(head, sizeof head) && std::string_view(head, 4) == std::string_view("PK\3\4", 4);
}

bool hasKmzExtension(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".kmz";
}

// The root element's local name, past the XML declaration, comments, a DOCTYPE and
// processing instructions; empty when there is none.
std::string_view xmlRootName(std::string_view text) {
  size_t at = 0;
  while (at < text.size()) {
    at = text.find('<', at);
    if (at == std::string_view::npos) return {};
    const std::string_view rest = text.substr(at);
    size_t skipTo = std::string_view::npos;
    if (rest.starts_with("<?")) {
      skipTo = text.find("?>", at);
    } else if (rest.starts_with("<!--")) {
      skipTo = text.find("-->", at);
    } else if (rest.starts_with("<!")) {
      skipTo = text.find('>', at);
    } else {
      size_t end = 1;
      while (end < rest.size() &&
             std::string_view(" \t\r\n/>").find(rest[end]) == std::string_view::npos) {
        ++end;
      }
      std::string_view name = rest.substr(1, end - 1);
      if (const size_t colon = name.find(':'); colon != std::string_view::npos) {
        name.remove_prefix(colon + 1);
      }
      return name;
    }
    if (skipTo == std::string_view::npos) return {};
    at = skipTo + 1;
  }
  return {};
}

Result<OverlayDocument> readKmz(const std::filesystem::path& file) {
  auto archive = openKmz(file);
  if (!archive) return Error{archive.error()};
  auto kml = readKmzEntry(*archive, archive->kmlEntry, kMaxOverlayXmlBytes);
  if (!kml) return makeError(file.string() + ": " + kml.error());
  if (!kml->has_value()) return makeError(file.string() + ": cannot read " + archive->kmlEntry);
  const std::vector<std::byte>& bytes = **kml;
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  OverlayImages images(*archive);
  return readKmlText(text, file, images);
}

}  // namespace

Result<OverlayDocument> readOverlayFile(const std::filesystem::path& file) {
  const std::string where = file.string();
  if (startsWithZipSignature(file)) {
    std::error_code ec;
    if (std::filesystem::file_size(file, ec) > kMaxOverlayFileBytes && !ec) {
      return makeError(where + ": larger than " + std::to_string(kMaxOverlayFileBytes >> 20) +
                       " MiB");
    }
    return readKmz(file);
  }
  auto bytes = transport::readWholeFile(file, kMaxOverlayFileBytes);
  if (!bytes) return Error{bytes.error()};
  if (hasKmzExtension(file)) {
    return makeError(where + ": not a KMZ (the file is not a zip archive)");
  }
  std::string_view text(reinterpret_cast<const char*>(bytes->data()), bytes->size());
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  const size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return makeError(where + ": an empty file");
  if (text[first] == '{' || text[first] == '[') return readGeoJsonText(text, file);
  if (text[first] == '<') {
    if (text.size() > kMaxOverlayXmlBytes) {
      return makeError(where + ": larger than " + std::to_string(kMaxOverlayXmlBytes >> 20) +
                       " MiB, the most KML or GPX one overlay file may hold; split it");
    }
    if (xmlRootName(text) == "gpx") return readGpxText(text, file);
    std::error_code ec;
    OverlayImages images(std::filesystem::absolute(file, ec).parent_path());
    return readKmlText(text, file, images);
  }
  return makeError(where +
                   ": neither KML, KMZ, GeoJSON nor GPX (the file starts with neither "
                   "'<' nor '{')");
}

void showEverything(OverlayDocument& document) {
  for (Placemark& placemark : document.placemarks) placemark.visible = true;
  for (GroundOverlay& overlay : document.groundOverlays) overlay.visible = true;
}

}  // namespace globe::overlays
