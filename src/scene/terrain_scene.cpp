#include "scene/terrain_scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <thread>

#include <glm/gtc/matrix_transform.hpp>

#include "geo/ecef.hpp"
#include "geo/frustum.hpp"
#include "geo/tiling_scheme.hpp"
#include "overlays/overlay_imagery.hpp"
#include "scene/native_resolution.hpp"
#include "scene/tileset_overlay.hpp"
#include "services/terrain_services.hpp"
#include "sun/solar_position.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/tile_mesh.hpp"
#include "terrain/upsampled_block.hpp"

namespace globe::scene {
namespace {

// Levels requested ahead of the refinement from a remote pyramid (SelectionOptions).
constexpr uint32_t kRemoteLookaheadLevels = 3;
// Tiles this near the camera's nadir morph when they arrive: a few camera heights above the
// ground, at least 2 km (collision reads the nadir and the near plane's neighbourhood).
constexpr double kMorphMinimumRadiusMeters = 2000.0;
constexpr double kMorphRadiusPerHeight = 3.0;
// The tile under the camera, the one collision reads, loads before anything on screen, and the
// levels below it too (a descent needs them next): this many past the finest one here.
constexpr double kNadirPriority = std::numeric_limits<double>::max();
constexpr uint32_t kNadirLookaheadLevels = 3;

// Refinement past the pyramid's data for imagery (SceneOptions::refineForImagery).
struct Upsampling {
  ImageryLayers& imagery;
  std::unordered_map<geo::TileId, terrain::TileSummary>& tiles;  // TerrainScene::upsampled_
  uint32_t verticesPerSide;
  double maximumScreenSpaceErrorPixels;
};

// The pyramid index says what exists; the loader's cache says what is drawable. With
// `notOpen`, a tile whose pack index was not read yet reads as a leaf's child would (its parent
// is drawn) and is listed there, so that a server's round trip never blocks the frame. With
// `upsampling`, a leaf's children exist where they sharpen a layer, and theirs in turn: their
// summary is their parent's height bounds, with no measured error (the nominal one refines them).
class SceneCatalog final : public terrain::TileCatalog {
 public:
  SceneCatalog(streaming::TerrainSource& store, const streaming::TileLoader& loader,
               std::vector<geo::TileId>* notOpen, Upsampling* upsampling)
      : store_(store), loader_(loader), notOpen_(notOpen), upsampling_(upsampling) {}
  std::optional<terrain::TileSummary> find(const geo::TileId& tile) const override {
    // A tile made from its parent is never the pyramid's: no pack lookup for it.
    if (upsampling_ != nullptr) {
      if (auto known = upsampling_->tiles.find(tile); known != upsampling_->tiles.end()) {
        return known->second;
      }
    }
    bool notYetOpen = false;
    if (auto summary = inPyramid(tile, notYetOpen)) return summary;
    if (notYetOpen || upsampling_ == nullptr || tile.level == 0) return std::nullopt;
    // The parent is a leaf of the pyramid, or itself made from its parent.
    const geo::TileId parent = tile.parent();
    std::optional<terrain::TileSummary> parentSummary;
    if (auto known = upsampling_->tiles.find(parent); known != upsampling_->tiles.end()) {
      parentSummary = known->second;
    } else {
      parentSummary = inPyramid(parent, notYetOpen);
    }
    if (!parentSummary ||
        !upsampling_->imagery.sharperBelow(
            parent, upsampling_->verticesPerSide, upsampling_->maximumScreenSpaceErrorPixels,
            finestStepDegreesAt(store_.manifest().sources, parent))) {
      return std::nullopt;
    }
    if (upsampling_->tiles.size() >= kUpsampledEntries) upsampling_->tiles.clear();
    const terrain::TileSummary summary{parentSummary->subtreeHeightRange,
                                       std::numeric_limits<double>::quiet_NaN()};
    upsampling_->tiles.emplace(tile, summary);
    return summary;
  }
  bool isResident(const geo::TileId& tile) const override { return loader_.isResident(tile); }
  // Tiles the selection asked about whose pack failed (FrameInfo::missingTiles).
  size_t missing() const { return missing_; }

