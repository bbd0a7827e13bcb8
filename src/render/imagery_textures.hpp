// GPU textures of imagery tiles keyed by (layer, tile): upload with premultiplied alpha and a mip
// chain, look-up for drawing, eviction and the byte count (mip chain included).
#pragma once

#include <array>
#include <cstdint>

#include <glm/vec4.hpp>
#include <span>
#include <unordered_map>

#include "core/result.hpp"
#include "geo/tile_id.hpp"
#include "render/gl_object.hpp"

namespace globe::render {

struct ImageryTextureKey {
  uint32_t layer = 0;
  geo::TileId tile{};
  bool operator==(const ImageryTextureKey&) const = default;
};

struct ImageryTextureKeyHash {
  size_t operator()(const ImageryTextureKey& key) const noexcept {
    return std::hash<geo::TileId>{}(key.tile) ^ (size_t{key.layer} * 0x9e3779b97f4a7c15ULL);
  }
};

// A resident tile texture (name 0: none) and its size.
struct ResidentTexture {
  GLuint name = 0;
  int widthPixels = 0;
  int heightPixels = 0;
};

// Needs the GL context current on the calling thread for its whole life (like TerrainRenderer).
class ImageryTextures {
 public:
  // Filters anisotropically up to maxAnisotropy samples where GL_EXT/ARB_texture_filter_anisotropic
  // is available (1: never); the context must be current.
  explicit ImageryTextures(float maxAnisotropy = 1.0f);

  // Uploads (or replaces) one tile: RGBA8 with straight alpha, rows top-down (row 0 = v 0). Stored
  // premultiplied so that bilinear filtering and the mip chain do not bleed the colour of
  // transparent texels; mipmapped, trilinear (+ anisotropic where available), clamped to edge.
  Result<void> upload(uint32_t layer, const geo::TileId& tile, std::span<const uint8_t> rgba,
                      int widthPixels, int heightPixels);
  bool contains(uint32_t layer, const geo::TileId& tile) const;
  // The texture, name 0 when not resident.
  ResidentTexture find(uint32_t layer, const geo::TileId& tile) const;
  // The sampler to bind with a tile's texture: trilinear (+ anisotropic), or, where the texture
  // is magnified over the whole tile (terrain/texel_footprint.hpp), bilinear on the base level
  // only, which draws the same pixels there and spares llvmpipe the per-fragment level of detail.
  GLuint sampler(bool magnified) const {
    return magnified ? bilinearSampler_.get() : trilinearSampler_.get();
  }
  // Whether the part of a resident tile that uv rectangle (x, y, width, height in texture
  // coordinates) draws is opaque: no texel with alpha < 255 in it or within a margin of one
  // sixteenth of the tile around it (what bilinear filtering and the first four mip levels reach).
  // Layers under it cannot show there.
  bool isOpaqueOver(uint32_t layer, const geo::TileId& tile, const glm::vec4& uvRect) const;
  // For a water mask (grey = water fraction): what every texel that rectangle draws says, with
  // the same margin: all land, all water, all undecided (alpha 0), or a mix.
  enum class MaskOver { Mixed, Land, Water, Undecided };
  MaskOver maskOver(uint32_t layer, const geo::TileId& tile, const glm::vec4& uvRect) const;
  bool evict(uint32_t layer, const geo::TileId& tile);
  void clear();

  uint64_t bytesResident() const { return bytes_; }
  uint32_t tilesResident() const { return static_cast<uint32_t>(textures_.size()); }
  float maxAnisotropy() const { return maxAnisotropy_; }  // 1: not available

 private:
  struct Texture {
    GlObject name;
    int widthPixels = 0;
    int heightPixels = 0;
    uint64_t bytes = 0;
    // Bit c of row r: the cell (r, c) of a 16×16 grid over the tile has only opaque texels.
    std::array<uint16_t, 16> opaqueCells{};
    // Likewise cells whose texels are all (0, alpha 255), all (255, 255), all alpha 0.
    std::array<uint16_t, 16> landCells{}, waterCells{}, undecidedCells{};
  };
  // The cells of `uvRect` grown by one cell, clamped: false when the rectangle is not finite.
  static bool cellsOver(const glm::vec4& uvRect, int& c0, int& c1, int& r0, int& r1);
  static bool allSet(const std::array<uint16_t, 16>& cells, int c0, int c1, int r0, int r1);
  std::unordered_map<ImageryTextureKey, Texture, ImageryTextureKeyHash> textures_;
  uint64_t bytes_ = 0;
  float maxAnisotropy_ = 1.0f;
  GlObject trilinearSampler_;
  GlObject bilinearSampler_;
};

// RGBA8 texture bytes with the full mip chain: 4/3 of the base level.
constexpr uint64_t mipmappedTextureBytes(int widthPixels, int heightPixels) {
  return uint64_t(widthPixels) * uint64_t(heightPixels) * 4 * 4 / 3;
}

}  // namespace globe::render
