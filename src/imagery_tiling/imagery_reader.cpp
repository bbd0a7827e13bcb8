#include "imagery_tiling/imagery_reader.hpp"

#include <gdal.h>
#include <gdal_alg.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "imagery_tiling/footprint_fade.hpp"
#include "imagery_tiling/gdal_dataset.hpp"
#include "imagery_tiling/imagery_pixels.hpp"
#include "transport/atomic_file.hpp"

namespace globe::imagery_tiling {
namespace {

namespace fs = std::filesystem;

constexpr int kSize = kImageryTileSizePixels;
constexpr int kGridStep = 16;  // pixels between exactly transformed points
constexpr int kGrid = kSize / kGridStep + 1;
constexpr double kMaxGridErrorPixels = 0.125;  // as gdalwarp's approximate transformer
// Source windows above this are read reduced (GDAL averages, using overviews where present).
constexpr int kMaxWindowPixels = 2048;
// How far outside a raster an edge sample may land through the transform's rounding.
constexpr double kEdgeTolerancePixels = 1e-6;

// An RGBA window of source pixels, row 0 at the top.
struct Window {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;
};

// Bilinear with premultiplied alpha at window coordinates (x, y), pixel centres at +0.5; neighbours
// beyond the window are clamped to its edge. Weights in 1/256 steps, integer sums: exact and the
// same on every machine. Writes nothing where the result is transparent.
inline void sampleInto(const Window& w, double x, double y, uint8_t* out) {
  const double fx = x - 0.5, fy = y - 0.5;
  const double floorX = std::floor(fx), floorY = std::floor(fy);
  const auto wx = static_cast<uint32_t>((fx - floorX) * 256 + 0.5);
  const auto wy = static_cast<uint32_t>((fy - floorY) * 256 + 0.5);
  const int ix = static_cast<int>(floorX), iy = static_cast<int>(floorY);
  const int x0 = std::clamp(ix, 0, w.width - 1), x1 = std::clamp(ix + 1, 0, w.width - 1);
  const int y0 = std::clamp(iy, 0, w.height - 1), y1 = std::clamp(iy + 1, 0, w.height - 1);
  const uint8_t* p[4] = {
      &w.rgba[(size_t(y0) * w.width + x0) * 4], &w.rgba[(size_t(y0) * w.width + x1) * 4],
      &w.rgba[(size_t(y1) * w.width + x0) * 4], &w.rgba[(size_t(y1) * w.width + x1) * 4]};
  const uint32_t weight[4] = {(256 - wx) * (256 - wy), wx * (256 - wy), (256 - wx) * wy, wx * wy};
  if ((p[0][3] & p[1][3] & p[2][3] & p[3][3]) == 255) {  // all opaque: the common case
    for (int c = 0; c < 3; ++c) {
      const uint32_t sum =
          weight[0] * p[0][c] + weight[1] * p[1][c] + weight[2] * p[2][c] + weight[3] * p[3][c];
      out[c] = static_cast<uint8_t>((sum + 32768) >> 16);
    }
    out[3] = 255;
    return;
  }
  uint32_t alpha = 0;
  uint64_t colour[3] = {0, 0, 0};
  for (int k = 0; k < 4; ++k) {
    const uint32_t a = weight[k] * p[k][3];
    alpha += a;
    for (int c = 0; c < 3; ++c) colour[c] += uint64_t{a} * p[k][c];
  }
  if (alpha < 32768) return;  // rounds to alpha 0
  for (int c = 0; c < 3; ++c) out[c] = static_cast<uint8_t>((colour[c] + alpha / 2) / alpha);
  out[3] = static_cast<uint8_t>((alpha + 32768) >> 16);
}

std::string gdalError() {
  const char* message = CPLGetLastErrorMsg();
  return message != nullptr && *message != '\0' ? message : "unknown GDAL error";
}

class RasterReader final : public ImageryReader {
 public:
  RasterReader(const ImageryInput& input, GDALDatasetH dataset)
      : input_(input), dataset_(dataset) {}
  ~RasterReader() override {
    if (transformer_ != nullptr) GDALDestroyGenImgProjTransformer(transformer_);
  }

