#include "services/pmtiles_imagery.hpp"

#include <nlohmann/json.hpp>

#include "compression/gzip_bytes.hpp"
#include "formats/pmtiles.hpp"
#include "services/recent_items.hpp"
#include "services/url_reader.hpp"
#include "services/url_template.hpp"
#include "transport/http_client.hpp"

namespace globe::services {
namespace {

// The spec keeps the header and root directory in the first 16 KiB: one read.
constexpr size_t kHeadBytes = 16384;

// What a tile type is, in words, for the error that refuses it.
std::string tileTypeName(formats::PmtilesTileType type) {
  switch (type) {
    case formats::PmtilesTileType::Mvt:
      return "Mapbox vector tiles, not imagery";
    default:
      return "of unknown type " + std::to_string(static_cast<int>(type));
  }
}
constexpr uint64_t kMaxDirectoryBytes = uint64_t{32} << 20;
constexpr uint64_t kMaxTileBytes = uint64_t{16} << 20;
constexpr size_t kLeafDirectories = 64;
constexpr int kMaxDirectoryDepth = 4;

class PmtilesImagery final : public ServiceImagery {
 public:
  PmtilesImagery(ImageryServiceDescription d, std::shared_ptr<const transport::ByteFile> file,
                 formats::PmtilesHeader header, std::vector<formats::PmtilesEntry> root)
      : ServiceImagery(std::move(d)),
        file_(std::move(file)),
        header_(header),
        root_(std::move(root)) {}

 protected:
  Result<std::optional<std::vector<std::byte>>> fetchSourceTile(size_t matrix, uint64_t column,
                                                                uint64_t row) override {
    const uint32_t z = header_.minZoom + static_cast<uint32_t>(matrix);
    const uint64_t id = formats::pmtilesTileId(z, column, row);
    const std::vector<formats::PmtilesEntry>* directory = &root_;
    std::shared_ptr<const std::vector<formats::PmtilesEntry>> leaf;
    for (int depth = 0; depth < kMaxDirectoryDepth; ++depth) {
      const auto entry = formats::findPmtilesEntry(*directory, id);
      if (!entry) return std::optional<std::vector<std::byte>>();
      if (entry->runLength > 0) {
        auto bytes = readSection(header_.tileDataOffset + entry->offset, entry->length,
                                 kMaxTileBytes, "a tile");
        if (!bytes) return Error{bytes.error()};
        if (header_.tileCompression == formats::PmtilesCompression::Gzip) {
          auto inflated =
              compression::gunzipIfNeeded(*bytes, sourceTileUrl(matrix, column, row), kMaxTileBytes);
          if (!inflated) return Error{inflated.error()};
          return std::optional<std::vector<std::byte>>(std::move(*inflated));
        }
        return std::optional<std::vector<std::byte>>(std::move(*bytes));
      }
      auto next = leafDirectory(header_.leavesOffset + entry->offset, entry->length);
      if (!next) return Error{next.error()};
      leaf = std::move(*next);
      directory = leaf.get();
    }
    return makeError(file_->location() + ": PMTiles leaf directories nested too deep");
  }

  std::string sourceTileUrl(size_t matrix, uint64_t column, uint64_t row) const override {
    return file_->location() + " tile " + std::to_string(header_.minZoom + matrix) + "/" +
           std::to_string(column) + "/" + std::to_string(row);
  }

 private:
  Result<std::vector<std::byte>> readSection(uint64_t offset, uint64_t length, uint64_t maximum,
                                             const char* what) {
    if (length > maximum) {
      return makeError(file_->location() + ": " + what + " of " + std::to_string(length) +
                       " bytes (at most " + std::to_string(maximum) + ")");
    }
    std::vector<std::byte> bytes(static_cast<size_t>(length));
    if (auto read = file_->read(bytes, offset); !read) return Error{read.error()};
    return bytes;
  }

  Result<std::shared_ptr<const std::vector<formats::PmtilesEntry>>> leafDirectory(uint64_t offset,
                                                                                  uint64_t length) {
    if (auto kept = leaves_.find(offset)) return *kept;
    auto bytes = readSection(offset, length, kMaxDirectoryBytes, "a leaf directory");
    if (!bytes) return Error{bytes.error()};
    auto entries = decodeDirectory(*bytes, header_, file_->location());
    if (!entries) return Error{entries.error()};
    auto shared = std::make_shared<const std::vector<formats::PmtilesEntry>>(std::move(*entries));
    leaves_.put(offset, shared);
    return shared;
  }

 public:
  static Result<std::vector<formats::PmtilesEntry>> decodeDirectory(
      std::span<const std::byte> bytes, const formats::PmtilesHeader& header,
      const std::string& name) {
    if (header.internalCompression == formats::PmtilesCompression::Gzip) {
      auto inflated = compression::gunzipIfNeeded(bytes, name, kMaxDirectoryBytes);
      if (!inflated) return Error{inflated.error()};
      return formats::decodePmtilesDirectory(*inflated, name);
    }
    return formats::decodePmtilesDirectory(bytes, name);
  }

