#include "overlays/gdal_image.hpp"

#include <cpl_vsi.h>
#include <gdal.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "overlays/quiet_gdal.hpp"

namespace globe::overlays {
namespace {

constexpr int kMaxSide = 32768;
// Only image drivers: an overlay's image is never opened as a database, a URL or a VRT that
// names other files.
const char* const kImageDrivers[] = {"GTiff", "COG", "PNG", "JPEG", "GIF", "BMP", "WEBP", nullptr};

struct DatasetCloser {
  void operator()(void* dataset) const { GDALClose(dataset); }
};

// A /vsimem/ name no other call uses, removed when done.
class MemoryFile {
 public:
  explicit MemoryFile(std::span<const std::byte> bytes) {
    static std::atomic<uint64_t> counter{0};
    name_ = "/vsimem/globe-overlay-image-" + std::to_string(counter++);
    // GDAL only reads the buffer (bTakeOwnership false); the cast is its C interface's.
    auto* data = reinterpret_cast<GByte*>(const_cast<std::byte*>(bytes.data()));
    VSIFCloseL(
        VSIFileFromMemBuffer(name_.c_str(), data, static_cast<vsi_l_offset>(bytes.size()), FALSE));
  }
  ~MemoryFile() { VSIUnlink(name_.c_str()); }
  MemoryFile(const MemoryFile&) = delete;
  MemoryFile& operator=(const MemoryFile&) = delete;
  const std::string& name() const { return name_; }

 private:
  std::string name_;
};

// Fills RGBA from the bands as read: 1 grey or palette, 2 grey + alpha, 3 RGB, 4 RGBA.
void toRgba(const std::vector<std::vector<uint8_t>>& bands, GDALColorTableH palette,
            std::vector<uint8_t>& rgba) {
  const size_t pixels = bands[0].size();
  for (size_t k = 0; k < pixels; ++k) {
    std::array<uint8_t, 4> p{bands[0][k], bands[0][k], bands[0][k], 255};
    if (palette != nullptr && bands.size() == 1) {
      if (const GDALColorEntry* e = GDALGetColorEntry(palette, bands[0][k])) {
        p = {static_cast<uint8_t>(e->c1), static_cast<uint8_t>(e->c2), static_cast<uint8_t>(e->c3),
             static_cast<uint8_t>(e->c4)};
      }
    } else if (bands.size() == 2) {
      p[3] = bands[1][k];
    } else if (bands.size() >= 3) {
      p = {bands[0][k], bands[1][k], bands[2][k], bands.size() >= 4 ? bands[3][k] : uint8_t{255}};
    }
    std::copy(p.begin(), p.end(), rgba.begin() + static_cast<std::ptrdiff_t>(4 * k));
  }
}

}  // namespace

Result<formats::ImageRgba> decodeImageWithGdal(std::span<const std::byte> bytes,
                                               const std::string& name, uint64_t maxDecodedBytes) {
  GDALAllRegister();
  const QuietGdal quiet;
  const MemoryFile file(bytes);
  std::unique_ptr<void, DatasetCloser> dataset(GDALOpenEx(
      file.name().c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, kImageDrivers, nullptr, nullptr));
  if (!dataset) return makeError(name + ": not an image GDAL reads (" + CPLGetLastErrorMsg() + ")");
  const int width = GDALGetRasterXSize(dataset.get()), height = GDALGetRasterYSize(dataset.get());
  const int bandCount = GDALGetRasterCount(dataset.get());
  if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide || bandCount < 1) {
    return makeError(name + ": a " + std::to_string(width) + "x" + std::to_string(height) +
                     " image of " + std::to_string(bandCount) + " bands (1 to 32768 a side)");
  }
  const uint64_t decodedBytes = uint64_t{4} * static_cast<uint64_t>(width) * height;
  if (decodedBytes > maxDecodedBytes) {
    return makeError(name + ": a " + std::to_string(width) + "x" + std::to_string(height) +
                     " image takes " + std::to_string(decodedBytes >> 20) +
                     " MiB decoded, beyond the " + std::to_string(maxDecodedBytes >> 20) +
                     " MiB left for this overlay's images");
  }
  std::vector<std::vector<uint8_t>> bands(static_cast<size_t>(std::min(bandCount, 4)));
  for (size_t b = 0; b < bands.size(); ++b) {
    bands[b].resize(static_cast<size_t>(width) * static_cast<size_t>(height));
    GDALRasterBandH band = GDALGetRasterBand(dataset.get(), static_cast<int>(b) + 1);
    if (GDALRasterIO(band, GF_Read, 0, 0, width, height, bands[b].data(), width, height, GDT_Byte,
                     0, 0) != CE_None) {
      return makeError(name + ": band " + std::to_string(b + 1) + " unreadable (" +
                       CPLGetLastErrorMsg() + ")");
    }
  }
  formats::ImageRgba image{width, height, std::vector<uint8_t>(decodedBytes)};
  toRgba(bands, GDALGetRasterColorTable(GDALGetRasterBand(dataset.get(), 1)), image.pixels);
  return image;
}

}  // namespace globe::overlays