  Result<void> init() {
    GDALDatasetH ds = dataset_.get();
    columns_ = GDALGetRasterXSize(ds);
    rows_ = GDALGetRasterYSize(ds);
    if (input_.assignedGeoTransform) {
      const auto& g = *input_.assignedGeoTransform;
      inverse_ = {-g[0] / g[1], 1 / g[1], 0, -g[3] / g[5], 0, 1 / g[5]};
    } else {
      static const std::string dst = [] {
        // EPSG:4326 in longitude, latitude order (GDAL's transformer uses GIS axis order).
        return std::string("DST_SRS=EPSG:4326");
      }();
      const std::string src = "SRC_SRS=" + input_.assumedSrsWkt;
      const char* options[] = {dst.c_str(), input_.assumedSrsWkt.empty() ? nullptr : src.c_str(),
                               nullptr};
      transformer_ = GDALCreateGenImgProjTransformer2(ds, nullptr, const_cast<char**>(options));
      if (transformer_ == nullptr) {
        return makeError(input_.argument +
                         ": cannot transform to longitude/latitude: " + gdalError());
      }
    }
    // A collar can only come from an alpha band, a mask or nodata (or a palette's alpha).
    fadesCollars_ =
        input_.fadeCollars && (input_.alphaBand != 0 || input_.palette ||
                               (GDALGetMaskFlags(GDALGetRasterBand(
                                    ds, input_.colourBands.empty() ? 1 : input_.colourBands[0])) &
                                GMF_ALL_VALID) == 0);
    if (input_.palette) {
      GDALColorTableH table = GDALGetRasterColorTable(GDALGetRasterBand(ds, 1));
      const int count = GDALGetColorEntryCount(table);
      palette_.assign(std::max(count, 1), {0, 0, 0, 0});
      for (int i = 0; i < count; ++i) {
        GDALColorEntry entry;
        GDALGetColorEntryAsRGB(table, i, &entry);
        palette_[size_t(i)] = {static_cast<uint8_t>(entry.c1), static_cast<uint8_t>(entry.c2),
                               static_cast<uint8_t>(entry.c3), static_cast<uint8_t>(entry.c4)};
      }
    }
    return {};
  }

  Result<bool> render(const geo::TileId& tile, formats::ImageRgba& out) override {
    const TileFrameDegrees frame = tileFrameDegrees(tile);
    auto covered = renderPart(frame, input_.extent, 0, out);
    if (!covered || !input_.wrappedExtent) return covered;
    auto wrapped = renderPart(frame, *input_.wrappedExtent, input_.wrapShiftDegrees, out);
    if (!wrapped) return wrapped;
    return *covered || *wrapped;
  }