 private:
  // Bounded: a long flight finds ever new tiles (the chain from a leaf is found again top-down).
  static constexpr size_t kUpsampledEntries = 1u << 16;

  std::optional<terrain::TileSummary> inPyramid(const geo::TileId& tile, bool& notYetOpen) const {
    if (notOpen_ != nullptr) {
      terrain::TileSummary summary;
      switch (store_.peek(tile, &summary)) {
        case streaming::TerrainSource::Peek::Present:
          return summary;
        case streaming::TerrainSource::Peek::Absent:
          if (store_.failedAt(tile)) ++missing_;  // its pack failed: its parent is drawn
          return std::nullopt;
        case streaming::TerrainSource::Peek::NotOpen:
          notOpen_->push_back(tile);
          notYetOpen = true;
          return std::nullopt;
      }
    }
    auto summary = store_.summary(tile);
    if (!summary || !*summary) {
      // An unreadable pack draws its parent instead: a tile the view needed and lacks.
      if (!summary || store_.failedAt(tile)) ++missing_;
      return std::nullopt;
    }
    return **summary;
  }

  streaming::TerrainSource& store_;
  const streaming::TileLoader& loader_;
  std::vector<geo::TileId>* notOpen_;
  Upsampling* upsampling_;
  mutable size_t missing_ = 0;
};

// Bilinear height inside a block at a position of its tile (water: 0 m, or its sea floor).
double blockHeightMeters(const terrain::HeightBlock& block, const geo::TileId& tile,
                         double longitudeRadians, double latitudeRadians) {
  const auto rect = geo::GeographicTilingScheme::tileRectangle(tile);
  const double n = block.verticesPerSide - 1;
  const double u =
      std::clamp((longitudeRadians - rect.westRadians) / rect.widthRadians(), 0.0, 1.0) * n;
  const double v =
      std::clamp((rect.northRadians - latitudeRadians) / rect.heightRadians(), 0.0, 1.0) * n;
  const auto j = static_cast<uint32_t>(std::min(std::floor(u), n - 1));
  const auto i = static_cast<uint32_t>(std::min(std::floor(v), n - 1));
  const double tu = u - j, tv = v - i;
  return (1 - tv) * ((1 - tu) * block.surfaceHeightMetersAt(i, j) +
                     tu * block.surfaceHeightMetersAt(i, j + 1)) +
         tv * ((1 - tu) * block.surfaceHeightMetersAt(i + 1, j) +
               tu * block.surfaceHeightMetersAt(i + 1, j + 1));
}

glm::dvec3 sunDirectionFor(const geo::Ellipsoid& ellipsoid, const camera::CameraPose& pose) {
  // Light from the north-west and high, the cartographers' convention for readable relief.
  const auto enu = camera::eastNorthUp(ellipsoid, pose.position);
  return glm::normalize(enu.up * 1.2 - enu.east * 0.6 + enu.north * 0.6);
}

}  // namespace

TerrainScene::TerrainScene(std::unique_ptr<streaming::TerrainSource> store,
                           const SceneOptions& options)
    : options_(options),
      ellipsoid_(geo::ellipsoidFor(options.globeModel)),
      store_(std::move(store)),
      cache_(options.cacheBudgetBytes),
      runner_(options.loaderThreads),
      loader_(std::make_unique<streaming::TileLoader>(*store_, runner_, cache_)),
      morphs_(options.morphFrames, ellipsoid_) {
  if (store_->remote()) loader_->setMaxInFlight(transport::kRemoteLoadsInFlight);
}

TerrainScene::~TerrainScene() {
  imagery_.reset();
  tilesets_.clear();  // their loads still running find them gone
  loader_.reset();    // waits for running loads before the runner goes
  runner_.shutdown();
}

Result<std::unique_ptr<TerrainScene>> TerrainScene::open(const std::filesystem::path& pyramidDir,
                                                         const SceneOptions& options) {
  auto store = services::openTerrainSource(pyramidDir.string(), options.sea, options.network);
  if (!store) return Error{store.error()};
  SceneOptions sceneOptions = options;
  const bool remote =
      (*store)->remote() ||
      std::any_of(options.layers.begin(), options.layers.end(),
                  [](const LayerOptions& l) { return transport::isHttpUrl(l.directory); });
  if (remote) {
    sceneOptions.loaderThreads =
        std::max<unsigned>(sceneOptions.loaderThreads, transport::kRemoteLoadsInFlight);
  }
  std::unique_ptr<TerrainScene> scene(new TerrainScene(std::move(*store), sceneOptions));
  std::vector<LayerOptions> layerOptions = options.layers;
  // The overlays' lines, polygons and ground overlays: a layer above the imagery.
  if (std::shared_ptr<overlays::OverlayImagery> draped =
          overlays::OverlayImagery::create(options.overlays, kOverlayLayerName);
      !draped->empty()) {
    LayerOptions overlayLayer;
    overlayLayer.directory = kOverlayLayerName;
    overlayLayer.tiles = std::move(draped);
    layerOptions.push_back(std::move(overlayLayer));
    scene->overlayLayer_ = static_cast<uint32_t>(layerOptions.size() - 1);
  }
  scene->pointMarks_ = scene::pointMarks(options.overlays);
  if (!layerOptions.empty()) {
    auto layers = ImageryLayers::open(layerOptions, scene->runner_, options.imageryBudget,
                                      options.network, options.warnings);
    if (!layers) return Error{layers.error()};
    scene->imagery_ = std::move(*layers);
    scene->nominalErrorRegions_ = scene->imagery_->nominalErrorRegions(
        scene->store_->manifest().verticesPerSide, options.maximumScreenSpaceErrorPixels);
  }
  return scene;
}

Result<void> TerrainScene::setOverlays(
    std::vector<std::shared_ptr<const overlays::OverlayDocument>> documents, TileGpu& gpu) {
  options_.overlays = std::move(documents);
  pointMarks_ = scene::pointMarks(options_.overlays);
  LayerOptions layer;
  layer.directory = kOverlayLayerName;
  layer.tiles = overlays::OverlayImagery::create(options_.overlays, kOverlayLayerName);
  if (!imagery_) {
    auto opened = ImageryLayers::open({}, runner_, options_.imageryBudget, options_.network,
                                      options_.warnings);
    if (!opened) return Error{opened.error()};
    imagery_ = std::move(*opened);
  }
  const uint32_t index = overlayLayer_.value_or(static_cast<uint32_t>(imagery_->size()));
  if (auto set = imagery_->setLayer(index, layer, runner_, gpu, options_.network); !set) {
    overlayLayer_.reset();
    return set;
  }
  overlayLayer_ = index;
  nominalErrorRegions_ = imagery_->nominalErrorRegions(store_->manifest().verticesPerSide,
                                                       options_.maximumScreenSpaceErrorPixels);
  return {};
}

Result<void> TerrainScene::uploadIfNeeded(const geo::TileId& tile,
                                          const terrain::HeightBlock& block, TileGpu& gpu,
                                          bool replace) {
  gpuLastUsedFrame_[tile] = frame_;
  if (!replace && gpu.hasTile(tile)) return {};
  const uint32_t n = store_->manifest().verticesPerSide;
  const auto mesh = terrain::buildTileMesh(
      tile, block, ellipsoid_, terrain::recommendedSkirtDepthMeters(tile.level, n, ellipsoid_));
  sunlight_.forget(tile);
  return gpu.prepareTile(tile, mesh);
}

std::vector<terrain::ArrayTile> TerrainScene::drawSelected(const std::vector<geo::TileId>& selected,
                                                           const camera::CameraPose& pose,
                                                           TileGpu& gpu, FrameInfo& info) {
  tiles_.clear();
  blocks_.clear();
  std::vector<terrain::ArrayTile> arrayTiles;
  const double lon = pose.position.longitudeRadians, lat = pose.position.latitudeRadians;
  // What collision may read soon: the ground within a few camera heights (at least 2 km).
  const double morphRadiusMeters =
      std::max(kMorphMinimumRadiusMeters,
               kMorphRadiusPerHeight * (pose.position.heightMeters - info.terrainHeightMeters));
  for (const geo::TileId& tile : selected) {
    const bool onGpu = gpu.hasTile(tile);
    auto loaded = loader_->get(tile);
    if (!loaded) continue;
    auto [block, replace] = morphs_.blockFor(tile, std::move(loaded),
                                             TileMorphs::isNear(tile, lon, lat, morphRadiusMeters));
    if (auto uploaded = uploadIfNeeded(tile, *block, gpu, replace); !uploaded) {
      // Each tile's failure once (it is tried again every frame): not a message per frame.
      if (failedUploads_.size() < kFailedUploadsReported && failedUploads_.insert(tile).second) {
        core::warn(options_.warnings, geo::tileName(tile) + ": " + uploaded.error());
      }
      continue;
    }
    tiles_.push_back(tile);
    arrayTiles.push_back(terrain::makeArrayTile(tile, *block));
    blocks_.push_back(std::move(block));
    info.uploaded += onGpu && !replace ? 0 : 1;
  }
  return arrayTiles;
}

void TerrainScene::finishMorphs(TileGpu& gpu, FrameInfo& info) {
  // A morph dropped half way leaves a morph's mesh on the GPU: not to be drawn when the tile
  // comes back.
  for (const geo::TileId& tile : morphs_.endFrame()) {
    gpu.releaseTile(tile);
    gpuLastUsedFrame_.erase(tile);
    sunlight_.forget(tile);
  }
  info.morphing = morphs_.active();
}

FrameInfo TerrainScene::update(const camera::CameraPose& pose, int widthPixels, int heightPixels,
                               TileGpu& gpu) {
  ++frame_;
  FrameInfo info;
  retryFailedLoadsWhenDue();
  cache_.beginFrame();
  const streaming::PollResult polled = loader_->poll();
  info.arrived = polled.arrived.size();
  reportFailures(polled.errors);

  // Clearance above the terrain sets the near plane: from the finest resident block under us.
  info.terrainHeightMeters = 0;
  uint32_t loadedUnderCamera = 0;  // the finest level loaded there (requestUnderCamera)
  for (uint32_t level = store_->manifest().maxLevel() + 1; level-- > 0;) {
    const auto tile = geo::GeographicTilingScheme::positionToTile(
        pose.position.longitudeRadians, pose.position.latitudeRadians, level);
    if (!tile || !loader_->isResident(*tile)) continue;
    if (auto block = loader_->get(*tile)) {
      info.terrainHeightMeters = blockHeightMeters(*block, *tile, pose.position.longitudeRadians,
                                                   pose.position.latitudeRadians);
      loadedUnderCamera = level;
      break;
    }
  }
  // A roof under the camera (last frame's drawn tilesets) is ground for the near plane too.
  if (const terrain::SurfaceOverlay* roofs = array_.overlay()) {
    const auto roof =
        roofs->heightAt(pose.position.longitudeRadians, pose.position.latitudeRadians);
    if (roof) info.terrainHeightMeters = std::max(info.terrainHeightMeters, *roof);
  }
  const camera::CameraFrame frame = camera::cameraFrame(ellipsoid_, pose);
  const double aspect = static_cast<double>(widthPixels) / std::max(heightPixels, 1);
  const auto projection = camera::projectionForHeight(
      pose.position.heightMeters,
      std::max(pose.position.heightMeters - info.terrainHeightMeters, 0.0), options_.fovYRadians,
      aspect, ellipsoid_);
  view_.cameraEcefMeters = frame.positionEcefMeters;
  view_.viewMatrix = camera::viewMatrix(frame);
  view_.projection = camera::projectionMatrix(projection);
  view_.farMeters = projection.farMeters;
  view_.widthPixels = widthPixels;
  view_.heightPixels = heightPixels;
  view_.sunIsReal = options_.sunTimeUnixSeconds.has_value();
  view_.sunDirectionEcef = view_.sunIsReal ? sun::sunDirectionEcef(*options_.sunTimeUnixSeconds)
                                           : sunDirectionFor(ellipsoid_, pose);
  view_.cameraHeightMeters = pose.position.heightMeters;

  terrain::SelectionView selectionView;
  selectionView.cameraEcefMeters = frame.positionEcefMeters;
  selectionView.frustum = geo::Frustum::fromViewProjection(view_.projection * view_.viewMatrix);
  selectionView.viewportHeightPixels = heightPixels;
  selectionView.fovYRadians = options_.fovYRadians;
  selectionView.ellipsoid = ellipsoid_;
  terrain::SelectionOptions selectionOptions;
  selectionOptions.maximumScreenSpaceErrorPixels = options_.maximumScreenSpaceErrorPixels;
  selectionOptions.verticesPerSide = store_->manifest().verticesPerSide;
  if (!options_.hysteresis) selectionOptions.hysteresisFraction = 0;
  // Imagery's resolution follows the terrain's level: flat ground keeps refining under a layer
  // as long as that sharpens it.
  selectionOptions.measuredErrors = options_.measuredLod;
  if (imagery_) {
    // Each frame: a layer's opacity may change (window keys), and a water mask under an opaque
    // world layer is known hidden once the level-0 tiles are in.
    nominalErrorRegions_ = imagery_->nominalErrorRegions(store_->manifest().verticesPerSide,
                                                         options_.maximumScreenSpaceErrorPixels);
  }
  selectionOptions.nominalErrorRegions = nominalErrorRegions_;
  if (store_->remote()) selectionOptions.lookaheadLevels = kRemoteLookaheadLevels;
  std::vector<geo::TileId> notOpen;
  if (store_->remote()) {
    // Every level's pack under the camera at once, rather than one level per round trip as the
    // refinement reaches it: the packs a view needs are mostly these (a pack spans 64 tiles).
    terrain::TileSummary ignored;
    for (uint32_t level = 0; level <= store_->manifest().maxLevel(); ++level) {
      const auto tile = geo::GeographicTilingScheme::positionToTile(
          pose.position.longitudeRadians, pose.position.latitudeRadians, level);
      if (tile && store_->peek(*tile, &ignored) == streaming::TerrainSource::Peek::NotOpen) {
        notOpen.push_back(*tile);
      }
    }
  }
  std::optional<Upsampling> upsampling;
  if (imagery_ && options_.refineForImagery) {
    upsampling.emplace(Upsampling{*imagery_, upsampled_, store_->manifest().verticesPerSide,
                                  options_.maximumScreenSpaceErrorPixels});
  }
  const SceneCatalog catalog(*store_, *loader_, store_->remote() ? &notOpen : nullptr,
                             upsampling ? &*upsampling : nullptr);
  terrain::SelectionResult selection =
      terrain::selectTiles(selectionView, catalog, selectionOptions,
                           options_.hysteresis ? tiles_ : std::vector<geo::TileId>{});

  cache_.touch(selection.tiles);
  info.missingTiles += catalog.missing();
  std::vector<streaming::LoadRequest> requests;
  for (const terrain::TileRequest& r : selection.requests) {
    if (r.tile.level > options_.maximumLoadLevel) continue;
    if (loader_->state(r.tile) == streaming::TileState::Failed) {
      info.missingTiles += r.lookahead ? 0 : 1;  // its parent is drawn instead
      continue;
    }
    if (upsampled_.contains(r.tile)) {
      // Made now from the parent's block, drawn from the next frame; a lookahead tile whose
      // parent is not here yet waits for it.
      if (auto parent =
              loader_->isResident(r.tile.parent()) ? loader_->get(r.tile.parent()) : nullptr) {
        cache_.insert(r.tile, std::make_shared<const terrain::HeightBlock>(
                                  terrain::upsampleBlock(*parent, r.tile, ellipsoid_)));
        ++info.upsampled;
      }
      continue;
    }
    const bool underCamera =
        geo::GeographicTilingScheme::positionToTile(
            pose.position.longitudeRadians, pose.position.latitudeRadians, r.tile.level) == r.tile;
    requests.push_back({r.tile, underCamera ? kNadirPriority : r.priority});
  }
  requestUnderCamera(pose, loadedUnderCamera, requests);
  loader_->request(requests);
  openPacksInBackground(notOpen);

  std::vector<terrain::ArrayTile> arrayTiles = drawSelected(selection.tiles, pose, gpu, info);
  // The ground under the camera must be known to collision even when it is not drawn (a camera
  // looking at the horizon does not see its own nadir): where no drawn tile covers the nadir, the
  // finest loaded tile there joins the collision array, and the finest tile is requested.
  // The nadir is nearer than anything drawn: it needs at least the finest level drawn.
  uint32_t nadirLevels = 0;
  for (const geo::TileId& tile : tiles_) nadirLevels = std::max(nadirLevels, tile.level);
  nadirLevels = std::min(nadirLevels, store_->manifest().maxLevel());
  const double lon = pose.position.longitudeRadians, lat = pose.position.latitudeRadians;
  array_.assign(arrayTiles);
  if (array_.lookupIndexed(lon, lat).tile == nullptr) {
    for (uint32_t level = std::min(nadirLevels, options_.maximumLoadLevel) + 1; level-- > 0;) {
      const auto tile = geo::GeographicTilingScheme::positionToTile(lon, lat, level);
      if (!tile) break;
      if (auto loaded = loader_->isResident(*tile) ? loader_->get(*tile) : nullptr) {
        // Its ground rises out of the coarser one too: the camera stands on it.
        auto block = morphs_.blockFor(*tile, std::move(loaded), true, false).block;
        arrayTiles.push_back(terrain::makeArrayTile(*tile, *block));
        arrayTiles.back().drawn = false;  // for collision only
        blocks_.push_back(std::move(block));
        array_.assign(std::move(arrayTiles));  // rebuilt only in this rare case
        break;
      }
      auto summary = store_->summary(*tile);
      if (summary && *summary && loader_->state(*tile) != streaming::TileState::Failed) {
        requests.push_back({*tile, kNadirPriority});
      }
    }
    if (!requests.empty()) loader_->request(requests);
  }
  finishMorphs(gpu, info);
  updateImagery(frame.positionEcefMeters, gpu, info);
  updateTilesets(selectionView.frustum, heightPixels, info);
  // Free GPU memory of tiles not drawn for a while, oldest first, once over the budget.
  if (gpuLastUsedFrame_.size() > options_.gpuTileBudget) {
    std::vector<std::pair<uint64_t, geo::TileId>> byAge;
    for (const auto& [tile, last] : gpuLastUsedFrame_) byAge.push_back({last, tile});
    std::sort(byAge.begin(), byAge.end());
    for (size_t k = 0; k < byAge.size() - options_.gpuTileBudget && byAge[k].first < frame_; ++k) {
      gpu.releaseTile(byAge[k].second);
      gpuLastUsedFrame_.erase(byAge[k].second);
      sunlight_.forget(byAge[k].second);
    }
  }
  if (options_.sunTimeUnixSeconds && options_.shadows) {
    const bool settled = requests.empty() && loader_->counters().inFlight == 0 &&
                         info.morphing == 0 && notOpen.empty();
    info.shadowsPending = sunlight_.update(array_, ellipsoid_, view_.sunDirectionEcef, gpu,
                                           options_.shadowTilesPerFrame, settled);
  }
  info.selection = selection.counters;
  info.tilesSelected = tiles_.size();
  info.requests = requests.size();
  info.arrived += packOpens_.takeFinished();
  info.complete = requests.empty() && info.upsampled == 0 && info.morphing == 0 &&
                  info.shadowsPending == 0 && loader_->counters().inFlight == 0 &&
                  notOpen.empty() && packOpens_.pending() == 0 && info.imagery.complete &&
                  info.modelsWanted == 0;
  return info;
}

void TerrainScene::openTilesets() {
  for (auto tileset : options_.tilesets) {
    const tiles3d::BoundingSphere& bounds = tileset->root.bounds;
    const auto center = geo::ecefToCartographic(ellipsoid_, bounds.centerEcefMeters);
    if (options_.clampTilesets && std::isfinite(bounds.radiusMeters) && center) {
      auto ground = terrainHeightMeters(center->longitudeRadians, center->latitudeRadians);
      if (ground) {
        const glm::dvec3 up = geo::geodeticSurfaceNormal(ellipsoid_, *center);
        auto placed = std::make_shared<tiles3d::Tileset>(*tileset);
        tiles3d::placeTileset(*placed, glm::translate(glm::dmat4(1.0), up * *ground));
        tileset = std::move(placed);
      } else {
        core::warn(options_.warnings, tileset->file + ": not clamped (" + ground.error() + ")");
      }
    }
    tilesets_.push_back(std::make_unique<tiles3d::TilesetStream>(tileset, ellipsoid_, runner_,
                                                                 options_.tilesetBudgetBytes));
  }
}

void TerrainScene::updateTilesets(const geo::Frustum& frustum, int heightPixels, FrameInfo& info) {
  if (options_.tilesets.empty()) return;
  if (tilesets_.empty()) openTilesets();
  tiles3d::TileSelectionView view;
  view.cameraEcefMeters = view_.cameraEcefMeters;
  view.frustum = frustum;
  view.pixelsPerRadian = heightPixels / (2 * std::tan(options_.fovYRadians / 2));
  view.maximumScreenSpaceErrorPixels = options_.tilesetScreenSpaceErrorPixels;
  drawnModels_.clear();
  std::vector<std::shared_ptr<const tiles3d::DrawnSurface>> surfaces;
  for (const auto& stream : tilesets_) {
    const tiles3d::StreamFrame frame = stream->update(view);
    for (const std::string& warning : frame.warnings) core::warn(options_.warnings, warning);
    info.modelsWanted += frame.wanted;
    info.arrived += frame.arrived;
    drawnModels_.insert(drawnModels_.end(), stream->drawn().begin(), stream->drawn().end());
    surfaces.push_back(stream->surface());
  }
  info.modelsDrawn = drawnModels_.size();
  array_.setOverlay(std::make_shared<TilesetOverlay>(std::move(surfaces)));
}

void TerrainScene::requestUnderCamera(const camera::CameraPose& pose, uint32_t resident,
                                      std::vector<streaming::LoadRequest>& requests) {
  const double lon = pose.position.longitudeRadians, lat = pose.position.latitudeRadians;
  const uint32_t deepest = std::min(store_->manifest().maxLevel(), options_.maximumLoadLevel);
  terrain::TileSummary ignored;
  for (uint32_t level = resident + 1; level <= std::min(deepest, resident + kNadirLookaheadLevels);
       ++level) {
    const auto tile = geo::GeographicTilingScheme::positionToTile(lon, lat, level);
    if (!tile) break;
    // Only tiles the pyramid holds: a local pack's index is read now (as the selection does); a
    // remote one not open yet is being opened in the background (openPacksInBackground).
    auto present = store_->peek(*tile, &ignored);
    if (present == streaming::TerrainSource::Peek::NotOpen && !store_->remote()) {
      auto summary = store_->summary(*tile);
      present = summary && *summary ? streaming::TerrainSource::Peek::Present
                                    : streaming::TerrainSource::Peek::Absent;
    }
    if (present != streaming::TerrainSource::Peek::Present ||
        loader_->state(*tile) == streaming::TileState::Failed) {
      break;
    }
    requests.push_back({*tile, kNadirPriority});
  }
}

void TerrainScene::reportFailures(const std::vector<streaming::LoadError>& failedLoads) {
  // Each missing or damaged pack once (the store remembers it), not once per tile or frame.
  for (std::string& error : store_->takeNewSourceErrors()) {
    core::warn(options_.warnings, error + "; drawing coarser tiles there");
    if (reportedSourceErrors_.size() >= kReportedSourceErrorsKept) reportedSourceErrors_.clear();
    reportedSourceErrors_.push_back(std::move(error));
  }
  // Each failed tile once (the loader reports it once), unless the store has said it of its pack:
  // a tile that fails to decode (a service's tile, say) is never a silent hole.
  for (const streaming::LoadError& error : failedLoads) {
    // Said already: the store named this tile's pack (one message a pack, not one a tile).
    const std::string file = error.file.string();
    const bool said = std::any_of(reportedSourceErrors_.begin(), reportedSourceErrors_.end(),
                                  [&](const std::string& text) {
                                    return (!file.empty() && text.starts_with(file)) ||
                                           error.message.find(text) != std::string::npos;
                                  });
    if (said) continue;
    core::warn(options_.warnings, error.message + "; drawing its parent there");
  }
}

void TerrainScene::openPacksInBackground(const std::vector<geo::TileId>& tiles) {
  for (const geo::TileId& tile : tiles) {
    packOpens_.post(runner_, store_->summaryGroupOf(tile), [this, tile] {
      (void)store_->summary(tile);  // opens the pack: an error is the store's to report
    });
  }
}

void TerrainScene::retryFailedLoadsWhenDue() {
  if (options_.retryFailedLoadsSeconds <= 0) return;
  const auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - lastRetry_).count() < options_.retryFailedLoadsSeconds) {
    return;
  }
  lastRetry_ = now;
  if (loader_->counters().failed > 0) loader_->forgetFailures();
  if (imagery_) imagery_->forgetFailures();
}

