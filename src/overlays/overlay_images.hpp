// Icon and ground overlay images named by a KML href, found and decoded once per document:
// beside the KML on disk, or inside its KMZ (then beside the KMZ, where Google Earth also looks).
// An overlay file reaches nothing but itself: a local href resolves only inside its archive or
// its own folder and below (no absolute path, no `..` out of it, no symlink leading out, only
// regular files: no device or FIFO); anything else is refused and named in warnings().
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "formats/image_io.hpp"
#include "overlays/kmz_archive.hpp"

namespace globe::overlays {

struct ResolvedImage {
  std::string href;  // what the model records (overlay_model.hpp's Style::iconHref)
  std::shared_ptr<const formats::ImageRgba> image;  // null: a URL, missing or undecodable
};

class OverlayImages {
 public:
  // Decoded pixels one document may hold in all: a file naming many large images still reads.
  static constexpr uint64_t kMaxDecodedBytes = uint64_t{512} << 20;

  // Relative hrefs resolve against kmlDirectory (absolute paths and file:// URLs as they are).
  explicit OverlayImages(std::filesystem::path kmlDirectory);
  // Relative hrefs resolve inside the archive first, then beside the .kmz.
  explicit OverlayImages(KmzArchive archive);

  // Never fails: whatever cannot be found, is refused or cannot be decoded gives a null image,
  // and a warning (URLs are the caller's).
  ResolvedImage resolve(const std::string& href);
  // The hrefs refused, missing or undecodable so far, each once with the reason
  // ("image href \"../x.png\": outside ...; not read").
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  std::optional<ResolvedImage> fromArchive(const std::string& relative);
  ResolvedImage fromDisk(const std::string& href, const std::filesystem::path& path);
  // stb_image's decode, else GDAL's; the error says both.
  Result<formats::ImageRgba> decoded(std::span<const std::byte> bytes,
                                     const std::string& name) const;
  // The decoded image within the document's budget, else null with a warning naming the href.
  std::shared_ptr<const formats::ImageRgba> keep(const std::string& href,
                                                 Result<formats::ImageRgba> image);
  void warn(const std::string& href, const std::string& why);

  std::filesystem::path directory_;
  std::optional<KmzArchive> archive_;
  std::map<std::string, ResolvedImage> cache_;
  uint64_t decodedBytes_ = 0;
  std::vector<std::string> warnings_;
};

}  // namespace globe::overlays
