// Imagery tile textures: premultiplied upload, mip chain, anisotropy, byte accounting.
#include "render/imagery_textures.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

namespace globe::render {
namespace {

// GL_EXT/ARB_texture_filter_anisotropic (core in 4.6); glad is generated for core 3.3 without
// extensions, so the enums are spelled out here.
constexpr GLenum kTextureMaxAnisotropy = 0x84FE;
constexpr GLenum kMaxTextureMaxAnisotropy = 0x84FF;

bool hasExtension(std::string_view name) {
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint k = 0; k < count; ++k) {
    const auto* extension = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(k)));
    if (extension != nullptr && name == extension) return true;
  }
  return false;
}

std::string tileName(uint32_t layer, const geo::TileId& tile) {
  return "layer " + std::to_string(layer) + " tile " + std::to_string(tile.level) + "/" +
         std::to_string(tile.x) + "/" + std::to_string(tile.y);
}

}  // namespace

ImageryTextures::ImageryTextures(float maxAnisotropy) {
  if (maxAnisotropy > 1.0f && (hasExtension("GL_EXT_texture_filter_anisotropic") ||
                               hasExtension("GL_ARB_texture_filter_anisotropic"))) {
    GLfloat maximum = 1.0f;
    glGetFloatv(kMaxTextureMaxAnisotropy, &maximum);
    maxAnisotropy_ = std::clamp(maximum, 1.0f, maxAnisotropy);
  }
  // Clamped: a tile's edge texels are exactly at its edge (pixel-is-area), so neighbouring tiles
  // meet without sampling each other or wrapping to the far side.
  auto makeSampler = [](GLenum minFilter) {
    GlObject sampler = makeGlSampler();
    glSamplerParameteri(sampler.get(), GL_TEXTURE_MIN_FILTER, static_cast<GLint>(minFilter));
    glSamplerParameteri(sampler.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(sampler.get(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(sampler.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return sampler;
  };
  trilinearSampler_ = makeSampler(GL_LINEAR_MIPMAP_LINEAR);
  if (maxAnisotropy_ > 1.0f)
    glSamplerParameterf(trilinearSampler_.get(), kTextureMaxAnisotropy, maxAnisotropy_);
  bilinearSampler_ = makeSampler(GL_LINEAR);
}

Result<void> ImageryTextures::upload(uint32_t layer, const geo::TileId& tile,
                                     std::span<const uint8_t> rgba, int widthPixels,
                                     int heightPixels) {
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (widthPixels < 1 || heightPixels < 1 || widthPixels > maxSize || heightPixels > maxSize) {
    return makeError("terrain renderer: imagery " + tileName(layer, tile) + ": size " +
                     std::to_string(widthPixels) + "x" + std::to_string(heightPixels) +
                     " out of range (GL_MAX_TEXTURE_SIZE " + std::to_string(maxSize) + ")");
  }
  const uint64_t baseBytes = uint64_t(widthPixels) * uint64_t(heightPixels) * 4;
  if (rgba.size() != baseBytes) {
    return makeError("terrain renderer: imagery " + tileName(layer, tile) + ": " +
                     std::to_string(rgba.size()) + " bytes, a " + std::to_string(widthPixels) +
                     "x" + std::to_string(heightPixels) + " RGBA image has " +
                     std::to_string(baseBytes));
  }
  // Premultiplied alpha; opaque tiles (JPEG imagery) go up as they are.
  std::vector<uint8_t> premultiplied;
  const uint8_t* pixels = rgba.data();
  std::array<uint16_t, 16> opaqueCells;
  opaqueCells.fill(0xffff);
  // What each cell says as a water mask (grey in red): every texel land, water or undecided.
  // A cell whose first texel is none of those is none: colour imagery is ruled out in 256 reads.
  std::array<uint16_t, 16> landCells{}, waterCells{}, undecidedCells{};
  const auto width = static_cast<size_t>(widthPixels), height = static_cast<size_t>(heightPixels);
  auto says = [&](size_t texel, int& land, int& water, int& undecided) {
    const uint8_t grey = rgba[texel * 4], alpha = rgba[texel * 4 + 3];
    land = alpha == 255 && grey == 0, water = alpha == 255 && grey == 255, undecided = alpha == 0;
  };
  bool anyUniform = false;
  for (size_t row = 0; row < 16 && !anyUniform; ++row) {
    for (size_t column = 0; column < 16 && !anyUniform; ++column) {
      int land = 0, water = 0, undecided = 0;
      says((row * height / 16) * width + column * width / 16, land, water, undecided);
      anyUniform = land != 0 || water != 0 || undecided != 0;
    }
  }
  if (anyUniform) {
    landCells.fill(0xffff);
    waterCells.fill(0xffff);
    undecidedCells.fill(0xffff);
    for (size_t y = 0; y < height; ++y) {
      const size_t row = y * 16 / height;
      for (size_t x = 0; x < width; ++x) {
        int land = 0, water = 0, undecided = 0;
        says(y * width + x, land, water, undecided);
        const auto clear = static_cast<uint16_t>(~(1u << (x * 16 / width)));
        if (land == 0) landCells[row] &= clear;
        if (water == 0) waterCells[row] &= clear;
        if (undecided == 0) undecidedCells[row] &= clear;
      }
    }
  }
  for (size_t k = 3; k < rgba.size(); k += 4) {
    if (rgba[k] == 255) continue;
    for (size_t p = 3; p < rgba.size(); p += 4) {
      if (rgba[p] == 255) continue;
      const size_t texel = p / 4;
      const auto row =
          (texel / static_cast<size_t>(widthPixels)) * 16 / static_cast<size_t>(heightPixels);
      const auto column =
          (texel % static_cast<size_t>(widthPixels)) * 16 / static_cast<size_t>(widthPixels);
      opaqueCells[row] = static_cast<uint16_t>(opaqueCells[row] & ~(1u << column));
    }
    premultiplied.assign(rgba.begin(), rgba.end());
    for (size_t p = 0; p < premultiplied.size(); p += 4) {
      const unsigned alpha = premultiplied[p + 3];
      for (size_t c = 0; c < 3; ++c) {
        premultiplied[p + c] = static_cast<uint8_t>((premultiplied[p + c] * alpha + 127) / 255);
      }
    }
    pixels = premultiplied.data();
    break;
  }

  const ImageryTextureKey key{layer, tile};
  auto found = textures_.find(key);
  if (found != textures_.end() &&
      (found->second.widthPixels != widthPixels || found->second.heightPixels != heightPixels)) {
    evict(layer, tile);
    found = textures_.end();
  }
  const bool replacing = found != textures_.end();
  Texture texture;
  if (!replacing) texture.name = makeGlTexture();
  const GLuint name = replacing ? found->second.name.get() : texture.name.get();
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, name);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  if (replacing) {
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, widthPixels, heightPixels, GL_RGBA, GL_UNSIGNED_BYTE,
                    pixels);
  } else {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, widthPixels, heightPixels, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, pixels);
    // Filtering and wrapping: the samplers bound with it (sampler()).
  }
  glGenerateMipmap(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, 0);
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
    if (replacing) evict(layer, tile);
    return makeError("terrain renderer: GL error " + std::to_string(error) + " uploading imagery " +
                     tileName(layer, tile));
  }
  if (replacing) {
    found->second.opaqueCells = opaqueCells;
    found->second.landCells = landCells;
    found->second.waterCells = waterCells;
    found->second.undecidedCells = undecidedCells;
  }
  if (!replacing) {
    texture.opaqueCells = opaqueCells;
    texture.landCells = landCells;
    texture.waterCells = waterCells;
    texture.undecidedCells = undecidedCells;
    texture.widthPixels = widthPixels;
    texture.heightPixels = heightPixels;
    texture.bytes = mipmappedTextureBytes(widthPixels, heightPixels);
    bytes_ += texture.bytes;
    textures_.emplace(key, std::move(texture));
  }
  return {};
}