void TerrainScene::updateImagery(const glm::dvec3& cameraEcefMeters, TileGpu& gpu,
                                 FrameInfo& info) {
  if (!imagery_) return;
  auto frame = imagery_->update(
      tiles_, store_->manifest().verticesPerSide, options_.maximumScreenSpaceErrorPixels,
      options_.maximumImageryLoadLevel, cameraEcefMeters, ellipsoid_, gpu, drapes_);
  if (frame) {
    info.imagery = *frame;
    info.missingTiles += frame->missing;
    // The terrain's own step where each tile is, for the relief weight (TileDrape).
    for (size_t i = 0; i < tiles_.size(); ++i) {
      if (drapes_[i].count == 0 && !drapes_[i].hasWaterMask) continue;
      const std::array<double, 4> step = terrainStepDegreesAt(tiles_[i]);
      for (uint32_t k = 0; k < drapes_[i].count; ++k)
        drapes_[i].layers[k].terrainStepDegrees = step;
      drapes_[i].waterMask.terrainStepDegrees = step;
    }
    return;
  }
  // A texture that cannot be uploaded: the terrain's own colours rather than no picture.
  core::warn(options_.warnings, "imagery: " + frame.error());
  drapes_.assign(tiles_.size(), terrain::TileDrapes{});
}

