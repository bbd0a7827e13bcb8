// One viewer frame's wiring, with no GL: camera pose → view → tile selection → loads → meshes
// and textures prepared on a TileGpu → the collision array. Shared by `globe snapshot`, `view`,
// `play`, the soak and the benchmarks; the caller draws view(), tiles() and drapes().
#pragma once

#include <array>
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "camera/camera_pose.hpp"
#include "core/result.hpp"
#include "core/thread_pool_runner.hpp"
#include "core/warnings.hpp"
#include "geo/ellipsoid.hpp"
#include "scene/imagery_layers.hpp"
#include "scene/overlay_points.hpp"
#include "scene/tile_gpu.hpp"
#include "scene/tile_morphs.hpp"
#include "scene/tile_sunlight.hpp"
#include "streaming/background_pack_opens.hpp"
#include "streaming/block_cache.hpp"
#include "streaming/terrain_source.hpp"
#include "streaming/tile_loader.hpp"
#include "terrain/height_block.hpp"
#include "terrain/relief_shading.hpp"
#include "terrain/render_view.hpp"
#include "terrain/rendering_tile_array.hpp"
#include "terrain/tile_selection.hpp"
#include "tiles3d/tileset.hpp"
#include "tiles3d/tileset_stream.hpp"
#include "transport/network_settings.hpp"

namespace globe::scene {

inline constexpr int kDefaultSamples = 1;

struct SceneOptions {
  geo::GlobeModel globeModel = geo::GlobeModel::Wgs84;
  double maximumScreenSpaceErrorPixels = 2.0;
  bool hysteresis = true;  // off for snapshots: the final view must not depend on history
  size_t cacheBudgetBytes = 256u << 20;
  unsigned loaderThreads = 2;
  uint32_t maximumLoadLevel = geo::kMaxLevel;  // tiles deeper than this are never loaded
  double fovYRadians = 0.7853981633974483;     // 45°
  size_t gpuTileBudget = 4000;  // tiles kept on the GPU, least recently drawn go first
  // The ground over water for drawing, collision and heights alike (--sea-floor: SeaFloor).
  terrain::SeaSurface sea = terrain::SeaSurface::Water;
  std::vector<LayerOptions> layers;  // imagery draped over the terrain, bottom layer first
  ImageryBudget imageryBudget;
  // KML/KMZ, GeoJSON and GPX files read (--overlay): their lines, polygons and ground overlays
  // drawn as a layer over the imagery, their points placed each frame (pointMarks()).
  std::vector<std::shared_ptr<const overlays::OverlayDocument>> overlays;
  // 3D Tiles tilesets read (--tileset): streamed by screen-space error on the loader's threads,
  // drawn over the terrain and collided with as ground (tiles3d/tileset_stream.hpp).
  std::vector<std::shared_ptr<const tiles3d::Tileset>> tilesets;
  double tilesetScreenSpaceErrorPixels = 16;  // CesiumJS's default for 3D Tiles
  // --tileset-clamp: each tileset moved up or down its centre's vertical so that height 0 there
  // (where most models stand) sits on the terrain; off: heights above the ellipsoid, as the
  // 3D Tiles spec says.
  bool clampTilesets = false;
  size_t tilesetBudgetBytes = tiles3d::TilesetStream::kDefaultBudgetBytes;  // each tileset's
  uint32_t maximumImageryLoadLevel = geo::kMaxLevel;  // imagery deeper than this is never loaded
  // --lighting: how much hill-shading the imagery takes (render::TerrainStyle::imageryLighting);
  // Auto: full where its texels are too coarse to carry the relief, gentle where they carry it.
  terrain::ImageryLighting imageryLighting = terrain::ImageryLighting::Auto;
  // The tiler's measured geometric errors (terrain::SelectionOptions::measuredErrors), unless
  // --nominal-lod; under an imagery layer only where refining would not sharpen it
  // (ImageryLayers::nominalErrorRegions).
  bool measuredLod = true;
  bool sky = true;  // the sky and distance fog (render/sky_model.hpp); --no-sky: black space
  // Anti-aliasing: samples a pixel (render/multisample_target.hpp); 1 draws without.
  int samples = kDefaultSamples;
  // --time: the terrain lit by the real Sun at this instant (seconds since 1970, UTC), the night
  // side dark; unset: a light from the north-west that follows the camera, every place by day.
  std::optional<double> sunTimeUnixSeconds;
  // Past the pyramid's finest data, terrain tiles made from their parent's surface
  // (terrain/upsampled_block.hpp) where a layer's imagery is finer, so imagery is drawn at its
  // own resolution; off: imagery stops one level above the pyramid's deepest tile there.
  bool refineForImagery = true;
  // Failed loads (a server down, a 503) are tried again this long after the last try; 0: never
  // (snapshots and playback, whose result must not depend on when a server came back).
  double retryFailedLoadsSeconds = 0;
  // Frames over which a finer tile arriving near the camera rises out of the coarser surface
  // drawn there before (scene/tile_morphs.hpp), so the camera on it is lifted, not popped; 0 or
  // 1: drawn at once. For views that draw while tiles arrive (globe view, play --real-time); a
  // complete view (snapshots, playback) waits for its tiles and needs none.
  uint32_t morphFrames = 0;
  // Shadows under the real Sun (sunTimeUnixSeconds; scene/tile_sunlight.hpp): how many tiles'
  // shadows a frame computes (0: all, as a complete view wants). Views that draw while moving
  // take a few a frame, so a frame's time stays bounded.
  uint32_t shadowTilesPerFrame = 0;
  bool shadows = true;
  // What pyramids and layers given as http(s) URLs are read through: the program's, made from its
  // flags (transport/network_settings.hpp). Null: local directories only (a URL is an error).
  std::shared_ptr<transport::Network> network;
  // Where the scene's warnings go, each once (a missing or damaged pack, an imagery tile that
  // failed: drawn coarser), without the program's name in front; none: they are dropped. Called
  // on the thread that calls update().
  core::WarningSink warnings;
};

struct FrameInfo {
  terrain::SelectionCounters selection;
  size_t upsampled = 0;  // blocks made from their parent's surface this frame
  size_t tilesSelected = 0;
  size_t requests = 0;        // wanted and loadable
  size_t arrived = 0;         // blocks that arrived this frame
  size_t uploaded = 0;        // meshes built and uploaded this frame
  bool complete = false;      // nothing loadable is missing: the image is final
  size_t morphing = 0;        // tiles drawn on their way from a coarser surface
  size_t shadowsPending = 0;  // drawn tiles whose shadows are not computed yet
  // Tiles (terrain and imagery) this view wanted whose load or pack failed: drawn coarser there.
  // What a complete view lacks (snapshot and play exit 1 on it unless --allow-missing).
  size_t missingTiles = 0;
  double terrainHeightMeters = 0;  // under the camera, from the finest resident block
  size_t modelsDrawn = 0;          // 3D tile contents drawn (drawnModels())
  size_t modelsWanted = 0;         // 3D tiles this view wants and lacks
  ImageryFrame imagery;            // the layers' part of this frame (complete counts it)
};

class TerrainScene {
 public:
  static Result<std::unique_ptr<TerrainScene>> open(const std::filesystem::path& pyramidDir,
                                                    const SceneOptions& options);
  ~TerrainScene();