bool ImageryTextures::contains(uint32_t layer, const geo::TileId& tile) const {
  return textures_.contains({layer, tile});
}

bool ImageryTextures::cellsOver(const glm::vec4& uvRect, int& c0, int& c1, int& r0, int& r1) {
  // The cells the rectangle touches, grown by one cell each way (clamped to the tile).
  auto cell = [](float uv) { return static_cast<int>(std::floor(uv * 16.0f)); };
  if (!std::isfinite(uvRect.x) || !std::isfinite(uvRect.y) || !std::isfinite(uvRect.z) ||
      !std::isfinite(uvRect.w)) {
    return false;
  }
  c0 = std::max(0, cell(uvRect.x) - 1), c1 = std::min(15, cell(uvRect.x + uvRect.z) + 1);
  r0 = std::max(0, cell(uvRect.y) - 1), r1 = std::min(15, cell(uvRect.y + uvRect.w) + 1);
  return true;
}

bool ImageryTextures::allSet(const std::array<uint16_t, 16>& cells, int c0, int c1, int r0,
                             int r1) {
  for (int r = r0; r <= r1; ++r) {
    for (int c = c0; c <= c1; ++c) {
      if ((cells[static_cast<size_t>(r)] & (1u << c)) == 0) return false;
    }
  }
  return true;
}

bool ImageryTextures::isOpaqueOver(uint32_t layer, const geo::TileId& tile,
                                   const glm::vec4& uvRect) const {
  const auto found = textures_.find({layer, tile});
  int c0 = 0, c1 = 0, r0 = 0, r1 = 0;
  if (found == textures_.end() || !cellsOver(uvRect, c0, c1, r0, r1)) return false;
  return allSet(found->second.opaqueCells, c0, c1, r0, r1);
}

ImageryTextures::MaskOver ImageryTextures::maskOver(uint32_t layer, const geo::TileId& tile,
                                                    const glm::vec4& uvRect) const {
  const auto found = textures_.find({layer, tile});
  int c0 = 0, c1 = 0, r0 = 0, r1 = 0;
  if (found == textures_.end() || !cellsOver(uvRect, c0, c1, r0, r1)) return MaskOver::Mixed;
  const Texture& t = found->second;
  if (allSet(t.landCells, c0, c1, r0, r1)) return MaskOver::Land;
  if (allSet(t.waterCells, c0, c1, r0, r1)) return MaskOver::Water;
  if (allSet(t.undecidedCells, c0, c1, r0, r1)) return MaskOver::Undecided;
  return MaskOver::Mixed;
}

ResidentTexture ImageryTextures::find(uint32_t layer, const geo::TileId& tile) const {
  const auto found = textures_.find({layer, tile});
  if (found == textures_.end()) return {};
  return {found->second.name.get(), found->second.widthPixels, found->second.heightPixels};
}

bool ImageryTextures::evict(uint32_t layer, const geo::TileId& tile) {
  const auto found = textures_.find({layer, tile});
  if (found == textures_.end()) return false;
  bytes_ -= found->second.bytes;
  textures_.erase(found);
  return true;
}

void ImageryTextures::clear() {
  textures_.clear();
  bytes_ = 0;
}

}  // namespace globe::render
