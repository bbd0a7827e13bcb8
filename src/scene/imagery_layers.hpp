// The viewer's imagery layers: per drawn terrain tile and layer, the imagery tile whose texel
// fits the tile (terrain/imagery_level.hpp), streamed through the same loader, cache and
// priorities as the height blocks, uploaded as textures, and drawn through its nearest loaded
// ancestor (scale/bias) until it arrives, so a tile is never drawn untextured.
#pragma once

#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/vec3.hpp>

#include "core/result.hpp"
#include "core/task_runner.hpp"
#include "core/warnings.hpp"
#include "geo/ellipsoid.hpp"
#include "geo/tile_id.hpp"
#include "scene/tile_gpu.hpp"
#include "streaming/imagery_source.hpp"
#include "streaming/imagery_tiles.hpp"
#include "terrain/tile_drape.hpp"
#include "terrain/tile_selection.hpp"
#include "transport/network_settings.hpp"

namespace globe::scene {

struct LayerOptions {
  LayerOptions() = default;
  // Not an aggregate: {directory, opacity} stays complete as fields are added.
  LayerOptions(std::filesystem::path layerDirectory, float layerOpacity = 1.0f,
               std::shared_ptr<streaming::ImageryTiles> layerTiles = nullptr)
      : directory(std::move(layerDirectory)), opacity(layerOpacity), tiles(std::move(layerTiles)) {}

  std::filesystem::path directory;  // made by `globe-tiler imagery`, or a service
  float opacity = 1.0f;             // 0..1
  // Night lights (a city-lights image): shown only on the night side, as light of its own.
  bool night = false;
  // The photo's exposure (terrain/imagery_exposure.hpp): NaN picks it from the layer's median
  // luminance (dark imagery lifted); 1 leaves the photo as it is. Night and program-made layers
  // are never exposed.
  float exposure = std::numeric_limits<float>::quiet_NaN();
  // Tiles made by the program itself (the overlays' draped lines and polygons): used instead of
  // opening `directory`, which then only names the layer.
  std::shared_ptr<streaming::ImageryTiles> tiles;
};

struct ImageryBudget {
  size_t decodedBytes = 64u << 20;   // decoded tiles waiting for (or kept after) upload, per layer
  size_t textureBytes = 256u << 20;  // textures on the GPU, mip chains included, all layers
};

struct ImageryFrame {
  size_t requests = 0;   // imagery tiles wanted and not yet loaded
  size_t arrived = 0;    // decoded tiles that arrived this frame
  size_t uploaded = 0;   // textures uploaded this frame
  size_t fallbacks = 0;  // drapes drawn with an ancestor's texture while their own loads
  size_t drapes = 0;     // (terrain tile, layer) pairs drawn with a texture
  bool complete = true;  // every drape uses its own imagery tile and nothing is loading
  size_t missing = 0;    // drapes drawn with an ancestor's texture because their own tile failed
};

class ImageryLayers {
 public:
  // Opens every layer (errors name the directory); bottom layer first. Layers given as http(s)
  // URLs are read through `network` (null: local directories only). `warnings` gets the tiles
  // and packs that failed (drawn coarser), from update().
  static Result<std::unique_ptr<ImageryLayers>> open(
      std::span<const LayerOptions> layers, core::TaskRunner& runner, const ImageryBudget& budget,
      std::shared_ptr<transport::Network> network = nullptr, core::WarningSink warnings = {});
  ~ImageryLayers();
  ImageryLayers(const ImageryLayers&) = delete;
  ImageryLayers& operator=(const ImageryLayers&) = delete;

  bool empty() const { return layers_.empty(); }
  // Each layer's exposure as drawn (known after the first update; 1 before), bottom first.
  std::vector<float> exposures() const;
  // Each layer's attribution (empty where it gives none), bottom layer first.
  std::vector<std::string> attributions() const;
  size_t size() const { return layers_.size(); }

  // One frame: drapes[i] for tiles[i]. Loads are prioritised by the terrain tile's distance to
  // the camera. Each layer's level-0 tiles are loaded and uploaded once, before anything else,
  // so every covered tile has a texture to fall back on.
  // Imagery tiles deeper than maximumLoadLevel are never loaded: their ancestor at that level is
  // drawn instead (as a view mid-refinement would), and the frame counts as complete.
  Result<ImageryFrame> update(std::span<const geo::TileId> tiles, uint32_t verticesPerSide,
                              double maximumScreenSpaceErrorPixels, uint32_t maximumLoadLevel,
                              const glm::dvec3& cameraEcefMeters, const geo::Ellipsoid& ellipsoid,
                              TileGpu& gpu, std::vector<terrain::TileDrapes>& drapes);

  // Where refining the terrain makes some layer sharper (its imagery level follows the terrain
  // tile's: terrain/imagery_level.hpp): per visible layer, its sources' extent and the deepest
  // terrain level whose children take a finer imagery level. Elsewhere the selection may stop
  // refining smooth ground early (terrain::NominalErrorRegion).
  std::vector<terrain::NominalErrorRegion> nominalErrorRegions(
      uint32_t verticesPerSide, double maximumScreenSpaceErrorPixels) const;

  // Whether refining terrain tile `tile` into its children sharpens some visible layer there: a
  // layer has the imagery tile the children take (terrain::imageryLevelFor), and it is deeper than
  // the one `tile` takes. Where a layer's index is not read yet, no for now (it is read in the
  // background and the answer comes a later frame).
  // A water mask counts only where it is in charge over terrain whose finest source step there
  // is terrainStepDegrees (terrain/water_mask_weight.hpp; NaN: unknown, it is).
  bool sharperBelow(const geo::TileId& tile, uint32_t verticesPerSide,
                    double maximumScreenSpaceErrorPixels,
                    double terrainStepDegrees = std::numeric_limits<double>::quiet_NaN());

  // Whether a water mask cannot show: some layer at full opacity covers the whole globe opaquely
  // (the Blue Marble), so the terrain's land and sea colours never do. Such a mask is neither
  // loaded nor drawn, nor refined for. Known once the level-0 tiles are loaded (first update).
  bool waterMaskHidden() const;

  // Replaces layer `index` with one made from `options` (or adds it on top when index == size()):
  // the old layer's loads finish and its textures leave the GPU first. For the window's overlays,
  // which change as files are opened. Errors name the layer; the old one is gone either way.
  Result<void> setLayer(uint32_t index, const LayerOptions& options, core::TaskRunner& runner,
                        TileGpu& gpu, std::shared_ptr<transport::Network> network = nullptr);

  // Loader counters summed over the layers.
  streaming::LoaderCounters counters() const;
  // Blocks until some layer's load completes or the timeout passes.
  void waitForLoads(std::chrono::milliseconds timeout) const;
  // Lets failed tiles and packs be tried again (a server that was down may be back).
  void forgetFailures();

 private:
  struct Layer;
  ImageryLayers(std::vector<std::unique_ptr<Layer>> layers, const ImageryBudget& budget,
                core::WarningSink warnings);
  Result<void> preload(Layer& layer, uint32_t index, TileGpu& gpu);
  void evictTextures(TileGpu& gpu);

  std::vector<std::unique_ptr<Layer>> layers_;
  ImageryBudget budget_;
  core::WarningSink warnings_;
  uint64_t frame_ = 0;
  bool preloaded_ = false;
};

}  // namespace globe::scene
