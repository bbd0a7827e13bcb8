#include "streaming/imagery_store.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>

#include "core/big_endian.hpp"

namespace globe::streaming {

ImageryStore::ImageryStore(std::shared_ptr<transport::ByteSource> source,
                           formats::LayerManifest manifest)
    : source_(std::move(source)), manifest_(std::move(manifest)) {}

Result<std::unique_ptr<ImageryStore>> ImageryStore::open(
    const std::string& layer, std::shared_ptr<transport::Network> network) {
  auto source = transport::openByteSource(layer, network.get());
  if (!source) return Error{source.error()};
  auto manifest = formats::readLayerManifest(**source);
  if (!manifest) return Error{manifest.error()};
  return std::unique_ptr<ImageryStore>(new ImageryStore(std::move(*source), std::move(*manifest)));
}

std::string ImageryStore::packFileOf(const geo::TileId& tile) const {
  return source_->locationOf(formats::packName(formats::packOf(tile, manifest_.packTilesPerSide)));
}

Result<std::shared_ptr<const ImageryStore::OpenPack>> ImageryStore::pack(
    const formats::PackId& id) {
  if (!listsPack(manifest_.levels, id)) return std::shared_ptr<const OpenPack>();
  return packs_.get(id, [this](const formats::PackId& p) { return openPack(p); });
}

Result<std::shared_ptr<const ImageryStore::OpenPack>> ImageryStore::openPack(
    const formats::PackId& id) {
  const std::string name = formats::packName(id);
  const std::string path = source_->locationOf(name);
  const uint64_t indexEnd = formats::imagePackIndexEndOffset(manifest_.packTilesPerSide);
  auto opened = source_->open(name, indexEnd);
  if (!opened) return Error{opened.error()};
  const uint64_t fileBytes = opened->file->sizeBytes();
  if (fileBytes < indexEnd + 4 || opened->head.size() != indexEnd) {
    return makeError(path + ": truncated pack (" + std::to_string(fileBytes) + " bytes)");
  }
  std::byte trailer[4];
  if (auto read = opened->file->read(trailer, fileBytes - 4); !read) return Error{read.error()};
  auto index =
      formats::decodeImagePackIndex(opened->head, core::loadBigEndian32(trailer), fileBytes, path);
  if (!index) return Error{index.error()};
  if (index->id != id || index->tilesPerSide != manifest_.packTilesPerSide) {
    return makeError(path + ": pack header disagrees with the layer manifest");
  }
  ++packIndexReads_;
  return std::make_shared<const OpenPack>(std::move(opened->file), std::move(*index));
}

std::vector<std::string> ImageryStore::takeNewPackErrors() { return packs_.takeNewErrors(); }

void ImageryStore::forgetFailedPacks() { packs_.forgetFailures(); }

Result<bool> ImageryStore::hasTile(const geo::TileId& tile) {
  auto opened = pack(formats::packOf(tile, manifest_.packTilesPerSide));
  if (!opened) return Error{opened.error()};
  if (!*opened) return false;
  return (*opened)->index.entries[formats::slotOf(tile, manifest_.packTilesPerSide)].present();
}

ImageryStore::Peek ImageryStore::peekTile(const geo::TileId& tile) {
  const formats::PackId id = formats::packOf(tile, manifest_.packTilesPerSide);
  if (!listsPack(manifest_.levels, id)) return Peek::Absent;
  const auto opened = packs_.peek(id);
  if (!opened) return Peek::NotOpen;
  if (!*opened) return Peek::Absent;
  return (**opened)->index.entries[formats::slotOf(tile, manifest_.packTilesPerSide)].present()
             ? Peek::Present
             : Peek::Absent;
}

Result<std::optional<std::vector<std::byte>>> ImageryStore::loadEncoded(const geo::TileId& tile) {
  if (tile.level > geo::kMaxLevel) return makeError(location() + ": no " + geo::tileName(tile));
  auto opened = pack(formats::packOf(tile, manifest_.packTilesPerSide));
  if (!opened) return Error{opened.error()};
  if (!*opened) return std::optional<std::vector<std::byte>>();
  const OpenPack& p = **opened;
  const size_t slot = formats::slotOf(tile, manifest_.packTilesPerSide);
  const formats::ImagePackEntry& e = p.index.entries[slot];
  if (!e.present()) return std::optional<std::vector<std::byte>>();
  const std::string& path = p.file->location();
  std::vector<std::byte> bytes(e.lengthBytes);
  auto checked = p.file->read(bytes, e.offset);
  if (checked) checked = formats::checkImageTile(bytes, e, slot, path);
  if (!checked) {
    packs_.noteError(p.index.id, checked.error());
    return Error{checked.error() + " (" + geo::tileName(tile) + ")"};
  }
  ++tileReads_;
  return std::optional<std::vector<std::byte>>(std::move(bytes));
}

Result<std::optional<formats::ImageRgba>> ImageryStore::loadImage(const geo::TileId& tile) {
  auto encoded = loadEncoded(tile);
  if (!encoded) return Error{encoded.error()};
  if (!*encoded) return std::optional<formats::ImageRgba>{};
  auto image = formats::decodeImageRgba(**encoded, packFileOf(tile));
  if (!image) return Error{image.error()};
  const auto size = static_cast<int>(manifest_.tileSizePixels);
  if (image->widthPixels != size || image->heightPixels != size) {
    return makeError(packFileOf(tile) + ": " + geo::tileName(tile) + " is " +
                     std::to_string(image->widthPixels) + "x" +
                     std::to_string(image->heightPixels) + " pixels, the layer's tiles are " +
                     std::to_string(size) + "x" + std::to_string(size));
  }
  return std::optional<formats::ImageRgba>{std::move(*image)};
}

}  // namespace globe::streaming