 private:
  // Draws the part of the footprint in `part`, reading the source at longitude + shiftDegrees,
  // into the pixels still transparent.
  Result<bool> renderPart(const TileFrameDegrees& frame, const formats::BoundsDegrees& e,
                          double shiftDegrees, formats::ImageRgba& out) {
    if (frame.west >= e.east || frame.west + frame.size <= e.west || frame.north <= e.south ||
        frame.north - frame.size >= e.north) {
      return false;
    }
    sourceCoordinates({frame.west + shiftDegrees, frame.north, frame.size});
    // The source window every pixel centre falls in, plus one pixel for the bilinear neighbours.
    double minX = std::numeric_limits<double>::max(), minY = minX;
    double maxX = std::numeric_limits<double>::lowest(), maxY = maxX;
    // Pixel-is-area: a tile pixel whose sample falls inside the raster's area is drawn; edge
    // samples on the area's far edges too (they are its neighbours' samples as well).
    const bool edges = input_.pixelGrid == formats::ImageryPixelGrid::Edges;
    // (within kEdgeTolerancePixels: the transform's rounding must not drop an edge sample)
    const auto inside = [&](double x, double y) {
      return edges ? x >= -kEdgeTolerancePixels && x <= columns_ + kEdgeTolerancePixels &&
                         y >= -kEdgeTolerancePixels && y <= rows_ + kEdgeTolerancePixels
                   : x >= 0 && x < columns_ && y >= 0 && y < rows_;
    };
    for (size_t i = 0; i < sourceX_.size(); ++i) {
      const double x = sourceX_[i], y = sourceY_[i];
      if (!inside(x, y)) continue;
      minX = std::min(minX, x), maxX = std::max(maxX, x);
      minY = std::min(minY, y), maxY = std::max(maxY, y);
    }
    if (minX > maxX) return false;
    // One pixel for the bilinear neighbours; with a collar fade, also the pixels within its reach.
    const int pad = 1 + (fadesCollars_ ? static_cast<int>(std::ceil(kFootprintFadePixels)) : 0);
    const int x0 = std::max(0, static_cast<int>(std::floor(minX)) - pad);
    const int y0 = std::max(0, static_cast<int>(std::floor(minY)) - pad);
    const int x1 = std::min(columns_, static_cast<int>(std::floor(maxX)) + 1 + pad);
    const int y1 = std::min(rows_, static_cast<int>(std::floor(maxY)) + 1 + pad);
    const int windowWidth = x1 - x0, windowHeight = y1 - y0;
    const int reduce =
        (std::max(windowWidth, windowHeight) + kMaxWindowPixels - 1) / kMaxWindowPixels;
    window_.width = (windowWidth + reduce - 1) / reduce;
    window_.height = (windowHeight + reduce - 1) / reduce;
    if (auto read = readWindow(x0, y0, windowWidth, windowHeight); !read) {
      return Error{read.error()};
    }
    const double scaleX = double(window_.width) / windowWidth;
    const double scaleY = double(window_.height) / windowHeight;
    bool covered = false;
    const bool fades = std::any_of(input_.fadeEdges.begin(), input_.fadeEdges.end(),
                                   [](bool edge) { return edge; });
    // The no-data collar's fade: each window pixel's distance to the nearest transparent one, in
    // source pixels (a reduced window's pixels span `reduce`).
    bool collar = false;
    if (fadesCollars_) {
      for (size_t i = 3; i < window_.rgba.size() && !collar; i += 4) collar = window_.rgba[i] == 0;
      if (collar)
        distanceToTransparent(window_.rgba, window_.width, window_.height, collarDistance_);
    }
    const bool wrapSeam = edges && wrapsAround();
    std::vector<size_t> seam;  // samples on a whole-globe raster's first or last column edge
    for (size_t i = 0; i < sourceX_.size(); ++i) {
      const double x = sourceX_[i], y = sourceY_[i];
      if (!inside(x, y)) continue;
      uint8_t* pixel = &out.pixels[i * 4];
      if (pixel[3] != 0) continue;  // drawn from the other part of the footprint
      if (wrapSeam && (x <= kEdgeTolerancePixels || x >= columns_ - kEdgeTolerancePixels)) {
        seam.push_back(i);
        continue;
      }
      sampleInto(window_, (x - x0) * scaleX, (y - y0) * scaleY, pixel);
      if ((fades || collar) && pixel[3] != 0) {
        double fade = fades ? footprintFade(input_, x, y, columns_, rows_) : 1.0;
        if (collar) {
          fade *= smoothFade(sampleDistance((x - x0) * scaleX, (y - y0) * scaleY) * reduce);
        }
        if (fade < 1.0) {
          pixel[3] = static_cast<uint8_t>(std::lround(pixel[3] * fade));
          if (pixel[3] == 0) std::fill_n(pixel, 4, uint8_t{0});
        }
      }
      covered = covered || pixel[3] != 0;
    }
    if (seam.empty()) return covered;
    // There the raster's last column meets its first: the sample is the mean of the two, as a
    // filter across the seam gives, in the tiles on both sides alike (no line along it).
    std::array<Window, 2> ends;
    for (int side = 0; side < 2; ++side) {
      window_.width = 1;
      window_.height = (windowHeight + reduce - 1) / reduce;
      if (auto read = readWindow(side == 0 ? 0 : columns_ - 1, y0, 1, windowHeight); !read) {
        return Error{read.error()};
      }
      ends[size_t(side)] = window_;
    }
    for (size_t i : seam) {
      std::array<uint8_t, 4> first{}, last{};
      sampleInto(ends[0], 0.5, (sourceY_[i] - y0) * scaleY, first.data());
      sampleInto(ends[1], 0.5, (sourceY_[i] - y0) * scaleY, last.data());
      uint8_t* pixel = &out.pixels[i * 4];
      const uint32_t alpha = uint32_t{first[3]} + last[3];
      if (alpha == 0) continue;
      for (int c = 0; c < 3; ++c) {
        pixel[c] =
            static_cast<uint8_t>((first[c] * first[3] + last[c] * last[3] + alpha / 2) / alpha);
      }
      pixel[3] = static_cast<uint8_t>((alpha + 1) / 2);
      covered = true;
    }
    return covered;
  }

