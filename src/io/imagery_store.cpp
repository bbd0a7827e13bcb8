#include "io/imagery_store.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>

#include "io/big_endian.hpp"
#include "io/file_reads.hpp"

namespace globe::io {
namespace {}  // namespace

ImageryStore::ImageryStore(std::filesystem::path dir, LayerManifest manifest)
    : dir_(std::move(dir)), manifest_(std::move(manifest)) {}

Result<std::unique_ptr<ImageryStore>> ImageryStore::open(const std::filesystem::path& layerDir) {
  auto manifest = readLayerManifest(layerDir);
  if (!manifest) return Error{manifest.error()};
  return std::unique_ptr<ImageryStore>(new ImageryStore(layerDir, std::move(*manifest)));
}

std::filesystem::path ImageryStore::packFileOf(const geo::TileId& tile) const {
  return packPath(dir_, packOf(tile, manifest_.packTilesPerSide));
}

Result<std::shared_ptr<const ImageryStore::OpenPack>> ImageryStore::pack(const PackId& id) {
  if (id.level >= manifest_.levels.size()) return std::shared_ptr<const OpenPack>();
  const auto& packs = manifest_.levels[id.level].packs;
  if (!std::binary_search(packs.begin(), packs.end(), id)) return std::shared_ptr<const OpenPack>();
  return packs_.get(id, [this](const PackId& p) { return openPack(p); });
}

Result<std::shared_ptr<const ImageryStore::OpenPack>> ImageryStore::openPack(const PackId& id) {
  const std::filesystem::path path = packPath(dir_, id);
  // O_NONBLOCK: a FIFO in the pack's place must not block the viewer; it is refused below.
  FdCloser file{::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK)};
  if (file.fd < 0) return makeError(path.string() + ": cannot open: " + std::strerror(errno));
  struct stat info {};
  if (::fstat(file.fd, &info) != 0) {
    return makeError(path.string() + ": cannot stat: " + std::strerror(errno));
  }
  if (!S_ISREG(info.st_mode)) return makeError(path.string() + ": not a regular file");
  const auto fileBytes = static_cast<uint64_t>(info.st_size);
  const uint64_t indexEnd = imagePackIndexEndOffset(manifest_.packTilesPerSide);
  if (fileBytes < indexEnd + 4) {
    return makeError(path.string() + ": truncated pack (" + std::to_string(fileBytes) + " bytes)");
  }
  std::vector<std::byte> head(indexEnd);
  std::byte trailer[4];
  if (auto read = preadFully(file.fd, head.data(), head.size(), 0, path); !read) {
    return Error{read.error()};
  }
  if (auto read = preadFully(file.fd, trailer, 4, fileBytes - 4, path); !read) {
    return Error{read.error()};
  }
  auto index = decodeImagePackIndex(head, loadBigEndian32(trailer), fileBytes, path);
  if (!index) return Error{index.error()};
  if (index->id != id || index->tilesPerSide != manifest_.packTilesPerSide) {
    return makeError(path.string() + ": pack header disagrees with the layer manifest");
  }
  ++packIndexReads_;
  auto opened = std::make_shared<const OpenPack>(file.fd, std::move(*index));
  file.fd = -1;
  return opened;
}

std::vector<std::string> ImageryStore::takeNewPackErrors() { return packs_.takeNewErrors(); }

void ImageryStore::forgetFailedPacks() { packs_.forgetFailures(); }

Result<bool> ImageryStore::hasTile(const geo::TileId& tile) {
  auto opened = pack(packOf(tile, manifest_.packTilesPerSide));
  if (!opened) return Error{opened.error()};
  if (!*opened) return false;
  return (*opened)->index.entries[slotOf(tile, manifest_.packTilesPerSide)].present();
}

Result<std::optional<std::vector<std::byte>>> ImageryStore::loadEncoded(const geo::TileId& tile) {
  if (tile.level > geo::kMaxLevel) return makeError(dir_.string() + ": no " + geo::tileName(tile));
  auto opened = pack(packOf(tile, manifest_.packTilesPerSide));
  if (!opened) return Error{opened.error()};
  if (!*opened) return std::optional<std::vector<std::byte>>();
  const OpenPack& p = **opened;
  const size_t slot = slotOf(tile, manifest_.packTilesPerSide);
  const ImagePackEntry& e = p.index.entries[slot];
  if (!e.present()) return std::optional<std::vector<std::byte>>();
  const std::filesystem::path path = packPath(dir_, p.index.id);
  std::vector<std::byte> bytes(e.lengthBytes);
  auto checked = preadFully(p.fd, bytes.data(), bytes.size(), e.offset, path);
  if (checked) checked = checkImageTile(bytes, e, slot, path);
  if (!checked) {
    packs_.noteError(p.index.id, checked.error());
    return Error{checked.error() + " (" + geo::tileName(tile) + ")"};
  }
  ++tileReads_;
  return std::optional<std::vector<std::byte>>(std::move(bytes));
}

}  // namespace globe::io
