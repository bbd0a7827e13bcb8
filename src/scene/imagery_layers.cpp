#include "scene/imagery_layers.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <thread>
#include <tuple>

#include <glm/geometric.hpp>

#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "scene/native_resolution.hpp"
#include "services/imagery_services.hpp"
#include "streaming/background_pack_opens.hpp"
#include "terrain/imagery_exposure.hpp"
#include "terrain/imagery_level.hpp"
#include "terrain/water_mask_weight.hpp"

namespace globe::scene {

struct ImageryLayers::Layer {
  LayerOptions options;
  std::shared_ptr<streaming::ImageryTiles> store;
  std::unique_ptr<streaming::ImagerySource> source;
  streaming::ImageryCache cache;
  std::unique_ptr<streaming::ImageryLoader> loader;
  core::TaskRunner& runner;
  // A remote layer's pack indexes, read on the loader's threads; the tasks hold the store, so a
  // layer may go while one still runs.
  streaming::BackgroundPackOpens opening;
  std::unordered_map<geo::TileId, uint64_t> textureLastUsedFrame;  // textures on the GPU
  std::unordered_map<geo::TileId, bool> present;  // the layer's index, asked once per tile
  std::unordered_map<geo::TileId, double> nativeTexelDegrees;  // per terrain tile, found once
  // Both level-0 tiles opaque in every texel (known after the preload): the layer covers the
  // whole globe opaquely at every level (a footprint's edge would be transparent).
  bool opaqueEverywhere = false;
  float exposure = 1.0f;  // chosen at the preload (LayerOptions::exposure)
  bool isWaterMask() const { return store->manifest().kind == formats::LayerKind::WaterMask; }

  Layer(LayerOptions layerOptions, std::shared_ptr<streaming::ImageryTiles> layerStore,
        core::TaskRunner& taskRunner, size_t decodedBytes)
      : options(std::move(layerOptions)),
        store(std::move(layerStore)),
        source(std::make_unique<streaming::ImagerySource>(*store)),
        cache(decodedBytes),
        loader(std::make_unique<streaming::ImageryLoader>(*source, taskRunner, cache)),
        runner(taskRunner) {
    if (store->remote()) loader->setMaxInFlight(transport::kRemoteLoadsInFlight);
  }
  ~Layer() { loader.reset(); }  // waits for its running loads before the store goes

  // Whether the layer has the tile; an unreadable pack counts as "no" (reported once, by the
  // store) so the view draws a coarser tile instead. nullopt for a remote layer whose pack index
  // is not read yet: it is read in the background, never on the render thread.
  std::optional<bool> has(const geo::TileId& tile) {
    if (auto it = present.find(tile); it != present.end()) return it->second;
    bool has = false;
    if (store->remote()) {
      const streaming::ImageryTiles::Peek peek = store->peekTile(tile);
      if (peek == streaming::ImageryTiles::Peek::NotOpen) {
        openInBackground(tile);
        return std::nullopt;
      }
      has = peek == streaming::ImageryTiles::Peek::Present;
    } else {
      auto answer = store->hasTile(tile);
      has = answer && *answer;
    }
    // Bounded: a long flight asks about ever new tiles (the store answers from its index anyway).
    if (present.size() >= kPresentEntries) present.clear();
    present.emplace(tile, has);
    return has;
  }

  void openInBackground(const geo::TileId& tile) {
    opening.post(runner, store->tileGroupOf(tile), [store = store, tile] {
      (void)store->hasTile(tile);  // opens the pack: an error is the store's to report
    });
  }
  // The imagery level a terrain tile of this level takes (terrain/imagery_level.hpp).
  uint32_t imageryLevel(uint32_t terrainLevel, uint32_t verticesPerSide,
                        double maximumScreenSpaceErrorPixels) const {
    const formats::LayerManifest& manifest = store->manifest();
    return terrain::imageryLevelFor(terrainLevel, verticesPerSide, manifest.tileSizePixels,
                                    maximumScreenSpaceErrorPixels, manifest.maxLevel());
  }