 private:
  std::shared_ptr<const transport::ByteFile> file_;
  formats::PmtilesHeader header_;
  std::vector<formats::PmtilesEntry> root_;
  RecentItems<uint64_t, std::shared_ptr<const std::vector<formats::PmtilesEntry>>> leaves_{
      kLeafDirectories};
};

bool supported(formats::PmtilesCompression c) {
  return c == formats::PmtilesCompression::None || c == formats::PmtilesCompression::Gzip;
}

}  // namespace

Result<std::unique_ptr<ServiceImagery>> openPmtilesImagery(
    const std::string& spec, std::shared_ptr<transport::Network> network) {
  std::string url = spec;
  auto options = takeQueryOptions(url, {"attribution"});
  const std::string path = url.substr(0, url.find('?'));
  const size_t slash = path.rfind('/');
  const std::string folder = slash == std::string::npos ? "." : path.substr(0, slash);
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  auto source = network ? network->open(folder.empty() ? "/" : folder)
                        : transport::openByteSource(folder.empty() ? "/" : folder, nullptr);
  if (!source) return Error{source.error()};
  auto opened = (*source)->open(name, kHeadBytes);
  if (!opened) return Error{opened.error()};
  const std::string location = (*source)->locationOf(name);
  const uint64_t fileBytes = opened->file->sizeBytes();
  auto header = formats::decodePmtilesHeader(opened->head, fileBytes, location);
  if (!header) return Error{header.error()};
  if (header->tileType != formats::PmtilesTileType::Png &&
      header->tileType != formats::PmtilesTileType::Jpeg &&
      header->tileType != formats::PmtilesTileType::Webp &&
      header->tileType != formats::PmtilesTileType::Avif) {
    return makeError(location + ": its tiles are " + tileTypeName(header->tileType) +
                     "; imagery is read from PNG, JPEG, WebP or AVIF tiles");
  }
  if (!supported(header->internalCompression) || !supported(header->tileCompression)) {
    return makeError(location + ": compressed with other than gzip (brotli and zstd are not read)");
  }
  auto readAt = [&](uint64_t offset, uint64_t length) -> Result<std::vector<std::byte>> {
    if (length > kMaxDirectoryBytes) return makeError(location + ": a directory too large");
    if (offset + length <= opened->head.size()) {
      return std::vector<std::byte>(opened->head.begin() + static_cast<ptrdiff_t>(offset),
                                    opened->head.begin() + static_cast<ptrdiff_t>(offset + length));
    }
    std::vector<std::byte> bytes(static_cast<size_t>(length));
    if (auto read = opened->file->read(bytes, offset); !read) return Error{read.error()};
    return bytes;
  };
  auto rootBytes = readAt(header->rootOffset, header->rootLength);
  if (!rootBytes) return Error{rootBytes.error()};
  auto root = PmtilesImagery::decodeDirectory(*rootBytes, *header, location);
  if (!root) return Error{root.error()};

  // Its metadata: the tile size and attribution where it gives them.
  uint32_t tileSize = 256;
  std::string attribution;
  if (header->metadataLength > 0 && header->metadataLength <= (uint64_t{1} << 20)) {
    auto metadata = readAt(header->metadataOffset, header->metadataLength);
    if (metadata && header->internalCompression == formats::PmtilesCompression::Gzip) {
      metadata = compression::gunzipIfNeeded(*metadata, location, size_t{4} << 20);
    }
    if (metadata) {
      try {
        const auto j = nlohmann::json::parse(
            std::string_view(reinterpret_cast<const char*>(metadata->data()), metadata->size()));
        if (j.is_object()) {
          // A number, or (as QGIS writes it) a string.
          if (auto t = j.find("tileSize"); t != j.end()) {
            const long size = t->is_number_unsigned() ? t->get<long>()
                              : t->is_string()        ? std::atol(t->get<std::string>().c_str())
                                                      : 0;
            if (size == 256 || size == 512) tileSize = static_cast<uint32_t>(size);
          }
          if (auto a = j.find("attribution"); a != j.end() && a->is_string()) attribution = *a;
        }
      } catch (const nlohmann::json::exception&) {
        // Metadata is optional: a malformed one is ignored, the tiles still read.
      }
    }
  }
  ImageryServiceDescription d;
  d.location = "pmtiles:" + spec;
  d.driver = "PMTiles";
  d.tiling = webMercatorQuad(header->minZoom, header->maxZoom, tileSize);
  d.bounds = {header->westDegrees, std::max(header->southDegrees, -kWebMercatorMaxLatitudeDegrees),
              header->eastDegrees, std::min(header->northDegrees, kWebMercatorMaxLatitudeDegrees)};
  d.attribution = options.count("attribution") ? options["attribution"] : attribution;
  d.remote = (*source)->remote();
  return std::unique_ptr<ServiceImagery>(std::make_unique<PmtilesImagery>(
      std::move(d), std::move(opened->file), *header, std::move(*root)));
}

}  // namespace globe::services