  // collarDistance_ bilinear at window coordinates (x, y), pixel centres at +0.5 as sampleInto.
  double sampleDistance(double x, double y) const {
    const double fx = x - 0.5, fy = y - 0.5;
    const double floorX = std::floor(fx), floorY = std::floor(fy);
    const double tx = fx - floorX, ty = fy - floorY;
    const int w = window_.width, h = window_.height;
    const int ix = static_cast<int>(floorX), iy = static_cast<int>(floorY);
    const int xa = std::clamp(ix, 0, w - 1), xb = std::clamp(ix + 1, 0, w - 1);
    const int ya = std::clamp(iy, 0, h - 1), yb = std::clamp(iy + 1, 0, h - 1);
    auto d = [&](int cx, int cy) { return double(collarDistance_[size_t(cy) * w + cx]); };
    return (1 - ty) * ((1 - tx) * d(xa, ya) + tx * d(xb, ya)) +
           ty * ((1 - tx) * d(xa, yb) + tx * d(xb, yb));
  }

  // A raster in longitude/latitude 360° wide: its first and last columns are neighbours.
  bool wrapsAround() const {
    return !transformer_ && std::abs(columns_ / inverse_[1] - 360.0) < 1e-6;
  }

  // Source pixel coordinates of every tile pixel's sample (NaN where the transform fails): pixel
  // k samples at (k + offset)·texel from the west (north) edge: the centre of its area, or with
  // edge samples k/(S−1) of the tile.
  void sourceCoordinates(const TileFrameDegrees& frame) {
    const bool edges = input_.pixelGrid == formats::ImageryPixelGrid::Edges;
    const double texel = frame.size / (edges ? kSize - 1 : kSize);
    const double offset = edges ? 0.0 : 0.5;
    sourceX_.resize(size_t{kSize} * kSize);
    sourceY_.resize(size_t{kSize} * kSize);
    if (!transformer_) {
      for (int r = 0; r < kSize; ++r) {
        const double lat = frame.north - (r + offset) * texel;
        for (int c = 0; c < kSize; ++c) {
          const double lon = frame.west + (c + offset) * texel;
          const size_t i = size_t(r) * kSize + c;
          sourceX_[i] = inverse_[0] + inverse_[1] * lon;
          sourceY_[i] = inverse_[3] + inverse_[5] * lat;
        }
      }
      return;
    }
    // The grid's corners, then the centre of each of its cells: a cell whose centre the
    // interpolation misses by more than kMaxGridErrorPixels (a wrap at ±180°, a pole) or whose
    // points fail is transformed pixel by pixel.
    constexpr int kCells = kGrid - 1;
    constexpr size_t kCorners = size_t{kGrid} * kGrid;
    std::array<double, kCorners + kCells * kCells> gx, gy, gz{};
    std::array<int, kCorners + kCells * kCells> ok{};
    for (int j = 0; j < kGrid; ++j) {
      for (int i = 0; i < kGrid; ++i) {
        gx[size_t(j * kGrid + i)] = frame.west + i * kGridStep * texel;
        gy[size_t(j * kGrid + i)] = frame.north - j * kGridStep * texel;
      }
    }
    for (int j = 0; j < kCells; ++j) {
      for (int i = 0; i < kCells; ++i) {
        gx[kCorners + size_t(j * kCells + i)] = frame.west + (i + 0.5) * kGridStep * texel;
        gy[kCorners + size_t(j * kCells + i)] = frame.north - (j + 0.5) * kGridStep * texel;
      }
    }
    GDALGenImgProjTransform(transformer_, TRUE, static_cast<int>(gx.size()), gx.data(), gy.data(),
                            gz.data(), ok.data());
    exactPixels_.clear();
    for (int j = 0; j < kCells; ++j) {
      for (int i = 0; i < kCells; ++i) {
        const size_t a = size_t(j * kGrid + i), b = a + 1, d = a + kGrid, e = d + 1;
        const size_t centre = kCorners + size_t(j * kCells + i);
        const bool good =
            ok[a] != 0 && ok[b] != 0 && ok[d] != 0 && ok[e] != 0 && ok[centre] != 0 &&
            std::abs((gx[a] + gx[b] + gx[d] + gx[e]) / 4 - gx[centre]) <= kMaxGridErrorPixels &&
            std::abs((gy[a] + gy[b] + gy[d] + gy[e]) / 4 - gy[centre]) <= kMaxGridErrorPixels;
        for (int r = j * kGridStep; r < (j + 1) * kGridStep; ++r) {
          const double ty = (r + offset) / kGridStep - j;
          for (int c = i * kGridStep; c < (i + 1) * kGridStep; ++c) {
            const size_t k = size_t(r) * kSize + c;
            if (!good) {
              exactPixels_.push_back(k);
              continue;
            }
            const double tx = (c + offset) / kGridStep - i;
            sourceX_[k] =
                (1 - ty) * ((1 - tx) * gx[a] + tx * gx[b]) + ty * ((1 - tx) * gx[d] + tx * gx[e]);
            sourceY_[k] =
                (1 - ty) * ((1 - tx) * gy[a] + tx * gy[b]) + ty * ((1 - tx) * gy[d] + tx * gy[e]);
          }
        }
      }
    }
    if (exactPixels_.empty()) return;
    std::vector<double> x(exactPixels_.size()), y(x.size()), z(x.size(), 0);
    std::vector<int> pixelOk(x.size(), 0);
    for (size_t n = 0; n < exactPixels_.size(); ++n) {
      const size_t k = exactPixels_[n];
      x[n] = frame.west + (double(k % kSize) + offset) * texel;
      y[n] = frame.north - (double(k / kSize) + offset) * texel;
    }
    GDALGenImgProjTransform(transformer_, TRUE, static_cast<int>(x.size()), x.data(), y.data(),
                            z.data(), pixelOk.data());
    for (size_t n = 0; n < exactPixels_.size(); ++n) {
      const size_t k = exactPixels_[n];
      const bool good = pixelOk[n] != 0;
      sourceX_[k] = good ? x[n] : std::numeric_limits<double>::quiet_NaN();
      sourceY_[k] = good ? y[n] : std::numeric_limits<double>::quiet_NaN();
    }
  }

