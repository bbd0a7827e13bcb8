// Draws terrain tiles: a GPU cache of tile meshes sharing one index buffer, camera-relative
// transforms made in double, logarithmic depth, hypsometric + hill-shaded (or imagery) colour.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>

#include <glm/vec3.hpp>

#include "core/result.hpp"
#include "core/warnings.hpp"
#include "geo/tile_id.hpp"
#include "render/frame_stats.hpp"
#include "terrain/relief_shading.hpp"
#include "terrain/render_view.hpp"
#include "terrain/tile_drape.hpp"
#include "terrain/tile_mesh.hpp"

namespace globe::render {

struct TerrainRendererOptions {
  std::filesystem::path
      shaderDirectory;  // holds terrain.vert/.frag; empty: defaultShaderDirectory() (embedded)
  uint32_t verticesPerSide = 17;  // every uploaded mesh must have this block size
  bool skirts = true;             // every uploaded mesh must have skirts iff this is set
  // Anisotropic filtering of imagery tiles, at most this many samples (where the GL has
  // GL_EXT/ARB_texture_filter_anisotropic; 1 = off). 0 (the default) = 8 on a GPU and off on the
  // software rasterisers (llvmpipe, softpipe), which take it on a slow path: 300 tiles at
  // 1280x720 looking at the horizon, one layer ~11 → 25-50 ms a frame, four ~16 → 70-150 ms.
  float maxImageryAnisotropy = 0.0f;
  // Said once each: no sky (its shaders did not build), draped layers this GL cannot compile.
  core::WarningSink warn;
};

struct TerrainStyle {
  bool drapeImagery = true;  // use the imagery set by setImagery (if any) instead of the ramp
  bool hillShading = true;   // light land with the mesh normals; off: with the ellipsoid "up"
  float ambient = 0.3f;      // light on faces turned away from the sun, 0..1
  // How much of the terrain's light drape layers (draw with drapes) take (terrain/relief_shading):
  // Off: none, imagery keeps its own baked-in shading and shows its texels' colours exactly; On:
  // all of it; Auto: by how much coarser the layer's texel is than the tile's samples.
  terrain::ImageryLighting imageryLighting = terrain::ImageryLighting::Off;
  glm::vec3 backgroundRgb{0.0f, 0.0f, 0.0f};  // space, where the sky is off
  // The sky behind the terrain and distance fog over it (render/sky_model.hpp, shaders/sky.*),
  // from the camera's height; off: backgroundRgb (the tests that look for gaps keep it off).
  bool sky = false;
  // Imagery magnified over a whole tile is sampled bilinearly from the base level, which is what
  // trilinear filtering does there too, but without a level of detail per fragment: on llvmpipe
  // the imagery's own cost on the Zion nadir view falls by a third
  // (docs/performance/imagery-frame-time.md). Off: always trilinear (for comparing the two).
  bool bilinearWhereMagnified = true;
};

// Needs a current GL 3.3 core context (OsMesaContext or GlfwWindowContext) on the calling thread
// for its whole life, and must be destroyed before that context.
//
// Precision: a mesh stores float offsets from a double tile centre; draw() forms the camera-
// relative transform in double (terrain/tile_transform.hpp: view · translate(eye rounded to the
// level's quantum), and the centre's exact offset from that eye) and only then casts to float,
// so the large ECEF translation cancels in double and the GPU sees camera-relative numbers: no
// jitter 1 m above the ground at earth radius, and bit-identical shared vertices between tiles.
//
// Depth: logarithmic, written per fragment: gl_FragDepth = log2(1 + w) / log2(1 + farMeters), w
// the eye distance along the view axis. With the 24-bit depth buffer OSMesa and most windows give,
// the resolvable depth step is ~1.1e-6 · (1 + w): 2 µm at 1 m, 1 mm at 1 km, 44 m at 40,000 km,
// so 5 cm to 40,000 km draws without z-fighting. Per-fragment (not per-vertex) because triangles
// next to a low camera span a wide depth range. Tiles whose nearest point is >= 1 km and >= 2
// bounding radii away get the same depth per vertex instead (a second program, early-z kept), and
// tiles are drawn front to back, near group first. Per-fragment depth costs early-z; reversed-Z
// would need a float depth buffer and glClipControl, which OSMesa's default framebuffer does not
// give.
//
// Shading (shaders/terrain.vert, per vertex): land takes a hypsometric ramp (0 m green, 300 m
// light green, 800 m tan, 1500 m brown, 2500 m grey-brown, 3500 m grey, 4500 m+ snow white) or,
// with imagery set and drapeImagery on, the image (sampled per fragment); it is lit by Lambert on
// the mesh normal, ambient + (1 − ambient)·max(n·sun, 0), which is the hill-shading. Sea (the
// vertex sea flag: water samples, terrain::isWater; land below sea level is land) is blue, darker
// with the sea floor's depth down to 6 km whether the water surface at 0 m or the floor is drawn
// (terrain::SeaSurface), and lit with the geocentric "up" instead of the normal, so water stays
// flat; the fragment picks land or sea by the interpolated flag, so coasts stay sharp.
// Drape layers (draw with drapes, shaders built with GLOBE_LAYERS): over that colour (the global
// image included, when set and drapeImagery is on), each layer bottom to top per fragment:
// colour = mix(colour, texel.rgb · mix(1, level, v) · mix(1, land / level, w), texel.a ·
// opacity), with `level` the sea light above (level ground's), land / level the relief's light (1
// over water), v = terrain::levelGroundLightWeight(imageryLighting) and w the layer's weight on
// this tile (imageryLighting: 0 Off, 1 On, Auto terrain::reliefShadingWeight of the data's own
// texel over its own sample step, TileDrape::nativeTexelDegrees and terrainStepDegrees; without
// them, of the drawn imagery tile's texel over the tile's vertex spacing; in double, once per
// tile and layer). Imagery covers sea too. Texels are stored premultiplied.
// Skirts: only on the edges whose same-level neighbour is not drawn this frame or draws the shared
// edge at other heights (terrain/skirt_edges.hpp, edge_heights.hpp). Tiles of one level with the
// same edge heights need none: their shared vertices reach the rasteriser bit-identical
// (terrain/tile_transform.hpp), so the seam is watertight.
// Back faces are culled (meshes are counter-clockwise from outside); draw() leaves depth test and
// culling enabled.
class TerrainRenderer {
 public:
  // Loads <shaderDirectory>/terrain.vert and terrain.frag and builds the shared index buffer.
  static Result<std::unique_ptr<TerrainRenderer>> create(const TerrainRendererOptions& options);
  ~TerrainRenderer();
  TerrainRenderer(const TerrainRenderer&) = delete;
  TerrainRenderer& operator=(const TerrainRenderer&) = delete;

