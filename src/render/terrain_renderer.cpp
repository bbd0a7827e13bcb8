// The terrain renderer: shared index buffer, per-tile GPU buffers, per-frame uniforms, draw loop.
#include "render/terrain_renderer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "geo/ecef.hpp"
#include "render/aerial_haze.hpp"
#include "render/gl_object.hpp"
#include "render/gpu_tile.hpp"
#include "render/imagery_textures.hpp"
#include "render/shader_directory.hpp"
#include "render/shader_program.hpp"
#include "render/sky_model.hpp"
#include "render/sky_pass.hpp"
#include "terrain/relief_shading.hpp"
#include "terrain/skirt_edges.hpp"
#include "terrain/texel_footprint.hpp"
#include "terrain/tile_transform.hpp"
#include "terrain/water_mask_weight.hpp"

namespace globe::render {

namespace {

// A tile gets per-vertex logarithmic depth (early depth test) when its nearest point is at least
// this far from the camera and at least this many bounding radii away: its triangles (1/16 of the
// tile across) then span under ~1/32 of their distance, where the screen-linear interpolation of
// log2(1 + w) between vertices is off by < 1e-3 · w and only ever farther (log is concave).
constexpr double kVertexDepthMinMeters = 1000.0;
constexpr double kVertexDepthRadii = 2.0;

// A drape is drawn with the bilinear sampler where the bound on base-level texels per pixel
// (terrain/texel_footprint.hpp, on WGS84) is at most this: 1 is where GL magnifies; the 1 %
// covers the spherical globe model's radius (0.1 % off WGS84's) and ground down to -11 km.
constexpr double kMagnifiedTexelsPerPixel = 0.99;

// Texture units: 0 the global image, 1..kMaxDrapeLayers the layers, then the water mask.
constexpr GLuint kWaterMaskUnit = 1 + terrain::kMaxDrapeLayers;
constexpr GLuint kHazeUnit = kWaterMaskUnit + 1;  // the physical sky's image (aerial_haze.hpp)

}  // namespace

struct TerrainRenderer::Impl {
  struct Uniforms {
    GLint modelView = -1, tileOrigin = -1, projection = -1, tileCenter = -1, imageryRect = -1;
    GLint sunDirection = -1, ambient = -1, hillShading = -1, imagery = -1, daylight = -1,
          daylightBand = -1;
    GLint logDepthScale = -1, coarserEdges = -1;
    GLint fogColor = -1, fogDensity = -1, fogMaximum = -1;
    GLint layerTransform = -1, layerOpacity = -1, layerLight = -1, levelLight = -1;
    GLint layerExposure = -1, layerNight = -1;
    AerialHazeUniforms aerial;
    GLint waterMask = -1, waterMaskTransform = -1, waterMaskWeight = -1;
    std::array<GLint, terrain::kMaxDrapeLayers> layerSamplers{-1, -1, -1, -1};
  };

  // [imagery][layers][depth]: imagery 1 = the global image draped (GLOBE_IMAGERY); layers n =
  // n drape layers over it (GLOBE_LAYERS n: one program per count, because llvmpipe pays for
  // texture fetches under uniform branches it cannot skip); depth 0 = logarithmic depth per
  // fragment (gl_FragDepth), 1 = per vertex (keeps early-z).
  struct Program {
    ShaderProgram program;
    Uniforms uniforms;
  };
  // A tile's layers as drawn: resident textures only, none under an opaque one.
  struct BoundDrapes {
    std::array<GLuint, terrain::kMaxDrapeLayers> textures{};
    std::array<glm::vec4, terrain::kMaxDrapeLayers> transforms{};
    std::array<float, terrain::kMaxDrapeLayers> opacities{};
    std::array<float, terrain::kMaxDrapeLayers> exposures{};
    std::array<float, terrain::kMaxDrapeLayers> nights{};  // 1: night lights (TileDrape::night)
    // w of mix(1, relief, w) per layer, at the tile's corners (NW, NE, SW, SE)
    std::array<glm::vec4, terrain::kMaxDrapeLayers> lightWeights{};
    std::array<GLuint, terrain::kMaxDrapeLayers> samplers{};
    uint32_t count = 0;
    bool opaqueBase = false;  // layer 0 is opaque everywhere (texels and opacity)
    // The water mask: texture, uv transform, its weight at the tile's corners (NW, NE, SW, SE;
    // terrain/water_mask_weight.hpp) times its opacity.
    GLuint maskTexture = 0;
    GLuint maskSampler = 0;
    glm::vec4 maskTransform{0.0f, 0.0f, 1.0f, 1.0f};
    glm::vec4 maskWeights{0.0f};
  };
  struct DrawItem {
    double nearestMeters;
    const GpuTile* gpu;
    geo::TileId tile;
    terrain::TileTransform transform;  // made once a frame (terrain/tile_transform.hpp)
    terrain::SkirtEdgeMask skirts;
    BoundDrapes drapes;
    terrain::SkirtEdgeMask coarser = 0;  // edges facing a coarser neighbour
  };