  // Reduced windows are averaged, except palette indices.
  Result<void> readBand(GDALRasterBandH band, int x0, int y0, int width, int height,
                        GDALDataType type, void* buffer) {
    GDALRasterIOExtraArg extra;
    INIT_RASTERIO_EXTRA_ARG(extra);
    extra.eResampleAlg =
        input_.palette && type == GDT_Int32 ? GRIORA_NearestNeighbour : GRIORA_Average;
    if (GDALRasterIOEx(band, GF_Read, x0, y0, width, height, buffer, window_.width, window_.height,
                       type, 0, 0, &extra) != CE_None) {
      return makeError(input_.argument + ": read failed: " + gdalError());
    }
    return {};
  }

  Result<void> readWindow(int x0, int y0, int width, int height) {
    GDALDatasetH ds = dataset_.get();
    const size_t count = size_t(window_.width) * window_.height;
    window_.rgba.assign(count * 4, 255);
    const size_t bands = input_.colourBands.size();
    if (input_.palette) {
      indices_.resize(count);
      if (auto read =
              readBand(GDALGetRasterBand(ds, 1), x0, y0, width, height, GDT_Int32, indices_.data());
          !read) {
        return read;
      }
      for (size_t i = 0; i < count; ++i) {
        const auto index = static_cast<size_t>(
            std::clamp<int32_t>(indices_[i], 0, static_cast<int32_t>(palette_.size()) - 1));
        std::copy_n(palette_[index].data(), 4, &window_.rgba[i * 4]);
      }
    } else {
      plane_.resize(count);
      values_.resize(count);
      for (size_t b = 0; b < bands; ++b) {
        GDALRasterBandH band = GDALGetRasterBand(ds, input_.colourBands[b]);
        if (input_.stretches.empty()) {
          if (auto read = readBand(band, x0, y0, width, height, GDT_Byte, plane_.data()); !read) {
            return read;
          }
        } else {
          if (auto read = readBand(band, x0, y0, width, height, GDT_Float64, values_.data());
              !read) {
            return read;
          }
          const ImageryStretch& s = input_.stretches[b];
          const double gain = 255.0 / (s.maximum - s.minimum);
          for (size_t i = 0; i < count; ++i) {
            const double v = std::clamp((values_[i] - s.minimum) * gain, 0.0, 255.0);
            plane_[i] = static_cast<uint8_t>(std::lround(v));
          }
        }
        for (size_t i = 0; i < count; ++i) {
          for (size_t c = bands == 1 ? 0 : b; c < (bands == 1 ? 3 : b + 1); ++c) {
            window_.rgba[i * 4 + c] = plane_[i];
          }
        }
      }
    }
    // Alpha: an alpha band, else GDAL's mask (nodata, internal masks): valid where any colour
    // band is valid, as gdalwarp reads per-band nodata.
    std::vector<GDALRasterBandH> masks;
    if (input_.alphaBand != 0) {
      masks.push_back(GDALGetRasterBand(ds, input_.alphaBand));
    } else {
      GDALRasterBandH first = GDALGetRasterBand(ds, input_.colourBands[0]);
      const int flags = GDALGetMaskFlags(first);
      if ((flags & GMF_ALL_VALID) != 0) return {};
      if ((flags & GMF_PER_DATASET) != 0) {
        masks.push_back(GDALGetMaskBand(first));
      } else {
        for (int b : input_.colourBands) masks.push_back(GDALGetMaskBand(GDALGetRasterBand(ds, b)));
      }
    }
    alpha_.assign(count, 0);
    for (GDALRasterBandH mask : masks) {
      if (auto read = readBand(mask, x0, y0, width, height, GDT_Byte, plane_.data()); !read) {
        return read;
      }
      for (size_t i = 0; i < count; ++i) alpha_[i] = std::max(alpha_[i], plane_[i]);
    }
    for (size_t i = 0; i < count; ++i) {
      uint8_t& a = window_.rgba[i * 4 + 3];
      a = static_cast<uint8_t>((a * alpha_[i] + 127) / 255);
    }
    return {};
  }