  // Uploads (or replaces) a tile's mesh. Fails when the mesh's block size or skirts do not match
  // the options, or its vertex array is not the expected size.
  Result<void> uploadTile(const geo::TileId& tile, const terrain::TileMesh& mesh);
  // Frees a tile's GPU buffers; false when it was not resident.
  bool evictTile(const geo::TileId& tile);
  bool hasTile(const geo::TileId& tile) const;
  // Shadows: the Sun's visibility (0..1) at each grid vertex of a resident tile, row-major
  // (collision/sun_visibility.hpp), multiplying its sunlight until the tile is uploaded again.
  // Fails for a tile not resident or a count other than N².
  Result<void> setTileSunlight(const geo::TileId& tile, std::span<const float> gridVisibility);
  void evictAllTiles();

  // A global equirectangular RGBA8 image, rows top-down: column 0 at -180°, row 0 at +90°.
  // Mipmapped, wraps in longitude.
  Result<void> setImagery(std::span<const uint8_t> rgba, int widthPixels, int heightPixels);
  void clearImagery();
  bool hasImagery() const;

  // Uploads (or replaces) one imagery tile's texture: RGBA8 with straight alpha, rows top-down
  // (row 0 = the tile's north edge, v 0), usually 256x256; mipmapped (glGenerateMipmap),
  // trilinear, anisotropic where GL_EXT/ARB_texture_filter_anisotropic is available, clamped to
  // edge.
  Result<void> uploadImageryTile(uint32_t layer, const geo::TileId& tile,
                                 std::span<const uint8_t> rgba, int widthPixels, int heightPixels);
  bool hasImageryTile(uint32_t layer, const geo::TileId& tile) const;
  bool evictImageryTile(uint32_t layer, const geo::TileId& tile);  // false: was not resident
  void evictAllImageryTiles();
  uint64_t imageryBytesResident() const;  // imagery tile textures incl. mip chains (4/3)
  uint32_t imageryTilesResident() const;

  void setStyle(const TerrainStyle& style);
  const TerrainStyle& style() const;

  // Clears colour and depth and draws the listed tiles (missing ones are counted and skipped)
  // into the current framebuffer's (0, 0, width, height) viewport.
  FrameStats draw(const terrain::RenderView& view, std::span<const geo::TileId> tiles);
  // The same with drapes[i] over tiles[i] (drapes.size() == tiles.size(); empty: exactly the
  // draw above; tiles past the end of a shorter span get none). A drape layer whose texture is
  // not uploaded is skipped and counted (FrameStats::drapesMissing).
  FrameStats draw(const terrain::RenderView& view, std::span<const geo::TileId> tiles,
                  std::span<const terrain::TileDrapes> drapes);

  uint64_t gpuBytesResident() const;  // meshes, index buffer, global image and imagery tiles
  uint32_t tilesResident() const;
  uint32_t indicesPerTile() const;  // triangles per tile = indicesPerTile() / 3

 private:
  struct Impl;
  explicit TerrainRenderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace globe::render