  TerrainRendererOptions options;
  TerrainStyle style;
  std::map<uint32_t, Program> programs;  // by variant key (programKey)
  std::vector<DrawItem> drawItems[2];
  bool programErrorReported = false;  // per-frame scratch, kept to avoid reallocating
  std::unordered_set<geo::TileId> drawnIds;
  GlObject indexBuffer;
  GLenum indexType = GL_UNSIGNED_SHORT;
  GLsizei indexCount = 0;
  uintptr_t indexSize = 2;  // bytes per index
  uint64_t indexBytes = 0;
  GlObject imagery;
  uint64_t imageryBytes = 0;
  ImageryTextures imageryTiles;
  std::unordered_map<geo::TileId, GpuTile> tiles;
  std::unique_ptr<SkyPass> sky;
  bool skyFailed = false;
  // The sky pass, made on first use; false (said once) when its shaders do not build.
  bool skyPass() {
    if (sky || skyFailed) return sky != nullptr;
    auto made = SkyPass::create(options.shaderDirectory);
    if (!made) {
      core::warn(options.warn, "no sky: " + made.error());
      skyFailed = true;
      return false;
    }
    sky = std::move(*made);
    return true;
  }
  uint64_t tileBytes = 0;

  // The program for this variant, compiled on first use and kept.
  Result<const Program*> program(bool globalImage, uint32_t layers, bool vertexDepth,
                                 bool lightImagery, bool opaqueBase = false,
                                 bool waterMask = false);
  // Where the camera is and one pixel's angle (terrain::pixelAngleRadians): which sampler a
  // drape needs.
  struct Footprint {
    glm::dvec3 cameraEcefMeters{0.0};
    double pixelAngleRadians = 0.0;
  };
  BoundDrapes resolveDrapes(const terrain::TileDrapes* drapes, const geo::TileId& tile,
                            const GpuTile& gpu, const Footprint& footprint,
                            FrameStats& stats) const;
  void bindDrapes(const BoundDrapes& drapes, const Uniforms& u) const;
  uint64_t gpuBytes() const {
    return tileBytes + indexBytes + imageryBytes + imageryTiles.bytesResident();
  }
};

// The tile's resident drape layers, bottom first. Layers under an opaque one (every texel this
// tile samples opaque, opacity 1) cannot show and are left out: fewer texture fetches per
// fragment, and the terrain's own colour is not needed (opaqueBase). Layers
// whose texture is not resident are skipped (the ones above still draw) and counted.
TerrainRenderer::Impl::BoundDrapes TerrainRenderer::Impl::resolveDrapes(
    const terrain::TileDrapes* drapes, const geo::TileId& tile, const GpuTile& gpu,
    const Footprint& footprint, FrameStats& stats) const {
  BoundDrapes bound;
  const uint32_t count = drapes == nullptr ? 0 : std::min(drapes->count, terrain::kMaxDrapeLayers);
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  const double sampleSpacingMeters =
      terrain::meridianSpacingMeters(tile, static_cast<int>(options.verticesPerSide) - 1, wgs84);
  for (uint32_t k = 0; k < count; ++k) {
    const terrain::TileDrape& drape = drapes->layers[k];
    const ResidentTexture resident = imageryTiles.find(drape.layer, drape.imageryTile);
    const GLuint texture = resident.name;
    if (texture == 0) {
      ++stats.drapesMissing;
      continue;
    }
    // NaN and negative opacities draw nothing.
    const float opacity = drape.opacity > 0.0f ? std::min(drape.opacity, 1.0f) : 0.0f;
    // Night lights add light where the Sun has set and cover nothing.
    const bool opaque =
        !drape.night && opacity >= 1.0f &&
        imageryTiles.isOpaqueOver(drape.layer, drape.imageryTile, drape.uvTransform);
    if (opaque) bound.count = 0;
    if (bound.count == 0) bound.opaqueBase = opaque;
    bound.textures[bound.count] = texture;
    bound.transforms[bound.count] = drape.uvTransform;
    bound.opacities[bound.count] = opacity;
    bound.exposures[bound.count] = std::max(drape.exposure, 1.0f);
    bound.nights[bound.count] = drape.night ? 1.0f : 0.0f;
    // Per corner from the data's own resolutions; where they are not known, from the drawn
    // imagery tile's texel over this tile's vertex spacing.
    for (int corner = 0; corner < 4; ++corner) {
      const double step = drape.terrainStepDegrees[static_cast<size_t>(corner)];
      const bool native = std::isfinite(drape.nativeTexelDegrees) && std::isfinite(step);
      bound.lightWeights[bound.count][corner] = static_cast<float>(
          native
              ? terrain::imageryLightWeight(style.imageryLighting, drape.nativeTexelDegrees, step)
              : terrain::imageryLightWeight(
                    style.imageryLighting,
                    terrain::meridianSpacingMeters(drape.imageryTile, resident.heightPixels, wgs84),
                    sampleSpacingMeters));
    }
    const double texelMeters = terrain::shortestTexelMeters(drape.imageryTile, resident.widthPixels,
                                                            resident.heightPixels, wgs84);
    const bool magnified =
        style.bilinearWhereMagnified &&
        terrain::maxTexelsPerPixel(footprint.cameraEcefMeters, gpu.box, texelMeters,
                                   footprint.pixelAngleRadians, wgs84) <= kMagnifiedTexelsPerPixel;
    bound.samplers[bound.count] = imageryTiles.sampler(magnified);
    ++bound.count;
  }
  // Under an opaque bottom layer the terrain's land and sea colours do not show: no mask.
  if (drapes != nullptr && drapes->hasWaterMask && !(bound.count > 0 && bound.opaqueBase)) {
    const terrain::TileDrape& mask = drapes->waterMask;
    const ResidentTexture resident = imageryTiles.find(mask.layer, mask.imageryTile);
    const float opacity = mask.opacity > 0.0f ? std::min(mask.opacity, 1.0f) : 0.0f;
    // Where the mask over the tile is all undecided, or agrees with every vertex's own flag, it
    // changes nothing: not sampled.
    const auto says = imageryTiles.maskOver(mask.layer, mask.imageryTile, mask.uvTransform);
    const bool changesNothing = says == ImageryTextures::MaskOver::Undecided ||
                                (says == ImageryTextures::MaskOver::Land && gpu.allLand) ||
                                (says == ImageryTextures::MaskOver::Water && gpu.allWater);
    if (resident.name == 0) {
      ++stats.drapesMissing;
    } else if (opacity > 0.0f && !changesNothing) {
      bound.maskTexture = resident.name;
      // Mipmapped where minified (a far coast as its coverage), bilinear where magnified over
      // the whole tile, as the layers.
      const double texelMeters = terrain::shortestTexelMeters(
          mask.imageryTile, resident.widthPixels, resident.heightPixels, wgs84);
      bound.maskSampler =
          imageryTiles.sampler(style.bilinearWhereMagnified &&
                               terrain::maxTexelsPerPixel(footprint.cameraEcefMeters, gpu.box,
                                                          texelMeters, footprint.pixelAngleRadians,
                                                          wgs84) <= kMagnifiedTexelsPerPixel);
      bound.maskTransform = mask.uvTransform;
      for (int corner = 0; corner < 4; ++corner) {
        bound.maskWeights[corner] =
            opacity *
            static_cast<float>(terrain::waterMaskWeight(
                mask.nativeTexelDegrees, mask.terrainStepDegrees[static_cast<size_t>(corner)]));
      }
      // Nowhere in charge (a finer terrain): not sampled either.
      if (bound.maskWeights == glm::vec4(0.0f)) bound.maskTexture = 0;
    }
  }
  // Counted once the layers under an opaque one are dropped.
  for (uint32_t k = 0; k < bound.count; ++k)
    stats.drapesMagnified += bound.samplers[k] == imageryTiles.sampler(true) ? 1 : 0;
  stats.drapesDrawn += bound.count;
  return bound;
}

Result<const TerrainRenderer::Impl::Program*> TerrainRenderer::Impl::program(
    bool globalImage, uint32_t layers, bool vertexDepth, bool lightImagery, bool opaqueBase,
    bool waterMask) {
  lightImagery = lightImagery && layers > 0;
  opaqueBase = opaqueBase && layers > 0;
  globalImage = globalImage && !opaqueBase;  // covered anyway
  // Under an opaque base the terrain's land and sea colours do not show (the relief's light on
  // water, flat at 0 m, is level anyway).
  waterMask = waterMask && !opaqueBase;
  const uint32_t key = (globalImage ? 1u : 0u) | (vertexDepth ? 2u : 0u) |
                       (lightImagery ? 4u : 0u) | (opaqueBase ? 8u : 0u) | (waterMask ? 16u : 0u) |
                       (layers << 5);
  if (auto found = programs.find(key); found != programs.end()) return &found->second;
  const auto& dir = options.shaderDirectory;
  const std::string defines =
      std::string(globalImage ? "#define GLOBE_IMAGERY 1\n" : "") +
      (layers > 0 ? "#define GLOBE_LAYERS " + std::to_string(layers) + "\n" : "") +
      (lightImagery ? "#define GLOBE_LIGHT_IMAGERY 1\n" : "") +
      (opaqueBase ? "#define GLOBE_OPAQUE_BASE 1\n" : "") +
      (waterMask ? "#define GLOBE_WATER_MASK 1\n" : "") +
      (vertexDepth ? "#define GLOBE_VERTEX_LOG_DEPTH 1\n" : "");
  auto loaded = loadNamedShaderProgram(dir, "terrain.vert", "terrain.frag", defines);
  if (!loaded) return Error{loaded.error()};
  Program target;
  target.program = std::move(*loaded);
  const ShaderProgram& p = target.program;
  Uniforms& u = target.uniforms;
  u.modelView = p.uniformLocation("u_modelView");
  u.tileOrigin = p.uniformLocation("u_tileOrigin");
  u.projection = p.uniformLocation("u_projection");
  u.tileCenter = p.uniformLocation("u_tileCenterEcef");
  u.imageryRect = p.uniformLocation("u_imageryRect");
  u.sunDirection = p.uniformLocation("u_sunDirection");
  u.daylight = p.uniformLocation("u_daylight");
  u.daylightBand = p.uniformLocation("u_daylightBand");
  u.ambient = p.uniformLocation("u_ambient");
  u.hillShading = p.uniformLocation("u_hillShading");
  u.imagery = p.uniformLocation("u_imagery");
  u.logDepthScale = p.uniformLocation("u_logDepthScale");
  u.coarserEdges = p.uniformLocation("u_coarserEdges");
  u.fogColor = p.uniformLocation("u_fogColor");
  u.fogDensity = p.uniformLocation("u_fogDensity");
  u.fogMaximum = p.uniformLocation("u_fogMaximum");
  u.layerTransform = p.uniformLocation("u_layerTransform");
  u.layerOpacity = p.uniformLocation("u_layerOpacity");
  u.layerLight = p.uniformLocation("u_layerLight");
  u.levelLight = p.uniformLocation("u_levelLight");
  u.aerial = AerialHazeUniforms::locate(p);
  u.layerExposure = p.uniformLocation("u_layerExposure");
  u.layerNight = p.uniformLocation("u_layerNight");
  u.waterMask = p.uniformLocation("u_waterMask");
  u.waterMaskTransform = p.uniformLocation("u_waterMaskTransform");
  u.waterMaskWeight = p.uniformLocation("u_waterMaskWeight");
  for (uint32_t k = 0; k < terrain::kMaxDrapeLayers; ++k) {
    u.layerSamplers[k] = p.uniformLocation(("u_layer" + std::to_string(k)).c_str());
  }
  if (u.modelView < 0 || u.tileOrigin < 0 || u.projection < 0 || u.logDepthScale < 0) {
    return makeError((dir / "terrain.vert").string() +
                     " + terrain.frag: the program lacks "
                     "u_modelView, u_tileOrigin, u_projection or u_logDepthScale");
  }
  if (layers > 0 && (u.layerTransform < 0 || u.layerOpacity < 0)) {
    return makeError((dir / "terrain.vert").string() +
                     " + terrain.frag: the GLOBE_LAYERS program lacks u_layerTransform or "
                     "u_layerOpacity");
  }
  if (waterMask && (u.waterMask < 0 || u.waterMaskTransform < 0 || u.waterMaskWeight < 0)) {
    return makeError((dir / "terrain.vert").string() +
                     " + terrain.frag: the GLOBE_WATER_MASK program lacks u_waterMask, "
                     "u_waterMaskTransform or u_waterMaskWeight");
  }
  return &programs.emplace(key, std::move(target)).first->second;
}

// Binds the layers to units 1.., the water mask to the unit after them, and sets their uniforms.
void TerrainRenderer::Impl::bindDrapes(const BoundDrapes& drapes, const Uniforms& u) const {
  if (drapes.maskTexture != 0 && u.waterMask >= 0) {
    glActiveTexture(GL_TEXTURE0 + kWaterMaskUnit);
    glBindTexture(GL_TEXTURE_2D, drapes.maskTexture);
    glBindSampler(kWaterMaskUnit, drapes.maskSampler);
    glUniform4fv(u.waterMaskTransform, 1, glm::value_ptr(drapes.maskTransform));
    glUniform4fv(u.waterMaskWeight, 1, glm::value_ptr(drapes.maskWeights));
  }
  for (uint32_t k = 0; k < drapes.count; ++k) {
    glActiveTexture(GL_TEXTURE1 + k);
    glBindTexture(GL_TEXTURE_2D, drapes.textures[k]);
    glBindSampler(1 + k, drapes.samplers[k]);
  }
  glActiveTexture(GL_TEXTURE0);
  if (drapes.count > 0) {
    const auto n = static_cast<GLsizei>(drapes.count);
    glUniform4fv(u.layerTransform, n, glm::value_ptr(drapes.transforms[0]));
    glUniform1fv(u.layerOpacity, n, drapes.opacities.data());
    if (u.layerExposure >= 0) glUniform1fv(u.layerExposure, n, drapes.exposures.data());
    if (u.layerNight >= 0) glUniform1fv(u.layerNight, n, drapes.nights.data());
    if (u.layerLight >= 0) {
      glUniform4fv(u.layerLight, n, glm::value_ptr(drapes.lightWeights[0]));
    }
  }
}

TerrainRenderer::TerrainRenderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
TerrainRenderer::~TerrainRenderer() = default;

Result<std::unique_ptr<TerrainRenderer>> TerrainRenderer::create(
    const TerrainRendererOptions& options) {
  if (!terrain::isValidBlockSize(options.verticesPerSide)) {
    return makeError("terrain renderer: block size " + std::to_string(options.verticesPerSide) +
                     " is not 2^k+1");
  }
  auto impl = std::make_unique<Impl>();
  impl->options = options;
  float anisotropy = options.maxImageryAnisotropy;
  if (!(anisotropy > 0.0f)) {  // 0 and NaN: by the GL (terrain_renderer.hpp)
    const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const std::string renderer = name != nullptr ? name : "";
    const bool software = renderer.find("llvmpipe") != std::string::npos ||
                          renderer.find("softpipe") != std::string::npos;
    anisotropy = software ? 1.0f : 8.0f;
  }
  impl->imageryTiles = ImageryTextures(anisotropy);
  if (impl->options.shaderDirectory.empty())
    impl->options.shaderDirectory = defaultShaderDirectory();
  // The programs without layers up front (a bad shader directory fails here); layered ones when
  // a frame first needs them.
  for (int imagery = 0; imagery < 2; ++imagery) {
    for (int depth = 0; depth < 2; ++depth) {
      auto program = impl->program(imagery == 1, 0, depth == 1, false);
      if (!program) return makeError(program.error());
    }
  }

  const std::vector<uint32_t> indices =
      terrain::buildGridIndices(options.verticesPerSide, options.skirts);
  const uint32_t vertexCount = terrain::tileVertexCount(options.verticesPerSide, options.skirts);
  impl->indexBuffer = makeGlBuffer();
  glBindVertexArray(0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, impl->indexBuffer.get());
  if (vertexCount <= std::numeric_limits<uint16_t>::max() + 1u) {
    const std::vector<uint16_t> shortIndices(indices.begin(), indices.end());
    impl->indexType = GL_UNSIGNED_SHORT;
    impl->indexSize = sizeof(uint16_t);
    impl->indexBytes = shortIndices.size() * sizeof(uint16_t);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(impl->indexBytes),
                 shortIndices.data(), GL_STATIC_DRAW);
  } else {
    impl->indexType = GL_UNSIGNED_INT;
    impl->indexSize = sizeof(uint32_t);
    impl->indexBytes = indices.size() * sizeof(uint32_t);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(impl->indexBytes), indices.data(),
                 GL_STATIC_DRAW);
  }
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  impl->indexCount = static_cast<GLsizei>(indices.size());
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
    return makeError("terrain renderer: GL error " + std::to_string(error) + " during set-up");
  }
  return std::unique_ptr<TerrainRenderer>(new TerrainRenderer(std::move(impl)));
}