  const geo::Ellipsoid& ellipsoid() const { return ellipsoid_; }
  streaming::TerrainSource& store() { return *store_; }
  const streaming::TileLoader& loader() const { return *loader_; }
  const streaming::BlockCache& cache() const { return cache_; }
  // The imagery layers, or null without --layer.
  const ImageryLayers* imagery() const { return imagery_.get(); }
  // Per tile of tiles(), the imagery drawn on it (empty without layers).
  const std::vector<terrain::TileDrapes>& drapes() const { return drapes_; }
  const SceneOptions& options() const { return options_; }
  // The Sun's instant for the frames from now on (a camera path's keyframe times, the window's
  // time keys); nullopt: the light that follows the camera.
  void setSunTime(std::optional<double> unixSeconds) { options_.sunTimeUnixSeconds = unixSeconds; }
  // The vertical field of view of the next update's view (a path's "fov").
  void setFovY(double radians) { options_.fovYRadians = radians; }
  // The overlays' visible points (scene/overlay_points.hpp), in file order.
  std::span<const PointMark> pointMarks() const { return pointMarks_; }
  // Shows these overlays instead of the options' (files opened in the window): their draped
  // layer is replaced (or added on top of the imagery), its old textures released.
  Result<void> setOverlays(std::vector<std::shared_ptr<const overlays::OverlayDocument>> documents,
                           TileGpu& gpu);
  // The imagery layer index of the overlays' draped layer, if there is one.
  std::optional<uint32_t> overlayLayer() const { return overlayLayer_; }

  // Selects and streams the tiles for this pose; prepares what arrived on the GPU and releases
  // what has not been drawn for a while. Draw view() with tiles() and drapes() afterwards.
  FrameInfo update(const camera::CameraPose& pose, int widthPixels, int heightPixels, TileGpu& gpu);
  const terrain::RenderView& view() const { return view_; }
  const std::vector<geo::TileId>& tiles() const { return tiles_; }
  // The 3D tile contents this frame draws, every tileset's (ids unique across them).
  const std::vector<tiles3d::DrawnItem>& drawnModels() const { return drawnModels_; }
  // Where the layers keep the terrain's nominal refinement (computed when the scene opens).
  std::span<const terrain::NominalErrorRegion> nominalErrorRegions() const {
    return nominalErrorRegions_;
  }
  // This frame's rendering tile array with its blocks: what collision runs against (the paper's
  // "rendering terrain tiles array"), exactly the tiles drawn.
  const terrain::RenderingTileArray& renderingTileArray() const { return array_; }
  // Blocks until a load completes or the timeout passes (loads run on worker threads).
  void waitForLoads(std::chrono::milliseconds timeout) const;
  // Who the terrain and each layer's imagery are from, as their services say, each once: shown
  // beside the picture (empty for pyramids and layers made by globe-tiler).
  std::vector<std::string> attributions() const;
  // Surface height at a position from the finest tile the pyramid has there (loads it if needed).
  Result<double> terrainHeightMeters(double longitudeRadians, double latitudeRadians);

