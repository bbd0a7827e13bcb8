#include "overlays/overlay_images.hpp"

#include <algorithm>
#include <cctype>
#include <span>
#include <string_view>

#include "overlays/gdal_image.hpp"
#include "overlays/xml_elements.hpp"
#include "transport/atomic_file.hpp"

namespace globe::overlays {
namespace {

constexpr uint64_t kMaxImageFileBytes = uint64_t{256} << 20;

bool startsWithNoCase(std::string_view text, std::string_view prefix) {
  return text.size() >= prefix.size() &&
         std::equal(prefix.begin(), prefix.end(), text.begin(), [](char a, char b) {
           return std::tolower(static_cast<unsigned char>(a)) ==
                  std::tolower(static_cast<unsigned char>(b));
         });
}

// "%20" and friends, which KML writers put in local hrefs too.
std::string percentDecoded(std::string_view text) {
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '%' && i + 2 < text.size() &&
        std::isxdigit(static_cast<unsigned char>(text[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(text[i + 2]))) {
      out += static_cast<char>(std::stoi(std::string(text.substr(i + 1, 2)), nullptr, 16));
      i += 2;
    } else {
      out += text[i];
    }
  }
  return out;
}

// Why a local path may not be read as an overlay's image, or "" when it may: it must lie in
// `folder` or below it, also once symlinks are followed, and be a regular file.
std::string refusal(const std::filesystem::path& folder, const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  if (path.is_absolute()) return "an absolute path: an overlay reads only files beside it";
  const fs::path joined = (folder / path).lexically_normal();
  const fs::path inside = joined.lexically_relative(folder.lexically_normal());
  if (inside.empty() || *inside.begin() == "..") return "outside the overlay's folder";
  std::error_code ec;
  const fs::path real = fs::weakly_canonical(joined, ec);
  const fs::path realFolder = fs::weakly_canonical(folder, ec);
  const fs::path realInside = real.lexically_relative(realFolder);
  if (ec || realInside.empty() || *realInside.begin() == "..") {
    return "leads outside the overlay's folder (a symlink)";
  }
  const fs::file_status status = fs::status(real, ec);
  if (!ec && fs::exists(status) && !fs::is_regular_file(status)) return "not a regular file";
  return "";
}

}  // namespace

OverlayImages::OverlayImages(std::filesystem::path kmlDirectory)
    : directory_(std::move(kmlDirectory)) {}

OverlayImages::OverlayImages(KmzArchive archive)
    : directory_(std::filesystem::absolute(archive.file).parent_path()),
      archive_(std::move(archive)) {}

ResolvedImage OverlayImages::resolve(const std::string& rawHref) {
  const std::string href(trimmed(rawHref));
  if (href.empty()) return {};
  if (auto cached = cache_.find(href); cached != cache_.end()) return cached->second;
  ResolvedImage resolved;
  if (startsWithNoCase(href, "http://") || startsWithNoCase(href, "https://")) {
    resolved.href = href;  // fetched, if at all, by the caller
  } else {
    std::string local = percentDecoded(href);
    if (startsWithNoCase(local, "file://")) local.erase(0, 7);
    const std::filesystem::path path(local);
    std::optional<ResolvedImage> inArchive;
    if (archive_ && path.is_relative()) inArchive = fromArchive(local);
    resolved = inArchive ? std::move(*inArchive) : fromDisk(href, path);
  }
  cache_.emplace(href, resolved);
  return resolved;
}

std::optional<ResolvedImage> OverlayImages::fromArchive(const std::string& relative) {
  const std::string entry = std::filesystem::path(relative).lexically_normal().generic_string();
  if (entry.empty() || entry.starts_with("..")) return std::nullopt;
  auto bytes = readKmzEntry(*archive_, entry, kMaxImageFileBytes);
  if (bytes && !bytes->has_value()) return std::nullopt;  // not in the archive
  ResolvedImage resolved{kmzEntryPath(*archive_, entry), nullptr};
  if (!bytes) {
    warn(relative, bytes.error());
  } else {
    resolved.image = keep(relative, decoded(**bytes, resolved.href));
  }
  return resolved;
}

ResolvedImage OverlayImages::fromDisk(const std::string& href, const std::filesystem::path& path) {
  if (const std::string why = refusal(directory_, path); !why.empty()) {
    warnings_.push_back("image href \"" + href.substr(0, 200) + "\": " + why + "; not read");
    return {href, nullptr};
  }
  const std::filesystem::path normal = (directory_ / path).lexically_normal();
  ResolvedImage resolved{normal.string(), nullptr};
  auto bytes = transport::readWholeFile(normal, kMaxImageFileBytes);
  if (!bytes) {
    warn(href, bytes.error());
  } else {
    resolved.image = keep(href, decoded(*bytes, resolved.href));
  }
  return resolved;
}

Result<formats::ImageRgba> OverlayImages::decoded(std::span<const std::byte> bytes,
                                                  const std::string& name) const {
  auto image = formats::decodeImageRgba(bytes, name);
  if (image) return image;
  // Beyond stb_image (GeoTIFF above all), and beyond its 4096-pixel side: GDAL's image drivers,
  // within what this document's images may still take.
  auto viaGdal = decodeImageWithGdal(bytes, name, kMaxDecodedBytes - decodedBytes_);
  if (viaGdal) return viaGdal;
  return Error{image.error() + "; " + viaGdal.error()};
}

std::shared_ptr<const formats::ImageRgba> OverlayImages::keep(const std::string& href,
                                                              Result<formats::ImageRgba> image) {
  if (!image) {
    warn(href, image.error());
    return nullptr;
  }
  if (decodedBytes_ + image->pixels.size() > kMaxDecodedBytes) {
    warn(href, "its pixels would take this overlay's images beyond " +
                   std::to_string(kMaxDecodedBytes >> 20) + " MiB");
    return nullptr;
  }
  decodedBytes_ += image->pixels.size();
  return std::make_shared<const formats::ImageRgba>(std::move(image).value());
}

void OverlayImages::warn(const std::string& href, const std::string& why) {
  warnings_.push_back("image href \"" + href.substr(0, 200) + "\": " + why + "; not drawn");
}

}  // namespace globe::overlays