Result<void> TerrainRenderer::uploadTile(const geo::TileId& tile, const terrain::TileMesh& mesh) {
  const auto& options = impl_->options;
  if (mesh.verticesPerSide != options.verticesPerSide || mesh.hasSkirts != options.skirts) {
    return makeError("terrain renderer: " + geo::tileName(tile) + ": mesh has " +
                     std::to_string(mesh.verticesPerSide) + " vertices per side" +
                     (mesh.hasSkirts ? " with" : " without") + " skirts, renderer expects " +
                     std::to_string(options.verticesPerSide) +
                     (options.skirts ? " with" : " without"));
  }
  const size_t expected =
      size_t{terrain::tileVertexCount(options.verticesPerSide, options.skirts)} *
      terrain::kTileVertexFloats;
  const size_t vertexCount = mesh.vertices.size() / terrain::kTileVertexFloats;
  const bool ownIndices =
      !mesh.indices.empty() && std::all_of(mesh.indices.begin(), mesh.indices.end(),
                                           [&](uint32_t k) { return k < vertexCount; });
  if (!mesh.indices.empty() && !ownIndices) {
    return makeError("terrain renderer: " + geo::tileName(tile) + ": a TIN index past its " +
                     std::to_string(vertexCount) + " vertices");
  }
  if (!ownIndices && mesh.vertices.size() != expected) {
    return makeError("terrain renderer: " + geo::tileName(tile) + ": mesh has " +
                     std::to_string(mesh.vertices.size()) + " floats, expected " +
                     std::to_string(expected));
  }
  evictTile(tile);
  GpuTile gpu = uploadGpuTile(tile, mesh, impl_->indexBuffer.get());
  impl_->tileBytes += gpu.vertexBytes;
  impl_->tiles.emplace(tile, std::move(gpu));
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
    evictTile(tile);
    return makeError("terrain renderer: GL error " + std::to_string(error) + " uploading a tile");
  }
  return {};
}

