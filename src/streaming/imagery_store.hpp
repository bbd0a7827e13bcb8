// Read access to an imagery layer on disk: each pack's index is read once, then every tile is one
// read with its CRC checked. Same spirit as TileStore.
#pragma once

#include <atomic>
#include <cstddef>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/result.hpp"
#include "formats/image_pack.hpp"
#include "formats/layer_manifest.hpp"
#include "geo/tile_id.hpp"
#include "streaming/imagery_tiles.hpp"
#include "streaming/open_packs.hpp"
#include "transport/byte_source.hpp"
#include "transport/network_settings.hpp"

namespace globe::streaming {

class ImageryStore final : public ImageryTiles {
 public:
  // `layer`: a directory, or the http(s) URL of one on a static server read through `network`
  // (the program's: transport/network_settings.hpp). Without a network (the default, for callers
  // that open local directories only) a URL is an error naming it.
  static Result<std::unique_ptr<ImageryStore>> open(
      const std::string& layer, std::shared_ptr<transport::Network> network = nullptr);
  ~ImageryStore() override = default;
  ImageryStore(const ImageryStore&) = delete;
  ImageryStore& operator=(const ImageryStore&) = delete;

  const formats::LayerManifest& manifest() const override { return manifest_; }
  // The layer's directory or URL.
  const std::string& location() const override { return source_->location(); }
  bool remote() const override { return source_->remote(); }

  // Whether the layer has this tile (reads the pack's index on first use). Thread-safe.
  Result<bool> hasTile(const geo::TileId& tile) override;
  // For a render thread that must not wait on a server: whether the layer has the tile, from its
  // pack's index without any I/O; Absent also for a pack that failed; NotOpen when the pack was
  // not read yet (hasTile, on a worker, reads it).
  Peek peekTile(const geo::TileId& tile) override;
  // ImageryTiles: loadEncoded, decoded; a tile whose decoded size is not the layer's tile size
  // is an error, not a picture drawn at the wrong scale.
  Result<std::optional<formats::ImageRgba>> loadImage(const geo::TileId& tile) override;
  std::string tileLocation(const geo::TileId& tile) const override { return packFileOf(tile); }
  std::vector<std::string> takeNewSourceErrors() override { return takeNewPackErrors(); }
  void forgetSourceFailures() override { forgetFailedPacks(); }
  // The tile's encoded bytes (JPEG or PNG) with one read, CRC checked; nullopt when the layer
  // has no such tile. Thread-safe.
  Result<std::optional<std::vector<std::byte>>> loadEncoded(const geo::TileId& tile);
  // Where a tile lives (its pack file path), for error messages.
  std::string packFileOf(const geo::TileId& tile) const;

  // The first error of each pack found missing or damaged since the last call, each pack once.
  std::vector<std::string> takeNewPackErrors();
  // Lets failed packs be opened (again, from their current file) and reported again.
  void forgetFailedPacks();

  uint64_t tileReads() const { return tileReads_.load(); }
  uint64_t packIndexReads() const { return packIndexReads_.load(); }

 private:
  using OpenPack = OpenPackFile<formats::ImagePackIndex>;
  ImageryStore(std::shared_ptr<transport::ByteSource> source, formats::LayerManifest manifest);
  // nullptr when the layer has no such pack.
  Result<std::shared_ptr<const OpenPack>> pack(const formats::PackId& id);
  Result<std::shared_ptr<const OpenPack>> openPack(const formats::PackId& id);

  std::shared_ptr<transport::ByteSource> source_;
  formats::LayerManifest manifest_;
  OpenPacks<OpenPack> packs_;
  std::atomic<uint64_t> tileReads_{0};
  std::atomic<uint64_t> packIndexReads_{0};
};

}  // namespace globe::streaming