  const ImageryInput& input_;
  GdalDataset dataset_;
  void* transformer_ = nullptr;
  std::array<double, 6> inverse_{};
  int columns_ = 0, rows_ = 0;
  std::vector<std::array<uint8_t, 4>> palette_;
  std::vector<double> sourceX_, sourceY_;
  std::vector<size_t> exactPixels_;
  Window window_;
  std::vector<uint8_t> plane_, alpha_;
  bool fadesCollars_ = false;
  std::vector<float> collarDistance_;
  std::vector<double> values_;
  std::vector<int32_t> indices_;
};

class TmsReader final : public ImageryReader {
 public:
  explicit TmsReader(const ImageryInput& input) : input_(input) {}

  Result<std::optional<std::vector<std::byte>>> ownTile(const geo::TileId& tile) override {
    if (tile.level > input_.tmsMaxLevel) return std::optional<std::vector<std::byte>>();
    const fs::path path = fileOf(tile);
    std::error_code error;
    if (!fs::exists(path, error)) return std::optional<std::vector<std::byte>>();
    auto bytes = transport::readWholeFile(path, formats::kImageTileMaximumBytes);
    if (!bytes) return Error{bytes.error()};
    const bool jpeg =
        bytes->size() > 3 && (*bytes)[0] == std::byte{0xFF} && (*bytes)[1] == std::byte{0xD8};
    const bool png =
        bytes->size() > 8 && (*bytes)[0] == std::byte{0x89} && (*bytes)[1] == std::byte{'P'};
    if (!jpeg && !png) return makeError(path.string() + ": not a JPEG or PNG tile");
    auto image = formats::decodeImageRgba(*bytes, path.string());
    if (!image) return Error{image.error()};
    if (image->widthPixels != kSize || image->heightPixels != kSize) {
      return makeError(path.string() + ": tile is " + std::to_string(image->widthPixels) + "x" +
                       std::to_string(image->heightPixels) + ", not 256x256");
    }
    if (!anyCovered(*image)) return std::optional<std::vector<std::byte>>();
    return std::optional<std::vector<std::byte>>(std::move(*bytes));
  }