bool TerrainRenderer::evictTile(const geo::TileId& tile) {
  const auto found = impl_->tiles.find(tile);
  if (found == impl_->tiles.end()) return false;
  impl_->tileBytes -= found->second.vertexBytes;
  impl_->tiles.erase(found);
  return true;
}

bool TerrainRenderer::hasTile(const geo::TileId& tile) const { return impl_->tiles.contains(tile); }

Result<void> TerrainRenderer::setTileSunlight(const geo::TileId& tile,
                                              std::span<const float> gridVisibility) {
  const auto found = impl_->tiles.find(tile);
  if (found == impl_->tiles.end()) {
    return makeError("terrain renderer: " + geo::tileName(tile) + " is not resident");
  }
  if (!setGpuTileSunlight(found->second, gridVisibility)) {
    return makeError("terrain renderer: " + geo::tileName(tile) + ": " +
                     std::to_string(gridVisibility.size()) + " sunlight values for " +
                     std::to_string(found->second.verticesPerSide) + "² vertices");
  }
  return {};
}

void TerrainRenderer::evictAllTiles() {
  impl_->tiles.clear();
  impl_->tileBytes = 0;
}

Result<void> TerrainRenderer::setImagery(std::span<const uint8_t> rgba, int widthPixels,
                                         int heightPixels) {
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (widthPixels < 1 || heightPixels < 1 || widthPixels > maxSize || heightPixels > maxSize) {
    return makeError("terrain renderer: imagery size " + std::to_string(widthPixels) + "x" +
                     std::to_string(heightPixels) + " out of range (GL_MAX_TEXTURE_SIZE " +
                     std::to_string(maxSize) + ")");
  }
  const uint64_t bytes = uint64_t(widthPixels) * uint64_t(heightPixels) * 4;
  if (rgba.size() != bytes) {
    return makeError("terrain renderer: imagery has " + std::to_string(rgba.size()) + " bytes, a " +
                     std::to_string(widthPixels) + "x" + std::to_string(heightPixels) +
                     " RGBA image has " + std::to_string(bytes));
  }
  impl_->imagery = makeGlTexture();
  glBindTexture(GL_TEXTURE_2D, impl_->imagery.get());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, widthPixels, heightPixels, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               rgba.data());
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);
  impl_->imageryBytes = bytes * 4 / 3;  // with the mipmap chain
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
    clearImagery();
    return makeError("terrain renderer: GL error " + std::to_string(error) + " uploading imagery");
  }
  return {};
}