  // The finest source texel at a terrain tile (native_resolution.hpp), found once per tile.
  double nativeTexelAt(const geo::TileId& tile) {
    if (auto it = nativeTexelDegrees.find(tile); it != nativeTexelDegrees.end()) return it->second;
    if (nativeTexelDegrees.size() >= kPresentEntries) nativeTexelDegrees.clear();
    const double degrees = finestTexelDegreesAt(store->manifest().sources, tile);
    nativeTexelDegrees.emplace(tile, degrees);
    return degrees;
  }
  static constexpr size_t kPresentEntries = 1u << 16;
};

ImageryLayers::ImageryLayers(std::vector<std::unique_ptr<Layer>> layers,
                             const ImageryBudget& budget, core::WarningSink warnings)
    : layers_(std::move(layers)), budget_(budget), warnings_(std::move(warnings)) {}

ImageryLayers::~ImageryLayers() = default;

Result<std::unique_ptr<ImageryLayers>> ImageryLayers::open(
    std::span<const LayerOptions> layers, core::TaskRunner& runner, const ImageryBudget& budget,
    std::shared_ptr<transport::Network> network, core::WarningSink warnings) {
  std::vector<std::unique_ptr<Layer>> opened;
  size_t colourLayers = 0, masks = 0;
  for (const LayerOptions& options : layers) {
    std::shared_ptr<streaming::ImageryTiles> store = options.tiles;
    if (!store) {
      auto tiles = services::openImageryTiles(options.directory.string(), network);
      if (!tiles) return Error{tiles.error()};
      store = std::move(*tiles);
    }
    const bool mask = store->manifest().kind == formats::LayerKind::WaterMask;
    (mask ? masks : colourLayers) += 1;
    if (colourLayers > terrain::kMaxDrapeLayers) {
      return makeError(
          "at most " + std::to_string(terrain::kMaxDrapeLayers) +
          " imagery layers (and one water mask); the overlays' draped lines and polygons "
          "take one");
    }
    if (masks > 1) {
      return makeError(options.directory.string() +
                       ": a second water mask (one is drawn: tile both sets of land polygons "
                       "into one with globe-tiler water-mask)");
    }
    opened.push_back(
        std::make_unique<Layer>(options, std::move(store), runner, budget.decodedBytes));
  }
  return std::unique_ptr<ImageryLayers>(
      new ImageryLayers(std::move(opened), budget, std::move(warnings)));
}

Result<void> ImageryLayers::setLayer(uint32_t index, const LayerOptions& options,
                                     core::TaskRunner& runner, TileGpu& gpu,
                                     std::shared_ptr<transport::Network> network) {
  if (index > layers_.size()) return makeError("no imagery layer " + std::to_string(index));
  if (index < layers_.size()) {
    for (const auto& [tile, frame] : layers_[index]->textureLastUsedFrame) {
      gpu.releaseImageryTile(index, tile);
    }
    layers_.erase(layers_.begin() + index);  // waits for its running loads
  } else if (layers_.size() >= terrain::kMaxDrapeLayers) {
    return makeError("at most " + std::to_string(terrain::kMaxDrapeLayers) + " imagery layers");
  }
  std::shared_ptr<streaming::ImageryTiles> store = options.tiles;
  if (!store) {
    auto opened = services::openImageryTiles(options.directory.string(), std::move(network));
    if (!opened) return Error{opened.error()};
    store = std::move(*opened);
  }
  layers_.insert(layers_.begin() + index,
                 std::make_unique<Layer>(options, std::move(store), runner, budget_.decodedBytes));
  if (preloaded_) return preload(*layers_[index], index, gpu);
  return {};
}

std::vector<std::string> ImageryLayers::attributions() const {
  std::vector<std::string> out;
  for (const auto& layer : layers_) out.push_back(layer->store->attribution());
  return out;
}

std::vector<float> ImageryLayers::exposures() const {
  std::vector<float> out;
  for (const auto& layer : layers_) out.push_back(layer->exposure);
  return out;
}

// The exposure a layer is drawn with: as given, or from its level-0 tiles' median luminance.
// Night lights, water masks and the program's own tiles (overlays) keep their colours.
static float chooseExposure(const LayerOptions& options, bool waterMask,
                            std::span<const uint8_t> levelZeroPixels) {
  if (options.night || waterMask || options.tiles) return 1.0f;
  if (std::isfinite(options.exposure)) return std::max(options.exposure, 1.0f);
  return static_cast<float>(
      terrain::exposureForMedianLuminance(terrain::medianOpaqueLuminance(levelZeroPixels)));
}

Result<void> ImageryLayers::preload(Layer& layer, uint32_t index, TileGpu& gpu) {
  layer.opaqueEverywhere = !layer.isWaterMask() && !layer.options.night;
  std::vector<uint8_t> levelZeroPixels;
  for (uint32_t x = 0; x < geo::GeographicTilingScheme::tilesX(0); ++x) {
    const geo::TileId root{0, x, 0};
    auto image = layer.source->load(root);
    if (!image) return Error{image.error()};
    if (!*image) {  // the layer covers nothing of this half
      layer.opaqueEverywhere = false;
      continue;
    }
    const std::vector<uint8_t>& pixels = (*image)->pixels;
    levelZeroPixels.insert(levelZeroPixels.end(), pixels.begin(), pixels.end());
    for (size_t k = 3; k < pixels.size() && layer.opaqueEverywhere; k += 4) {
      layer.opaqueEverywhere = pixels[k] == 255;
    }
    if (auto uploaded = gpu.prepareImageryTile(index, root, (*image)->pixels, (*image)->widthPixels,
                                               (*image)->heightPixels);
        !uploaded) {
      return uploaded;
    }
    layer.textureLastUsedFrame[root] = frame_;
  }
  layer.exposure = chooseExposure(layer.options, layer.isWaterMask(), levelZeroPixels);
  return {};
}

Result<ImageryFrame> ImageryLayers::update(std::span<const geo::TileId> tiles,
                                           uint32_t verticesPerSide,
                                           double maximumScreenSpaceErrorPixels,
                                           uint32_t maximumLoadLevel,
                                           const glm::dvec3& cameraEcefMeters,
                                           const geo::Ellipsoid& ellipsoid, TileGpu& gpu,
                                           std::vector<terrain::TileDrapes>& drapes) {
  ++frame_;
  ImageryFrame frame;
  drapes.assign(tiles.size(), terrain::TileDrapes{});
  if (!preloaded_) {
    for (uint32_t index = 0; index < layers_.size(); ++index) {
      if (auto done = preload(*layers_[index], index, gpu); !done) {
        return Error{done.error()};
      }
    }
    preloaded_ = true;
  }
  // Priority: nearer terrain tiles first (the distance to the rectangle's centre on the
  // ellipsoid is plenty to order loads); computed only for tiles that want a load.
  auto priority = [&](size_t i) {
    const auto rect = geo::GeographicTilingScheme::tileRectangle(tiles[i]);
    const glm::dvec3 center =
        geo::cartographicToEcef(ellipsoid, {rect.westRadians + rect.widthRadians() / 2,
                                            rect.southRadians + rect.heightRadians() / 2, 0.0});
    return -glm::length(center - cameraEcefMeters);
  };

  const bool maskHidden = waterMaskHidden();
  for (uint32_t index = 0; index < layers_.size(); ++index) {
    Layer& layer = *layers_[index];
    if (maskHidden && layer.isWaterMask()) continue;
    layer.cache.beginFrame();
    const streaming::PollResult polled = layer.loader->poll();
    frame.arrived += polled.arrived.size();
    for (const streaming::LoadError& error : polled.errors) {
      core::warn(warnings_, "imagery " + error.message + "; drawing a coarser tile there");
    }
    for (const std::string& error : layer.source->takeNewSourceErrors()) {
      core::warn(warnings_, "imagery " + error + "; drawing coarser tiles there");
    }
    const uint32_t tileSize = layer.store->manifest().tileSizePixels;
    std::vector<streaming::LoadRequest> wanted;
    std::vector<geo::TileId> wantedTiles;
    for (size_t i = 0; i < tiles.size(); ++i) {
      const geo::TileId& tile = tiles[i];
      const uint32_t level =
          layer.imageryLevel(tile.level, verticesPerSide, maximumScreenSpaceErrorPixels);
      // The tile this terrain tile wants: the deepest the layer has at or above that level.
      geo::TileId want = terrain::ancestorAt(tile, level);
      bool unknown = false;  // a pack index still on its way: a coarser tile for now
      auto has = [&](const geo::TileId& t) {
        const std::optional<bool> answer = layer.has(t);
        unknown = unknown || !answer;
        return answer.value_or(false);
      };
      // An overlay tile that is not there is clear: nothing to drape, not an ancestor's texels.
      if (!layer.store->emptyWhereAbsent()) {
        while (!has(want) && want.level > 0) want = want.parent();
      }
      if (unknown) frame.complete = false;
      if (!has(want)) continue;  // the layer does not cover this tile (or not known yet)
      const geo::TileId target = terrain::ancestorAt(want, std::min(want.level, maximumLoadLevel));
      wantedTiles.push_back(target);
      // Drawn with the nearest ancestor (or itself) that has a texture or a decoded image.
      geo::TileId drawn = want;
      bool found = false;
      for (;;) {
        if (gpu.hasImageryTile(index, drawn)) {
          found = true;
        } else if (auto image = layer.cache.get(drawn)) {
          if (auto uploaded = gpu.prepareImageryTile(index, drawn, image->pixels,
                                                     image->widthPixels, image->heightPixels);
              !uploaded) {
            return Error{uploaded.error()};
          }
          ++frame.uploaded;
          found = true;
        }
        if (found || drawn.level == 0) break;
        drawn = drawn.parent();
      }
      // A tile whose load failed (reported once) stays drawn through its ancestor.
      const streaming::TileState state = layer.loader->state(target);
      if (drawn.level < target.level && state == streaming::TileState::Failed) ++frame.missing;
      if (drawn.level < target.level && state != streaming::TileState::Failed &&
          state != streaming::TileState::Absent) {
        frame.complete = false;
        wanted.push_back({target, priority(i)});
      }
      if (!found) continue;
      // An overlay's own tile (lines and polygons the program rasterises) drawn from a coarser
      // one would show its lines 2^k times as wide, a line's colour flooding the ground until the
      // tile is made: nothing is draped there until then.
      if (drawn != want && layer.store->emptyWhereAbsent()) continue;
      if (drawn != want) ++frame.fallbacks;
      layer.textureLastUsedFrame[drawn] = frame_;
      terrain::TileDrapes& tileDrapes = drapes[i];
      const bool mask = layer.store->manifest().kind == formats::LayerKind::WaterMask;
      if (mask) tileDrapes.hasWaterMask = true;
      terrain::TileDrape& drape =
          mask ? tileDrapes.waterMask : tileDrapes.layers[tileDrapes.count++];
      glm::vec4 transform = terrain::uvTransformInAncestor(tile, drawn);
      if (layer.store->manifest().pixelGrid == formats::ImageryPixelGrid::Edges) {
        transform = terrain::edgeSampledTransform(transform, tileSize);
      }
      drape = terrain::TileDrape{index, drawn, transform, layer.options.opacity};
      drape.exposure = layer.exposure;
      drape.night = layer.options.night;
      drape.nativeTexelDegrees = layer.nativeTexelAt(tile);
      ++frame.drapes;
    }
    layer.cache.touch(wantedTiles);
    layer.loader->request(wanted);
    frame.requests += wanted.size();
    if (layer.loader->counters().inFlight > 0 || layer.opening.pending() > 0) {
      frame.complete = false;
    }
  }
  evictTextures(gpu);
  return frame;
}

void ImageryLayers::evictTextures(TileGpu& gpu) {
  if (gpu.imageryBytesResident() <= budget_.textureBytes) return;
  // Least recently drawn first; never this frame's, never a level-0 root (the last fallback).
  std::vector<std::tuple<uint64_t, uint32_t, geo::TileId>> byAge;
  for (uint32_t index = 0; index < layers_.size(); ++index) {
    for (const auto& [tile, last] : layers_[index]->textureLastUsedFrame) {
      if (last < frame_ && tile.level > 0) byAge.emplace_back(last, index, tile);
    }
  }
  std::sort(byAge.begin(), byAge.end());
  for (const auto& [last, index, tile] : byAge) {
    if (gpu.imageryBytesResident() <= budget_.textureBytes) break;
    gpu.releaseImageryTile(index, tile);
    layers_[index]->textureLastUsedFrame.erase(tile);
  }
}

std::vector<terrain::NominalErrorRegion> ImageryLayers::nominalErrorRegions(
    uint32_t verticesPerSide, double maximumScreenSpaceErrorPixels) const {
  std::vector<terrain::NominalErrorRegion> regions;
  const bool maskHidden = waterMaskHidden();
  for (const auto& layer : layers_) {
    if (!(layer->options.opacity > 0.0f)) continue;  // draws nothing
    if (maskHidden && layer->isWaterMask()) continue;
    const formats::LayerManifest& manifest = layer->store->manifest();
    auto imageryLevel = [&](uint32_t terrainLevel) {
      return layer->imageryLevel(terrainLevel, verticesPerSide, maximumScreenSpaceErrorPixels);
    };
    std::optional<uint32_t> deepest;
    for (uint32_t level = 0; level < geo::kMaxLevel; ++level) {
      if (imageryLevel(level + 1) > imageryLevel(level)) deepest = level;
    }
    if (!deepest) continue;  // one level only: refining never sharpens it
    // The sources' extent, not the tiles' (a coarse tile spans far beyond its data).
    std::optional<formats::BoundsDegrees> extent;
    for (const formats::ImagerySourceInfo& source : manifest.sources) {
      if (!extent) {
        extent = source.bounds;
        continue;
      }
      extent->west = std::min(extent->west, source.bounds.west);
      extent->south = std::min(extent->south, source.bounds.south);
      extent->east = std::max(extent->east, source.bounds.east);
      extent->north = std::max(extent->north, source.bounds.north);
    }
    formats::BoundsDegrees bounds = extent.value_or(manifest.bounds);
    if (bounds.west > bounds.east || bounds.west < -180.0 || bounds.east > 180.0) {
      // Across the antimeridian (either way of writing it): every longitude.
      bounds.west = -180.0;
      bounds.east = 180.0;
    }
    regions.push_back(
        {geo::GlobeRectangle::fromDegrees(bounds.west, bounds.south, bounds.east, bounds.north),
         *deepest});
  }
  return regions;
}

bool ImageryLayers::waterMaskHidden() const {
  return std::any_of(layers_.begin(), layers_.end(), [](const auto& layer) {
    return layer->opaqueEverywhere && layer->options.opacity >= 1.0f;
  });
}

bool ImageryLayers::sharperBelow(const geo::TileId& tile, uint32_t verticesPerSide,
                                 double maximumScreenSpaceErrorPixels, double terrainStepDegrees) {
  if (tile.level >= geo::kMaxLevel) return false;
  const bool maskHidden = waterMaskHidden();
  for (const auto& layer : layers_) {
    if (!(layer->options.opacity > 0.0f)) continue;  // draws nothing
    if (maskHidden && layer->isWaterMask()) continue;
    if (layer->isWaterMask() &&
        !(terrain::waterMaskWeight(layer->nativeTexelAt(tile), terrainStepDegrees) > 0.0)) {
      continue;  // the terrain's own coast is as fine: the mask is not drawn here
    }
    const uint32_t childLevel =
        layer->imageryLevel(tile.level + 1, verticesPerSide, maximumScreenSpaceErrorPixels);
    if (childLevel <=
        layer->imageryLevel(tile.level, verticesPerSide, maximumScreenSpaceErrorPixels)) {
      continue;
    }
    for (const geo::TileId& child : tile.children()) {
      const geo::TileId imageryTile = terrain::ancestorAt(child, childLevel);
      if (layer->has(imageryTile).value_or(false)) return true;
      if (imageryTile.level <= tile.level) break;  // one imagery tile for all four children
    }
  }
  return false;
}

streaming::LoaderCounters ImageryLayers::counters() const {
  streaming::LoaderCounters sum;
  for (const auto& layer : layers_) {
    const streaming::LoaderCounters c = layer->loader->counters();
    sum.requested += c.requested;
    sum.started += c.started;
    sum.completed += c.completed;
    sum.absent += c.absent;
    sum.failed += c.failed;
    sum.cancelled += c.cancelled;
    sum.pending += c.pending;
    sum.inFlight += c.inFlight;
  }
  return sum;
}

void ImageryLayers::forgetFailures() {
  for (const auto& layer : layers_) {
    layer->loader->forgetFailures();
    layer->present.clear();  // a pack that failed answered "no tile"
  }
}

void ImageryLayers::waitForLoads(std::chrono::milliseconds timeout) const {
  for (const auto& layer : layers_) {
    if (layer->opening.pending() > 0) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));  // a pack index on its way
      return;
    }
  }
  for (const auto& layer : layers_) {
    if (layer->loader->counters().inFlight > 0) {
      layer->loader->waitForCompletion(timeout);
      return;
    }
  }
}

}  // namespace globe::scene