  Result<bool> render(const geo::TileId& tile, formats::ImageRgba& out) override {
    const uint32_t shift = tile.level > input_.tmsMaxLevel ? tile.level - input_.tmsMaxLevel : 0;
    const geo::TileId ancestor{tile.level - shift, tile.x >> shift, tile.y >> shift};
    auto window = decoded(ancestor);
    if (!window) return Error{window.error()};
    if (!*window) return false;
    const Window& w = **window;
    const double cells = std::ldexp(1.0, static_cast<int>(shift));
    const double localX = tile.x - ancestor.x * cells, localY = tile.y - ancestor.y * cells;
    bool covered = false;
    for (int r = 0; r < kSize; ++r) {
      const double y = (localY * kSize + r + 0.5) / cells;
      for (int c = 0; c < kSize; ++c) {
        const double x = (localX * kSize + c + 0.5) / cells;
        uint8_t* pixel = &out.pixels[(size_t(r) * kSize + c) * 4];
        if (shift == 0) {
          std::copy_n(&w.rgba[(size_t(r) * kSize + c) * 4], 4, pixel);
        } else {
          sampleInto(w, x, y, pixel);
        }
        covered = covered || pixel[3] != 0;
      }
    }
    return covered;
  }

 private:
  fs::path fileOf(const geo::TileId& tile) const {
    const uint32_t rows = uint32_t{1} << tile.level;
    return fs::path(input_.argument) / std::to_string(tile.level) / std::to_string(tile.x) /
           (std::to_string(rows - 1 - tile.y) + "." + input_.tmsExtension);
  }

  // The tile decoded, the last few kept: neighbouring tiles share an ancestor.
  Result<const Window*> decoded(const geo::TileId& tile) {
    if (auto it = cache_.find(tile); it != cache_.end()) return &it->second;
    auto bytes = ownTile(tile);
    if (!bytes) return Error{bytes.error()};
    if (cache_.size() >= 16) cache_.clear();
    Window& w = cache_[tile];
    if (!*bytes) return static_cast<const Window*>(nullptr);
    auto image = formats::decodeImageRgba(**bytes, fileOf(tile).string());
    if (!image) return Error{image.error()};
    w = {image->widthPixels, image->heightPixels, std::move(image->pixels)};
    return &w;
  }

  const ImageryInput& input_;
  std::map<geo::TileId, Window> cache_;
};

}  // namespace

Result<std::optional<std::vector<std::byte>>> ImageryReader::ownTile(const geo::TileId&) {
  return std::optional<std::vector<std::byte>>();
}

TileFrameDegrees tileFrameDegrees(const geo::TileId& tile) {
  const double size = std::ldexp(180.0, -static_cast<int>(tile.level));
  return {-180.0 + tile.x * size, 90.0 - tile.y * size, size};
}

Result<std::unique_ptr<ImageryReader>> ImageryReader::open(const ImageryInput& input) {
  if (input.kind == ImageryInput::Kind::Tms)
    return std::unique_ptr<ImageryReader>(new TmsReader(input));
  GDALDatasetH dataset = GDALOpenEx(input.argument.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY,
                                    nullptr, nullptr, nullptr);
  if (dataset == nullptr) return makeError(input.argument + ": cannot open: " + gdalError());
  auto reader = std::make_unique<RasterReader>(input, dataset);
  if (auto ready = reader->init(); !ready) return Error{ready.error()};
  return std::unique_ptr<ImageryReader>(std::move(reader));
}

}  // namespace globe::imagery_tiling