void TerrainRenderer::clearImagery() {
  impl_->imagery.reset();
  impl_->imageryBytes = 0;
}

bool TerrainRenderer::hasImagery() const { return static_cast<bool>(impl_->imagery); }

Result<void> TerrainRenderer::uploadImageryTile(uint32_t layer, const geo::TileId& tile,
                                                std::span<const uint8_t> rgba, int widthPixels,
                                                int heightPixels) {
  return impl_->imageryTiles.upload(layer, tile, rgba, widthPixels, heightPixels);
}
bool TerrainRenderer::hasImageryTile(uint32_t layer, const geo::TileId& tile) const {
  return impl_->imageryTiles.contains(layer, tile);
}
bool TerrainRenderer::evictImageryTile(uint32_t layer, const geo::TileId& tile) {
  return impl_->imageryTiles.evict(layer, tile);
}
void TerrainRenderer::evictAllImageryTiles() { impl_->imageryTiles.clear(); }
uint64_t TerrainRenderer::imageryBytesResident() const {
  return impl_->imageryTiles.bytesResident();
}
uint32_t TerrainRenderer::imageryTilesResident() const {
  return impl_->imageryTiles.tilesResident();
}

void TerrainRenderer::setStyle(const TerrainStyle& style) { impl_->style = style; }
const TerrainStyle& TerrainRenderer::style() const { return impl_->style; }