std::array<double, 4> TerrainScene::terrainStepDegreesAt(const geo::TileId& tile) {
  if (auto it = terrainStepDegrees_.find(tile); it != terrainStepDegrees_.end()) return it->second;
  if (terrainStepDegrees_.size() >= kTerrainStepEntries) terrainStepDegrees_.clear();
  const std::array<double, 4> degrees =
      finestStepDegreesAtCorners(store_->manifest().sources, tile);
  terrainStepDegrees_.emplace(tile, degrees);
  return degrees;
}

void TerrainScene::waitForLoads(std::chrono::milliseconds timeout) const {
  if (packOpens_.pending() > 0) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));  // a pack index on its way
  } else if (loader_->counters().inFlight > 0) {
    loader_->waitForCompletion(timeout);
  } else if (imagery_) {
    imagery_->waitForLoads(timeout);
  }
}

Result<FrameInfo> TerrainScene::updateUntilComplete(const camera::CameraPose& pose, int widthPixels,
                                                    int heightPixels, TileGpu& gpu,
                                                    std::chrono::seconds timeout) {
  const auto until = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    FrameInfo info = update(pose, widthPixels, heightPixels, gpu);
    if (info.complete) return info;
    if (std::chrono::steady_clock::now() > until) {
      return makeError("the view was not complete after " + std::to_string(timeout.count()) +
                       " s (" + std::to_string(info.requests) + " tiles still wanted)");
    }
    waitForLoads(std::chrono::milliseconds(50));
  }
}

std::vector<std::string> TerrainScene::attributions() const {
  std::vector<std::string> out;
  auto add = [&out](const std::string& text) {
    if (!text.empty() && std::find(out.begin(), out.end(), text) == out.end()) out.push_back(text);
  };
  add(store_->attribution());
  if (imagery_) {
    for (const std::string& text : imagery_->attributions()) add(text);
  }
  return out;
}

Result<double> TerrainScene::terrainHeightMeters(double longitudeRadians, double latitudeRadians) {
  for (uint32_t level = store_->manifest().maxLevel() + 1; level-- > 0;) {
    const auto tile =
        geo::GeographicTilingScheme::positionToTile(longitudeRadians, latitudeRadians, level);
    if (!tile) return makeError("invalid position");
    auto summary = store_->summary(*tile);
    if (!summary) return Error{summary.error()};
    if (!*summary) continue;
    auto block = store_->loadBlock(*tile);
    if (!block) return Error{block.error()};
    return blockHeightMeters(*block, *tile, longitudeRadians, latitudeRadians);
  }
  return 0.0;
}

}  // namespace globe::scene