  // Runs update() until the view is complete (or the timeout), for deterministic images.
  Result<FrameInfo> updateUntilComplete(const camera::CameraPose& pose, int widthPixels,
                                        int heightPixels, TileGpu& gpu,
                                        std::chrono::seconds timeout);

 private:
  TerrainScene(std::unique_ptr<streaming::TerrainSource> store, const SceneOptions& options);
  void updateImagery(const glm::dvec3& cameraEcefMeters, TileGpu& gpu, FrameInfo& info);
  // The tilesets' streams, made at the first frame (clamped: on the terrain's finest height).
  void openTilesets();
  // Streams the tilesets for this view; their drawn surfaces become the array's overlay.
  void updateTilesets(const geo::Frustum& frustum, int heightPixels, FrameInfo& info);
  void retryFailedLoadsWhenDue();
  // Says (to the warnings) the store's new errors and these failed loads, each once.
  void reportFailures(const std::vector<streaming::LoadError>& failedLoads);
  // Ends the frame's morphs (scene/tile_morphs.hpp), releasing meshes of morphs dropped.
  void finishMorphs(TileGpu& gpu, FrameInfo& info);
  // The tiles under the camera below the finest one loaded there, a few levels deep, first of all.
  // `resident`: the finest level loaded under the camera.
  void requestUnderCamera(const camera::CameraPose& pose, uint32_t resident,
                          std::vector<streaming::LoadRequest>& requests);
  // Reads these tiles' pack indexes on the loader's threads (a remote pyramid).
  void openPacksInBackground(const std::vector<geo::TileId>& tiles);
  Result<void> uploadIfNeeded(const geo::TileId& tile, const terrain::HeightBlock& block,
                              TileGpu& gpu, bool replace = false);
  // The selected tiles that have blocks, uploaded where needed (morphing near the camera), into
  // tiles_, blocks_ and the collision array's records.
  std::vector<terrain::ArrayTile> drawSelected(const std::vector<geo::TileId>& selected,
                                               const camera::CameraPose& pose, TileGpu& gpu,
                                               FrameInfo& info);
  // The pyramid's finest source step at the tile's corners (scene/native_resolution.hpp), found
  // once per tile.
  std::array<double, 4> terrainStepDegreesAt(const geo::TileId& tile);
  static constexpr size_t kTerrainStepEntries = 1u << 16;
  // Tiles whose upload to the GPU failed and was reported (each once; bounded).
  std::unordered_set<geo::TileId> failedUploads_;
  static constexpr size_t kFailedUploadsReported = 64;

  SceneOptions options_;
  geo::Ellipsoid ellipsoid_;
  std::unique_ptr<streaming::TerrainSource> store_;
  streaming::BlockCache cache_;
  core::ThreadPoolRunner runner_;
  std::unique_ptr<streaming::TileLoader> loader_;
  streaming::BackgroundPackOpens
      packOpens_;  // a remote pyramid's pack indexes, read off this thread
  std::chrono::steady_clock::time_point lastRetry_ = std::chrono::steady_clock::now();
  std::unique_ptr<ImageryLayers> imagery_;
  // Where the layers need the terrain's nominal refinement (ImageryLayers::nominalErrorRegions):
  // fixed once the layers are open.
  std::vector<terrain::NominalErrorRegion> nominalErrorRegions_;
  std::vector<terrain::TileDrapes> drapes_;  // per tile of tiles_, with imagery
  std::vector<PointMark> pointMarks_;
  std::optional<uint32_t> overlayLayer_;
  static constexpr const char* kOverlayLayerName = "overlays";
  std::vector<geo::TileId> tiles_;
  std::vector<std::shared_ptr<const terrain::HeightBlock>>
      blocks_;  // keep the array's blocks alive
  terrain::RenderingTileArray array_;
  TileMorphs morphs_;
  std::vector<std::unique_ptr<tiles3d::TilesetStream>> tilesets_;
  std::vector<tiles3d::DrawnItem> drawnModels_;
  TileSunlight sunlight_;
  // The store's errors said lately, so a failed load that repeats one is not said again.
  std::vector<std::string> reportedSourceErrors_;
  static constexpr size_t kReportedSourceErrorsKept = 256;
  terrain::RenderView view_;
  uint64_t frame_ = 0;
  std::unordered_map<geo::TileId, uint64_t> gpuLastUsedFrame_;
  // Tiles past the pyramid's data that the selection may refine into (options.refineForImagery),
  // with their summaries (their parent's height bounds): filled as the selection finds them.
  std::unordered_map<geo::TileId, terrain::TileSummary> upsampled_;
  // terrainStepDegreesAt's answers
  std::unordered_map<geo::TileId, std::array<double, 4>> terrainStepDegrees_;
};

}  // namespace globe::scene
