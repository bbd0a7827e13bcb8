#include "mask_tiling/water_mask_tiler.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <thread>

#include "formats/image_pack.hpp"
#include "formats/layer_manifest.hpp"
#include "formats/pyramid_manifest.hpp"
#include "geo/tile_id.hpp"
#include "geo/tiling_scheme.hpp"
#include "imagery_tiling/imagery_encoding.hpp"
#include "imagery_tiling/imagery_reader.hpp"
#include "mask_tiling/land_coverage.hpp"
#include "mask_tiling/land_polygons.hpp"
#include "tiling/write_failed.hpp"
#include "transport/atomic_file.hpp"

namespace globe::mask_tiling {
namespace {

namespace fs = std::filesystem;
constexpr int kTileSize = 256;

double texelDegrees(uint32_t level) {
  return 180.0 / std::ldexp(1.0, static_cast<int>(level)) / (kTileSize - 1);
}

struct Layer {
  LandPolygonLayer polygons;
  uint32_t finestLevel = 0;
};

// A tile to make: its rings per layer, clipped to its rectangle grown by one sample step (the
// boxes of its edge samples reach half a step outside).
struct Node {
  geo::TileId tile;
  std::vector<std::vector<Ring>> rings;  // per layer
};

struct Made {
  std::vector<std::byte> payload;  // empty: no layer covers the tile
  bool coast = false;              // a shoreline (or a change of layer) runs through it
  std::vector<Node> children;
};

RectangleDegrees tileRectangle(const geo::TileId& tile) {
  const imagery_tiling::TileFrameDegrees f = imagery_tiling::tileFrameDegrees(tile);
  return {f.west, f.north - f.size, f.west + f.size, f.north};
}

// Shoelace, degrees².
double ringArea(const Ring& ring) {
  double twice = 0;
  for (size_t i = 0; i < ring.size(); ++i) {
    const glm::dvec2& a = ring[i];
    const glm::dvec2& b = ring[(i + 1) % ring.size()];
    twice += (a.x - ring[0].x) * (b.y - ring[0].y) - (b.x - ring[0].x) * (a.y - ring[0].y);
  }
  return twice / 2;
}

RectangleDegrees grown(const RectangleDegrees& r, double by) {
  return {r.west - by, r.south - by, r.east + by, r.north + by};
}

std::vector<Ring> clipAll(const std::vector<Ring>& rings, const RectangleDegrees& rectangle) {
  std::vector<Ring> out;
  for (const Ring& ring : rings) {
    Ring clipped = clipRing(ring, rectangle);
    if (!clipped.empty()) out.push_back(std::move(clipped));
  }
  return out;
}

class Maker {
 public:
  explicit Maker(const std::vector<Layer>& layers) : layers_(layers) {}