FrameStats TerrainRenderer::draw(const terrain::RenderView& view,
                                 std::span<const geo::TileId> tiles) {
  return draw(view, tiles, {});
}

FrameStats TerrainRenderer::draw(const terrain::RenderView& view,
                                 std::span<const geo::TileId> tiles,
                                 std::span<const terrain::TileDrapes> drapes) {
  Impl& impl = *impl_;
  const TerrainStyle& style = impl.style;
  FrameStats stats;
  stats.tilesRequested = static_cast<uint32_t>(tiles.size());

  // Near tiles (per-fragment depth) and far ones (per-vertex depth), each front to back so the
  // depth test rejects hidden fragments early. Near tiles go first: they occlude the far ones.
  for (auto& items : impl.drawItems) items.clear();
  impl.drawnIds.clear();
  const Impl::Footprint footprint{view.cameraEcefMeters, terrain::pixelAngleRadians(view)};
  for (size_t i = 0; i < tiles.size(); ++i) {
    const geo::TileId& tile = tiles[i];
    const auto found = impl.tiles.find(tile);
    if (found == impl.tiles.end()) {
      ++stats.tilesMissing;
      continue;
    }
    impl.drawnIds.insert(tile);
    const GpuTile& gpu = found->second;
    const double nearest = std::max(
        0.0, glm::distance(view.cameraEcefMeters, gpu.centerEcefMeters) - gpu.radiusMeters);
    const bool far =
        nearest >= kVertexDepthMinMeters && nearest >= kVertexDepthRadii * gpu.radiusMeters;
    const terrain::TileDrapes* tileDrapes = i < drapes.size() ? &drapes[i] : nullptr;
    impl.drawItems[far ? 1 : 0].push_back(
        {nearest, &gpu, tile, terrain::tileTransform(view, tile.level, gpu.centerEcefMeters), 0,
         impl.resolveDrapes(tileDrapes, tile, gpu, footprint, stats)});
  }
  // Skirts face the tiles that are really drawn (resident ones), known once all are listed.
  if (impl.options.skirts) {
    const terrain::DrawnEdgeHashes hashesOf =
        [&impl](const geo::TileId& tile) -> const terrain::EdgeHeightHashes* {
      if (!impl.drawnIds.contains(tile)) return nullptr;
      return &impl.tiles.find(tile)->second.edgeHeightHashes;
    };
    for (auto& items : impl.drawItems) {
      for (Impl::DrawItem& item : items) {
        item.skirts = terrain::neededSkirtEdges(item.tile, impl.drawnIds) |
                      terrain::mismatchedEdges(item.tile, item.gpu->edgeHeightHashes, hashesOf);
        // Too far for exact float positions (terrain/tile_transform.hpp): seams below a pixel.
        if (!item.transform.exact) item.skirts = terrain::kAllSkirtEdges;
        if (item.skirts != 0)
          item.coarser = terrain::coarserNeighbourEdges(item.tile, impl.drawnIds);
      }
    }
  }

  glViewport(0, 0, view.widthPixels, view.heightPixels);
  glClearColor(style.backgroundRgb.r, style.backgroundRgb.g, style.backgroundRgb.b, 1.0f);
  glClearDepth(1.0);
  glDepthMask(GL_TRUE);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  SkyParameters sky;  // all zero: no fog
  AerialHaze haze;    // none: the fog
  double globeRadius = 0.0;
  const bool drawSky = style.sky && impl.skyPass();
  if (drawSky) {
    double height = view.cameraHeightMeters;
    if (!std::isfinite(height)) {
      const auto camera = geo::ecefToCartographic(geo::Ellipsoid::wgs84(), view.cameraEcefMeters);
      height = camera ? camera->heightMeters : 0.0;
    }
    globeRadius = glm::length(view.cameraEcefMeters) - height;
    sky = skyAt(height, globeRadius);  // the fog needs it now; the sky is drawn last
    if (view.sunIsReal) {
      const double sunUp =
          glm::dot(glm::normalize(view.cameraEcefMeters), glm::normalize(view.sunDirectionEcef));
      sky = skyUnderSun(sky, sunUp);
      // The physically based sky, and its horizon's colour for the haze over the terrain.
      sky.horizonRgb = impl.sky->usePhysicalSky(height, sunUp);
      haze = aerialHazeFor(view, *impl.sky, height);
    } else {
      impl.sky->useModelSky();
    }
  }
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glFrontFace(GL_CCW);
  glDisable(GL_BLEND);

  const glm::mat4 projection(view.projection);
  const double sunLength = glm::length(view.sunDirectionEcef);
  const glm::vec3 sun = std::isfinite(sunLength) && sunLength > 0.0
                            ? glm::vec3(view.sunDirectionEcef / sunLength)
                            : glm::vec3(0.0f);
  const bool useImagery = style.drapeImagery && impl.imagery;
  // Without drapes the programs without GLOBE_LAYERS draw, exactly as before layers existed.
  const bool useLayers = !drapes.empty();
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, useImagery ? impl.imagery.get() : 0);
  const double farMeters = view.farMeters > 1.0 ? view.farMeters : terrain::kDefaultFarMeters;
  const auto logDepthScale = static_cast<float>(1.0 / std::log2(1.0 + farMeters));

  for (int variant = 0; variant < 2; ++variant) {
    auto& items = impl.drawItems[variant];
    if (items.empty()) continue;
    // By program (layer count, opaque base, water mask), then front to back.
    std::sort(items.begin(), items.end(), [](const Impl::DrawItem& a, const Impl::DrawItem& b) {
      if (a.drapes.count != b.drapes.count) return a.drapes.count < b.drapes.count;
      if (a.drapes.opaqueBase != b.drapes.opaqueBase) return a.drapes.opaqueBase;
      const bool aMask = a.drapes.maskTexture != 0, bMask = b.drapes.maskTexture != 0;
      if (aMask != bMask) return bMask;
      return a.nearestMeters < b.nearestMeters;
    });
    const Impl::Uniforms* current = nullptr;
    uint32_t currentLayers = terrain::kMaxDrapeLayers + 1;
    bool currentOpaqueBase = false;
    bool currentMask = false;
    for (const Impl::DrawItem& item : items) {
      const bool mask = item.drapes.maskTexture != 0;
      if (item.drapes.count != currentLayers || item.drapes.opaqueBase != currentOpaqueBase ||
          mask != currentMask || current == nullptr) {
        currentLayers = item.drapes.count;
        currentOpaqueBase = item.drapes.opaqueBase;
        currentMask = mask;
        auto found = impl.program(useImagery, currentLayers, variant == 1,
                                  style.imageryLighting != terrain::ImageryLighting::Off,
                                  currentOpaqueBase, currentMask);
        if (!found) {
          // Layers this GL cannot compile: the terrain without them, said once.
          if (!impl.programErrorReported) core::warn(impl.options.warn, found.error());
          impl.programErrorReported = true;
          found = impl.program(useImagery, 0, variant == 1, false);
          if (!found) continue;
          currentLayers = 0;
        }
        const Impl::Program& program = **found;
        current = &program.uniforms;
        const Impl::Uniforms& u = *current;
        glUseProgram(program.program.id());
        glVertexAttrib1f(kAttributeSunlight, 1.0f);  // tiles without shadows: full sun
        glUniformMatrix4fv(u.projection, 1, GL_FALSE, glm::value_ptr(projection));
        glUniform3fv(u.sunDirection, 1, glm::value_ptr(sun));
        glUniform1f(u.ambient, style.ambient);
        glUniform1i(u.daylight, view.sunIsReal ? 1 : 0);
        const DaylightBand band = daylightBand();
        glUniform3f(u.daylightBand, band.nightLight, band.nightCosine, band.dayCosine);
        glUniform3fv(u.fogColor, 1, glm::value_ptr(sky.horizonRgb));
        glUniform1f(u.fogDensity, sky.fogDensityPerMeter);
        glUniform1f(u.fogMaximum, sky.fogMaximum);
        setAerialHaze(haze, u.aerial, kHazeUnit);
        glUniform1i(u.hillShading, style.hillShading ? 1 : 0);
        if (u.levelLight >= 0) {
          glUniform1f(u.levelLight,
                      static_cast<float>(terrain::levelGroundLightWeight(style.imageryLighting)));
        }
        if (u.imagery >= 0) glUniform1i(u.imagery, 0);
        glUniform1f(u.logDepthScale, logDepthScale);
        // Units 1..4 (unit 0 holds the global image).
        for (uint32_t k = 0; k < currentLayers; ++k) {
          glUniform1i(u.layerSamplers[k], static_cast<GLint>(1 + k));
        }
        if (u.waterMask >= 0) glUniform1i(u.waterMask, static_cast<GLint>(kWaterMaskUnit));
      }
      const Impl::Uniforms& u = *current;
      const GpuTile& gpu = *item.gpu;
      // Camera-relative in double: the ~6.4e6 m translation cancels before the cast to float.
      // The eye rounded to the level's quantum gives every tile of the level the same matrix and
      // an exact float origin, so shared edge vertices come out bit-identical (header).
      glUniformMatrix4fv(u.modelView, 1, GL_FALSE, glm::value_ptr(item.transform.levelView));
      glUniform3fv(u.tileOrigin, 1, glm::value_ptr(item.transform.origin));
      const glm::vec3 center(gpu.centerEcefMeters);
      glUniform3fv(u.tileCenter, 1, glm::value_ptr(center));
      if (useImagery) glUniform4fv(u.imageryRect, 1, glm::value_ptr(gpu.imageryRect));
      // North, south, west, east (TileEdge order): 1 where the neighbour is coarser.
      auto coarser = [&](terrain::TileEdge edge) {
        return (item.coarser >> static_cast<uint32_t>(edge)) & 1U ? 1.0f : 0.0f;
      };
      glUniform4f(u.coarserEdges, coarser(terrain::TileEdge::North),
                  coarser(terrain::TileEdge::South), coarser(terrain::TileEdge::West),
                  coarser(terrain::TileEdge::East));
      if (currentLayers > 0 || currentMask) impl.bindDrapes(item.drapes, u);
      glBindVertexArray(gpu.vertexArray.get());
      if (gpu.indexCount > 0) {  // a TIN: its own triangles and skirts
        glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(gpu.indexCount), GL_UNSIGNED_INT,
                       nullptr);
        stats.triangles += gpu.indexCount / 3;
        ++stats.drawCalls;
        ++stats.tilesDrawn;
        continue;
      }
      // The grid and only the skirts this tile needs (terrain/skirt_edges.hpp), in one call.
      std::array<terrain::IndexRange, 3> ranges;
      const uint32_t rangeCount =
          terrain::skirtedIndexRanges(impl.options.verticesPerSide, item.skirts, ranges);
      std::array<GLsizei, 3> counts{};
      std::array<const void*, 3> offsets{};
      for (uint32_t r = 0; r < rangeCount; ++r) {
        counts[r] = static_cast<GLsizei>(ranges[r].count);
        offsets[r] = reinterpret_cast<const void*>(uintptr_t{ranges[r].first} * impl.indexSize);
        stats.triangles += ranges[r].count / 3;
      }
      glMultiDrawElements(GL_TRIANGLES, counts.data(), impl.indexType, offsets.data(),
                          static_cast<GLsizei>(rangeCount));
      ++stats.drawCalls;
      ++stats.tilesDrawn;
    }
  }
  glBindVertexArray(0);
  // Behind everything, only where nothing was drawn (sky_pass.hpp).
  if (drawSky) impl.sky->draw(view, sky, globeRadius);
  if (useLayers) {
    for (uint32_t k = 0; k < terrain::kMaxDrapeLayers + 1; ++k) {  // and the water mask's
      glActiveTexture(GL_TEXTURE1 + k);
      glBindTexture(GL_TEXTURE_2D, 0);
      glBindSampler(1 + k, 0);
    }
    glActiveTexture(GL_TEXTURE0);
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  glUseProgram(0);

  stats.gpuBytesResident = impl.gpuBytes();
  stats.tilesResident = static_cast<uint32_t>(impl.tiles.size());
  stats.imageryTilesResident = impl.imageryTiles.tilesResident();
  stats.imageryBytesResident = impl.imageryTiles.bytesResident();
  return stats;
}

uint64_t TerrainRenderer::gpuBytesResident() const { return impl_->gpuBytes(); }
uint32_t TerrainRenderer::tilesResident() const {
  return static_cast<uint32_t>(impl_->tiles.size());
}
uint32_t TerrainRenderer::indicesPerTile() const {
  return static_cast<uint32_t>(impl_->indexCount);
}

}  // namespace globe::render