  Result<Made> make(const Node& node) const {
    Made made;
    const imagery_tiling::TileFrameDegrees f = imagery_tiling::tileFrameDegrees(node.tile);
    const double step = f.size / (kTileSize - 1);
    const RectangleDegrees tile = tileRectangle(node.tile);
    const RectangleDegrees ringBox = grown(tile, step);
    const TexelGrid grid{f.west, f.north, step, kTileSize};
    constexpr int kPoints = kWaterMaskSupersample * kWaterMaskSupersample;

    // Per layer over the tile: its land counts, or one count for the whole tile when its rings
    // only run along the sides (no shoreline here).
    std::vector<size_t> active;
    std::vector<std::vector<uint16_t>> counts(layers_.size());
    std::vector<int> uniformCount(layers_.size(), -1);
    uint32_t deepestCoast = 0, deepestActive = 0;
    bool anyShoreline = false;
    for (size_t l = 0; l < layers_.size(); ++l) {
      if (!layers_[l].polygons.extent.intersects(tile)) continue;
      active.push_back(l);
      deepestActive = std::max(deepestActive, layers_[l].finestLevel);
      const std::vector<Ring>& rings = node.rings[l];
      const bool shoreline = std::any_of(rings.begin(), rings.end(), [&](const Ring& ring) {
        return !runsAlongSides(ring, ringBox);
      });
      if (!shoreline) {
        // Each ring along the sides encloses the whole box or nothing (a trace that goes and
        // comes back): its area tells which.
        const double boxArea = (ringBox.east - ringBox.west) * (ringBox.north - ringBox.south);
        size_t enclosing = 0;
        for (const Ring& ring : rings) enclosing += std::abs(ringArea(ring)) > boxArea / 2 ? 1 : 0;
        uniformCount[l] = enclosing % 2 == 1 ? kPoints : 0;
        continue;
      }
      anyShoreline = true;
      deepestCoast = std::max(deepestCoast, layers_[l].finestLevel);
      countLandPoints(rings, grid, kWaterMaskSupersample, counts[l]);
    }
    if (active.empty()) return made;

    // Grey (water fraction) and alpha (a layer decides) per sample, the finest layer whose
    // extent holds the sample deciding; near a side of its extent where a coarser layer goes on,
    // blended into that one's (extentBlend), so the coast moves from one shoreline to the other
    // instead of jumping at a straight line.
    std::vector<uint8_t> pixels(size_t{kTileSize} * kTileSize * 2);
    for (int r = 0; r < kTileSize; ++r) {
      const double latitude = f.north - r * step;
      for (int c = 0; c < kTileSize; ++c) {
        const double longitude = f.west + c * step;
        const size_t sample = static_cast<size_t>(r) * kTileSize + static_cast<size_t>(c);
        auto water = [&](size_t l) {
          const int land = uniformCount[l] >= 0 ? uniformCount[l] : counts[l][sample];
          return static_cast<double>(kPoints - land) / kPoints;
        };
        std::optional<size_t> finest;
        for (size_t l : active) {
          if (!layers_[l].polygons.extent.contains(longitude, latitude)) continue;
          if (!finest) {
            finest = l;
            continue;
          }
          // The next layer under the finest: blend towards it near the finest one's side.
          const double t = extentBlend(*finest, l, longitude, latitude);
          if (t < 1.0) {
            const double w = t * water(*finest) + (1.0 - t) * water(l);
            pixels[2 * sample] = static_cast<uint8_t>(std::lround(w * 255));
            pixels[2 * sample + 1] = 255;
          }
          break;
        }
        if (finest && pixels[2 * sample + 1] == 0) {
          pixels[2 * sample] = static_cast<uint8_t>(std::lround(water(*finest) * 255));
          pixels[2 * sample + 1] = 255;
        }
      }
    }
    bool varies = false;
    for (size_t i = 2; i < pixels.size() && !varies; i += 2) {
      varies = pixels[i] != pixels[0] || pixels[i + 1] != pixels[1];
    }
    made.coast = anyShoreline || varies;
    auto encoded = imagery_tiling::encodePngGreyAlphaFast(pixels, kTileSize, kTileSize);
    if (!encoded) return Error{encoded.error()};
    made.payload = std::move(*encoded);

    const uint32_t deepest = anyShoreline ? deepestCoast : deepestActive;
    if (!made.coast || node.tile.level >= deepest) return made;
    for (const geo::TileId& child : node.tile.children()) {
      Node next{child, std::vector<std::vector<Ring>>(layers_.size())};
      const RectangleDegrees childTile = tileRectangle(child);
      const RectangleDegrees childBox = grown(childTile, step / 2);
      for (size_t l : active) {
        if (layers_[l].polygons.extent.intersects(childTile)) {
          next.rings[l] = clipAll(node.rings[l], childBox);
        }
      }
      made.children.push_back(std::move(next));
    }
    return made;
  }

 private:
  // How much layer `fine` decides at a point of its extent where layer `coarse` goes on too:
  // smoothstep from 0 at a side of its extent (not ±180° or a pole: nothing lies beyond those)
  // to 1 a blend width in: the coarse layer's own detail (its median edge), at least 16 of the
  // fine layer's finest texels, at most an eighth of the extent's size.
  double extentBlend(size_t fine, size_t coarse, double longitude, double latitude) const {
    const RectangleDegrees& e = layers_[fine].polygons.extent;
    double distance = std::numeric_limits<double>::max();
    if (e.west > -180.0 + kEdgeDegrees) distance = std::min(distance, longitude - e.west);
    if (e.east < 180.0 - kEdgeDegrees) distance = std::min(distance, e.east - longitude);
    if (e.south > -90.0 + kEdgeDegrees) distance = std::min(distance, latitude - e.south);
    if (e.north < 90.0 - kEdgeDegrees) distance = std::min(distance, e.north - latitude);
    const double width = std::min(std::max(16.0 * texelDegrees(layers_[fine].finestLevel),
                                           layers_[coarse].polygons.medianEdgeDegrees),
                                  0.125 * std::min(e.east - e.west, e.north - e.south));
    if (!(width > 0) || distance >= width) return 1.0;
    const double t = std::clamp(distance / width, 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
  }

  static constexpr double kEdgeDegrees = 1e-9;
  const std::vector<Layer>& layers_;
};

Result<void> prepareOutput(const fs::path& dir) {
  std::error_code error;
  fs::create_directories(dir, error);
  if (error) return makeError(dir.string() + ": cannot create: " + error.message());
  if (fs::exists(dir / formats::kManifestFileName, error)) {
    return makeError(dir.string() + ": holds a terrain pyramid; choose another output directory");
  }
  if (fs::exists(dir / formats::kLayerManifestFileName, error)) {
    auto existing = formats::readLayerManifest(dir);
    if (!existing || existing->kind != formats::LayerKind::WaterMask) {
      return makeError(dir.string() +
                       ": holds an imagery layer (or a damaged layer.json); choose another "
                       "output directory");
    }
  }
  transport::removeAtomicTemporaries(dir);  // a killed run's half-written files
  return {};
}

void include(formats::BoundsDegrees& bounds, const RectangleDegrees& more) {
  bounds = {std::min(bounds.west, more.west), std::min(bounds.south, more.south),
            std::max(bounds.east, more.east), std::max(bounds.north, more.north)};
}

}  // namespace

uint32_t waterMaskLevelFor(double medianEdgeDegrees) {
  uint32_t level = 0;
  while (level < kWaterMaskMaxAutoLevel && texelDegrees(level) > medianEdgeDegrees / 2) ++level;
  return level;
}

Result<WaterMaskTilerReport> runWaterMaskTiler(const WaterMaskTilerOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (options.inputs.empty()) return makeError("no input given");
  if (options.packTilesPerSide == 0 ||
      options.packTilesPerSide > formats::kImagePackMaxTilesPerSide) {
    return makeError("--pack-tiles must be between 1 and " +
                     std::to_string(formats::kImagePackMaxTilesPerSide));
  }
  if (options.maxLevel && *options.maxLevel > geo::kMaxLevel) {
    return makeError("--max-level must be at most " + std::to_string(geo::kMaxLevel));
  }
  WaterMaskTilerReport report;
  std::vector<Layer> layers;
  for (const std::string& input : options.inputs) {
    auto read = readLandPolygons(input);
    if (!read) return Error{read.error()};
    for (LandPolygonLayer& polygons : *read) {
      Layer layer;
      layer.finestLevel = options.maxLevel.value_or(waterMaskLevelFor(polygons.medianEdgeDegrees));
      report.rings += polygons.rings.size();
      report.vertices += polygons.vertices;
      layer.polygons = std::move(polygons);
      layers.push_back(std::move(layer));
    }
  }
  report.layers = layers.size();
  // The finest shoreline first: it decides where layers overlap.
  std::stable_sort(layers.begin(), layers.end(), [](const Layer& a, const Layer& b) {
    return a.polygons.medianEdgeDegrees < b.polygons.medianEdgeDegrees;
  });
  if (auto prepared = prepareOutput(options.outputDir); !prepared) return Error{prepared.error()};

  formats::LayerManifest manifest;
  manifest.kind = formats::LayerKind::WaterMask;
  manifest.pixelGrid = formats::ImageryPixelGrid::Edges;
  manifest.packTilesPerSide = options.packTilesPerSide;
  manifest.bounds = {180, 90, -180, -90};
  for (const Layer& layer : layers) {
    formats::ImagerySourceInfo source;
    source.path = layer.polygons.path;
    source.driver = layer.polygons.driver;
    source.crs = layer.polygons.crs;
    source.finestLevel = layer.finestLevel;
    // Its resolution: the shoreline's own detail (the median edge), or the deepest texel if
    // coarser. The viewer weighs the mask against the terrain's step by it: GSHHG's full
    // resolution is not 40 m because its tiles are, and SRTM's coast beside it is as good.
    source.pixelDegrees =
        std::max(texelDegrees(layer.finestLevel), layer.polygons.medianEdgeDegrees);
    const RectangleDegrees& e = layer.polygons.extent;
    source.bounds = {e.west, e.south, e.east, e.north};
    source.bands = "land polygons: layer " + layer.polygons.name + ", " +
                   std::to_string(layer.polygons.rings.size()) + " rings";
    manifest.sources.push_back(source);
  }

  const Maker maker(layers);
  std::vector<Node> nodes;
  for (uint32_t x = 0; x < geo::GeographicTilingScheme::tilesX(0); ++x) {
    Node root{geo::TileId{0, x, 0}, {}};
    const RectangleDegrees box = grown(tileRectangle(root.tile), 180.0 / (kTileSize - 1));
    for (const Layer& layer : layers) root.rings.push_back(clipAll(layer.polygons.rings, box));
    nodes.push_back(std::move(root));
  }
  const unsigned threads =
      options.threads != 0 ? options.threads : std::max(1U, std::thread::hardware_concurrency());
  uint64_t tilesDone = 0;
  for (uint32_t level = 0; !nodes.empty(); ++level) {
    std::vector<Result<Made>> results(nodes.size(), Result<Made>(Made{}));
    std::atomic<size_t> next{0};
    std::vector<std::thread> workers;
    for (unsigned w = 0; w < std::min<size_t>(threads, nodes.size()); ++w) {
      workers.emplace_back([&] {
        for (size_t i; (i = next++) < nodes.size();) {
          results[i] = maker.make(nodes[i]);
          nodes[i].rings = {};  // the children hold what they need
        }
      });
    }
    for (std::thread& worker : workers) worker.join();

    std::map<formats::PackId, std::vector<std::vector<std::byte>>> packs;
    formats::ImageryLevelInfo info;
    info.level = level;
    info.bounds = {180, 90, -180, -90};
    std::vector<Node> children;
    for (size_t i = 0; i < nodes.size(); ++i) {
      if (!results[i]) return Error{results[i].error()};
      Made& made = *results[i];
      if (made.payload.empty()) continue;
      const geo::TileId& tile = nodes[i].tile;
      auto& payloads = packs[formats::packOf(tile, options.packTilesPerSide)];
      payloads.resize(size_t{options.packTilesPerSide} * options.packTilesPerSide);
      payloads[formats::slotOf(tile, options.packTilesPerSide)] = std::move(made.payload);
      ++info.tileCount;
      report.coastTiles += made.coast ? 1 : 0;
      include(info.bounds, tileRectangle(tile));
      for (Node& child : made.children) children.push_back(std::move(child));
    }
    for (auto& [id, payloads] : packs) {
      const fs::path path = formats::packPath(options.outputDir, id);
      std::error_code error;
      fs::create_directories(path.parent_path(), error);
      if (error) {
        return makeError(path.parent_path().string() + ": cannot create: " + error.message());
      }
      const auto bytes = formats::encodeImagePack(id, options.packTilesPerSide, payloads);
      if (auto written = transport::writeFileAtomically(path, bytes); !written) {
        return tiling::writeFailed(written.error());
      }
      info.packs.push_back(id);
    }
    if (info.tileCount == 0) break;
    const formats::BoundsDegrees& b = info.bounds;
    include(manifest.bounds, {b.west, b.south, b.east, b.north});
    report.tiles += info.tileCount;
    tilesDone += info.tileCount;
    manifest.levels.push_back(std::move(info));
    if (options.progress) {
      options.progress(
          {tilesDone, tilesDone + children.size(), "level " + std::to_string(level), false});
    }
    nodes = std::move(children);
  }
  if (manifest.levels.empty())
    return makeError("no land polygon reaches any tile: nothing to tile");
  report.maxLevel = manifest.maxLevel();
  if (options.progress) options.progress({tilesDone, tilesDone, "done", true});
  if (auto written = formats::writeLayerManifest(options.outputDir, manifest); !written) {
    return tiling::writeFailed(written.error());
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace globe::mask_tiling
