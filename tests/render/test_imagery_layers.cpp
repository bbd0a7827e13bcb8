// Tiled imagery layers draped over terrain tiles (TerrainRenderer::uploadImageryTile and draw with
// terrain::TileDrapes): exact texel colours, uv transforms into ancestor tiles, opacity and alpha,
// layer order, seams between tiles, lighting, missing textures, texture memory and mipmaps. Flat
// synthetic terrain, so every expected pixel is known.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "render/gl_loader.hpp"
#include "render/imagery_textures.hpp"
#include "render/read_pixels.hpp"
#include "terrain/imagery_exposure.hpp"
#include "terrain/tile_mesh.hpp"
#include "tests/render/render_test_support.hpp"

namespace globe::render::test {
namespace {

using Rgba = std::array<uint8_t, 4>;
constexpr int kImagerySize = 256;
constexpr double kGroundMeters = 100.0;  // flat land everywhere

// Level 6 tiles (2.8125° square) just north of the equator, east of Greenwich.
constexpr geo::TileId kTile{6, 64, 28};
constexpr geo::TileId kEastNeighbour{6, 65, 28};
constexpr geo::TileId kSouthNeighbour{6, 64, 29};

constexpr Rgba kRed{200, 30, 40, 255};
constexpr Rgba kGreen{20, 180, 60, 255};
constexpr Rgba kBlue{30, 50, 210, 255};
constexpr Rgba kYellow{230, 210, 20, 255};
constexpr Rgba kWhite{250, 250, 250, 255};

std::vector<uint8_t> makeImage(const std::function<Rgba(int column, int row)>& texel,
                               int size = kImagerySize) {
  std::vector<uint8_t> rgba;
  rgba.reserve(static_cast<size_t>(size) * static_cast<size_t>(size) * 4);
  for (int row = 0; row < size; ++row) {
    for (int column = 0; column < size; ++column) {
      const Rgba c = texel(column, row);
      rgba.insert(rgba.end(), c.begin(), c.end());
    }
  }
  return rgba;
}

std::vector<uint8_t> solidImage(Rgba colour) {
  return makeImage([&](int, int) { return colour; });
}

// NW red, NE green, SW blue, SE yellow, a white 64² square in the middle.
std::vector<uint8_t> quadrantImage() {
  return makeImage([](int column, int row) {
    if (std::abs(column - 128) < 32 && std::abs(row - 128) < 32) return kWhite;
    if (row < 128) return column < 128 ? kRed : kGreen;
    return column < 128 ? kBlue : kYellow;
  });
}

// A distinct colour for each cell of a 4×4 grid.
Rgba cellColour(int cellColumn, int cellRow) {
  return {static_cast<uint8_t>(20 + 60 * cellColumn), static_cast<uint8_t>(20 + 60 * cellRow),
          static_cast<uint8_t>(230 - 30 * (cellColumn + cellRow)), 255};
}
std::vector<uint8_t> cellImage() {
  return makeImage([](int column, int row) { return cellColour(column / 64, row / 64); });
}

terrain::TileDrapes drapesOf(std::initializer_list<terrain::TileDrape> layers) {
  terrain::TileDrapes drapes;
  for (const terrain::TileDrape& layer : layers) drapes.layers[drapes.count++] = layer;
  return drapes;
}

::testing::AssertionResult near(const std::array<uint8_t, 4>& actual, const Rgba& expected,
                                int tolerance) {
  for (size_t c = 0; c < 3; ++c) {
    if (std::abs(int(actual[c]) - int(expected[c])) > tolerance) {
      return ::testing::AssertionFailure()
             << "got (" << int(actual[0]) << ", " << int(actual[1]) << ", " << int(actual[2])
             << "), expected (" << int(expected[0]) << ", " << int(expected[1]) << ", "
             << int(expected[2]) << ") ± " << tolerance;
    }
  }
  return ::testing::AssertionSuccess();
}

class ImageryLayers : public RenderTest {
 protected:
  void uploadFlat(const geo::TileId& tile) {
    terrain::HeightBlock block;
    block.verticesPerSide = 17;
    block.heights.assign(17 * 17, static_cast<int16_t>(kGroundMeters));
    const double skirt = terrain::recommendedSkirtDepthMeters(tile.level, 17, kWgs84);
    const auto uploaded =
        renderer_->uploadTile(tile, terrain::buildTileMesh(tile, block, kWgs84, skirt));
    ASSERT_TRUE(uploaded.ok()) << uploaded.error();
  }

  void uploadImagery(uint32_t layer, const geo::TileId& tile, const std::vector<uint8_t>& rgba) {
    const auto uploaded =
        renderer_->uploadImageryTile(layer, tile, rgba, kImagerySize, kImagerySize);
    ASSERT_TRUE(uploaded.ok()) << uploaded.error();
  }

  // Straight down onto the middle of `tile` from `altitudeMeters`, sun from `sun` (ECEF).
  static terrain::RenderView viewOnto(const geo::TileId& tile, double altitudeMeters,
                                      glm::dvec3 sun = glm::dvec3(0.0)) {
    const geo::Cartographic centre = geo::GeographicTilingScheme::tileRectangle(tile).center();
    if (sun == glm::dvec3(0.0)) sun = geo::geodeticSurfaceNormal(kWgs84, centre);
    return lookDownView(geo::radiansToDegrees(centre.longitudeRadians),
                        geo::radiansToDegrees(centre.latitudeRadians), altitudeMeters, 45.0, kWidth,
                        kHeight, sun);
  }

  // The pixel showing tile-local (u, v) of `tile` on the flat ground.
  static glm::ivec2 pixelAt(const terrain::RenderView& view, const geo::TileId& tile, double u,
                            double v) {
    const geo::GlobeRectangle rect = geo::GeographicTilingScheme::tileRectangle(tile);
    const geo::Cartographic point{rect.westRadians + u * rect.widthRadians(),
                                  rect.northRadians - v * rect.heightRadians(), kGroundMeters};
    const auto pixel = projectToPixel(view, geo::cartographicToEcef(kWgs84, point));
    EXPECT_TRUE(pixel.has_value());
    return pixel ? glm::ivec2(std::floor(pixel->x), std::floor(pixel->y)) : glm::ivec2(0);
  }

  // Heights rising 150 m per sample interval eastwards, or westwards.
  void uploadRamp(const geo::TileId& tile, bool westwards = false) {
    terrain::HeightBlock block;
    block.verticesPerSide = 17;
    block.heights.resize(17 * 17);
    for (uint32_t i = 0; i < 17 * 17; ++i) {
      const uint32_t step = westwards ? 16 - i % 17 : i % 17;
      block.heights[i] = static_cast<int16_t>(kGroundMeters + 150.0 * step);
    }
    const double skirt = terrain::recommendedSkirtDepthMeters(tile.level, 17, kWgs84);
    ASSERT_TRUE(
        renderer_->uploadTile(tile, terrain::buildTileMesh(tile, block, kWgs84, skirt)).ok());
  }
  // Straight down on `tile` with the Sun 60° from the zenith in the east, and its middle pixel.
  struct SunView {
    terrain::RenderView view;
    glm::ivec2 middle;
  };
  static SunView easternSunView(const geo::TileId& tile, double altitudeMeters) {
    const geo::Cartographic centre = geo::GeographicTilingScheme::tileRectangle(tile).center();
    const LocalFrame frame = localFrame(geo::radiansToDegrees(centre.longitudeRadians),
                                        geo::radiansToDegrees(centre.latitudeRadians));
    const glm::dvec3 sun = glm::normalize(0.5 * frame.up + std::sqrt(0.75) * frame.east);
    const terrain::RenderView view = viewOnto(tile, altitudeMeters, sun);
    return {view, pixelAt(view, tile, 0.5, 0.5)};
  }
  Image drawDraped(const terrain::RenderView& view, const std::vector<geo::TileId>& tiles,
                   const std::vector<terrain::TileDrapes>& drapes, FrameStats* stats = nullptr) {
    const FrameStats frame = renderer_->draw(view, tiles, drapes);
    if (stats != nullptr) *stats = frame;
    return readImage(view.widthPixels, view.heightPixels);
  }
};

TEST_F(ImageryLayers, NadirViewShowsTheTexelColoursExactly) {
  uploadFlat(kTile);
  uploadImagery(0, kTile, quadrantImage());
  const terrain::RenderView view = viewOnto(kTile, 450e3);
  FrameStats stats;
  const Image image = drawDraped(view, {kTile}, {drapesOf({{0, kTile}})}, &stats);
  savePng(image, "imagery_layers_quadrants");
  EXPECT_EQ(stats.tilesDrawn, 1u);
  EXPECT_EQ(stats.drapesDrawn, 1u);
  EXPECT_EQ(stats.drapesMissing, 0u);
  EXPECT_EQ(stats.imageryTilesResident, 1u);

  auto at = [&](double u, double v) {
    const glm::ivec2 p = pixelAt(view, kTile, u, v);
    return image.at(p.x, p.y);
  };
  EXPECT_TRUE(near(at(0.5, 0.5), kWhite, 2));
  EXPECT_TRUE(near(at(0.2, 0.2), kRed, 2));
  EXPECT_TRUE(near(at(0.8, 0.2), kGreen, 2));
  EXPECT_TRUE(near(at(0.2, 0.8), kBlue, 2));
  EXPECT_TRUE(near(at(0.8, 0.8), kYellow, 2));
  EXPECT_TRUE(near(at(0.03, 0.97), kBlue, 2));  // near the corners too
  EXPECT_TRUE(near(at(0.97, 0.03), kGreen, 2));
  // Outside the tile: space.
  EXPECT_TRUE(image.isBackground(2, 2));
}

TEST_F(ImageryLayers, UvTransformShowsTheParentsQuadrant) {
  // Each child of the parent, drawn with the parent's texture, shows its quadrant's 2×2 cells.
  const geo::TileId parent = kTile.parent();
  uploadImagery(0, parent, cellImage());
  for (const geo::TileId& child : parent.children()) {
    renderer_->evictAllTiles();
    uploadFlat(child);
    const uint32_t qx = child.x - parent.x * 2, qy = child.y - parent.y * 2;
    terrain::TileDrape drape{0, parent, {0.5f * float(qx), 0.5f * float(qy), 0.5f, 0.5f}};
    const terrain::RenderView view = viewOnto(child, 450e3);
    FrameStats stats;
    const Image image = drawDraped(view, {child}, {drapesOf({drape})}, &stats);
    if (qx == 1 && qy == 1) savePng(image, "imagery_layers_parent_quadrant");
    EXPECT_EQ(stats.drapesDrawn, 1u);
    for (int j = 0; j < 2; ++j) {
      for (int i = 0; i < 2; ++i) {
        const glm::ivec2 p = pixelAt(view, child, 0.25 + 0.5 * i, 0.25 + 0.5 * j);
        EXPECT_TRUE(near(image.at(p.x, p.y), cellColour(int(qx) * 2 + i, int(qy) * 2 + j), 2))
            << "child " << qx << "," << qy << " cell " << i << "," << j;
      }
    }
  }
}

TEST_F(ImageryLayers, OpacityAlphaAndLayerOrderComposite) {
  uploadFlat(kTile);
  const terrain::RenderView view = viewOnto(kTile, 450e3);
  const std::vector<geo::TileId> tiles{kTile};
  // The terrain's own colour: no layers at all, and the layer program with zero layers, alike.
  const Image plain = drawDraped(view, tiles, {});
  const Image noLayers = drawDraped(view, tiles, {terrain::TileDrapes{}});
  EXPECT_EQ(plain.rgba, noLayers.rgba);
  const glm::ivec2 west = pixelAt(view, kTile, 0.25, 0.5), east = pixelAt(view, kTile, 0.75, 0.5);
  const Rgba base = plain.at(west.x, west.y);
  ASSERT_FALSE(plain.isBackground(west.x, west.y));

  // Opacity 0.5: halfway between the base and the texel.
  uploadImagery(0, kTile, solidImage(kRed));
  terrain::TileDrape red{0, kTile};
  red.opacity = 0.5f;
  const Image half = drawDraped(view, tiles, {drapesOf({red})});
  savePng(half, "imagery_layers_half_opacity");
  Rgba expected{};
  for (size_t c = 0; c < 3; ++c) expected[c] = uint8_t(std::lround(0.5 * base[c] + 0.5 * kRed[c]));
  EXPECT_TRUE(near(half.at(west.x, west.y), expected, 2));

  // Transparent texels (west half, with a colour that must not leak) show the terrain.
  uploadImagery(1, kTile, makeImage([](int column, int) {
                  return column < 128 ? Rgba{255, 0, 255, 0} : Rgba{30, 200, 90, 255};
                }));
  const Image alpha = drawDraped(view, tiles, {drapesOf({{1, kTile}})});
  savePng(alpha, "imagery_layers_alpha");
  EXPECT_TRUE(near(alpha.at(west.x, west.y), base, 1));
  EXPECT_TRUE(near(alpha.at(east.x, east.y), {30, 200, 90, 255}, 2));

  // Two layers: opaque red below, the half-transparent layer above wins where it is opaque.
  const Image two = drawDraped(view, tiles, {drapesOf({{0, kTile}, {1, kTile}})});
  savePng(two, "imagery_layers_two");
  EXPECT_TRUE(near(two.at(west.x, west.y), kRed, 2));
  EXPECT_TRUE(near(two.at(east.x, east.y), {30, 200, 90, 255}, 2));
  // Swapped, the opaque red covers everything.
  const Image swapped = drawDraped(view, tiles, {drapesOf({{1, kTile}, {0, kTile}})});
  EXPECT_TRUE(near(swapped.at(east.x, east.y), kRed, 2));
}

// Where the upper layer's texels that a tile samples are all opaque, the layer under it cannot
// show and is not sampled (FrameStats::drapesDrawn); where some are transparent it still is.
TEST_F(ImageryLayers, AnOpaqueLayerHidesTheLayersUnderItOnlyWhereItIsOpaque) {
  const auto children = kTile.children();  // NW, NE, SW, SE
  for (const geo::TileId& child : children) uploadFlat(child);
  uploadImagery(0, kTile, solidImage(kRed));
  uploadImagery(1, kTile, makeImage([](int column, int) {
                  // Transparent up to column 95: the east half and a margin of 16 texels around
                  // it (what filtering and the first mip levels reach) are opaque.
                  return column < 96 ? Rgba{255, 0, 255, 0} : Rgba{30, 200, 90, 255};
                }));
  const terrain::RenderView view = viewOnto(kTile, 450e3);
  const std::vector<geo::TileId> west{children[0]}, east{children[1]};
  FrameStats stats;
  const Image westImage = drawDraped(
      view, west,
      {drapesOf({{0, kTile, {0.0f, 0.0f, 0.5f, 0.5f}}, {1, kTile, {0.0f, 0.0f, 0.5f, 0.5f}}})},
      &stats);
  EXPECT_EQ(stats.drapesDrawn, 2u) << "the west half is transparent: red must show through";
  const glm::ivec2 w = pixelAt(view, children[0], 0.5, 0.5);
  EXPECT_TRUE(near(westImage.at(w.x, w.y), kRed, 2));
  const Image eastImage = drawDraped(
      view, east,
      {drapesOf({{0, kTile, {0.5f, 0.0f, 0.5f, 0.5f}}, {1, kTile, {0.5f, 0.0f, 0.5f, 0.5f}}})},
      &stats);
  EXPECT_EQ(stats.drapesDrawn, 1u) << "the east half is opaque: the red layer is not sampled";
  const glm::ivec2 e = pixelAt(view, children[1], 0.5, 0.5);
  EXPECT_TRUE(near(eastImage.at(e.x, e.y), {30, 200, 90, 255}, 2));
}

TEST_F(ImageryLayers, LayersDrawOverTheGlobalImage) {
  uploadFlat(kTile);
  const std::vector<uint8_t> global(64 * 32 * 4, 160);
  ASSERT_TRUE(renderer_->setImagery(global, 64, 32).ok());
  const terrain::RenderView view = viewOnto(kTile, 450e3);
  const Image globalOnly = drawDraped(view, {kTile}, {});
  uploadImagery(0, kTile, makeImage([](int column, int) {
                  return column < 128 ? Rgba{0, 0, 0, 0} : kBlue;
                }));
  const Image layered = drawDraped(view, {kTile}, {drapesOf({{0, kTile}})});
  const glm::ivec2 west = pixelAt(view, kTile, 0.25, 0.5), east = pixelAt(view, kTile, 0.75, 0.5);
  EXPECT_TRUE(near(layered.at(west.x, west.y), globalOnly.at(west.x, west.y), 1));
  EXPECT_TRUE(near(layered.at(east.x, east.y), kBlue, 2));
}

// A smooth gradient across two imagery tiles on two terrain tiles: the boundary column (or row)
// differs from its neighbours by no more than the gradient does, and nothing dark shows there.
void expectNoSeam(const Image& image, bool vertical, int boundary, int from, int to,
                  double stepPerPixel) {
  int checked = 0;
  for (int along = from; along <= to; ++along) {
    for (int offset = -3; offset <= 3; ++offset) {
      const int x = vertical ? boundary + offset : along, y = vertical ? along : boundary + offset;
      const Rgba here = image.at(x, y);
      const Rgba next = vertical ? image.at(x + 1, y) : image.at(x, y + 1);
      ASSERT_GT(int(here[1]), 100) << "dark pixel at " << x << "," << y;
      for (size_t c = 0; c < 3; ++c) {
        EXPECT_LE(std::abs(int(here[c]) - int(next[c])), std::ceil(stepPerPixel) + 2)
            << "at " << x << "," << y << " channel " << c;
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
}

TEST_F(ImageryLayers, AdjacentTilesShowNoSeam) {
  // Red grows by 0.5 per texel across 512 texels (two tiles) east-west, blue north-south.
  auto gradient = [](int firstColumn, int firstRow) {
    return makeImage([=](int column, int row) {
      return Rgba{static_cast<uint8_t>((firstColumn + column) / 2), 160,
                  static_cast<uint8_t>((firstRow + row) / 2), 255};
    });
  };
  for (const bool eastWest : {true, false}) {
    renderer_->evictAllTiles();
    renderer_->evictAllImageryTiles();
    const geo::TileId second = eastWest ? kEastNeighbour : kSouthNeighbour;
    uploadFlat(kTile);
    uploadFlat(second);
    uploadImagery(0, kTile, gradient(0, 0));
    uploadImagery(0, second, gradient(eastWest ? 256 : 0, eastWest ? 0 : 256));
    // Over the middle of the shared edge.
    const geo::GlobeRectangle a = geo::GeographicTilingScheme::tileRectangle(kTile);
    const double lon = eastWest ? a.eastRadians : (a.westRadians + a.eastRadians) / 2;
    const double lat = eastWest ? (a.southRadians + a.northRadians) / 2 : a.southRadians;
    for (const double altitude : {400e3, 1500e3}) {
      const terrain::RenderView view = lookDownView(
          geo::radiansToDegrees(lon), geo::radiansToDegrees(lat), altitude, 45.0, kWidth, kHeight,
          geo::geodeticSurfaceNormal(kWgs84, geo::Cartographic{lon, lat, 0.0}));
      const Image image =
          drawDraped(view, {kTile, second}, {drapesOf({{0, kTile}}), drapesOf({{0, second}})});
      savePng(image, std::string("imagery_layers_seam_") + (eastWest ? "ew_" : "ns_") +
                         std::to_string(int(altitude / 1000)) + "km");
      // Texels per pixel at the boundary, from the tile's width on screen.
      const glm::ivec2 p0 = pixelAt(view, kTile, 0.0, 0.0), p1 = pixelAt(view, kTile, 1.0, 1.0);
      const double tilePixels = eastWest ? std::abs(p1.x - p0.x) : std::abs(p1.y - p0.y);
      const double step = 0.5 * kImagerySize / std::max(tilePixels, 1.0);
      const glm::ivec2 b0 = pixelAt(view, kTile, eastWest ? 1.0 : 0.1, eastWest ? 0.1 : 1.0);
      const glm::ivec2 b1 = pixelAt(view, kTile, eastWest ? 1.0 : 0.9, eastWest ? 0.9 : 1.0);
      const int boundary = eastWest ? b0.x : b0.y;
      int from = eastWest ? std::min(b0.y, b1.y) : std::min(b0.x, b1.x);
      int to = eastWest ? std::max(b0.y, b1.y) : std::max(b0.x, b1.x);
      from = std::max(from, 0);
      to = std::min(to, (eastWest ? kHeight : kWidth) - 1);
      SCOPED_TRACE((eastWest ? "east-west, " : "north-south, ") + std::to_string(altitude) + " m");
      expectNoSeam(image, eastWest, boundary, from, to, step);
    }
  }
}

TEST_F(ImageryLayers, LightImageryDimsTheTexelsByTheTerrainLight) {
  uploadFlat(kTile);
  uploadImagery(0, kTile, solidImage(kWhite));
  const geo::Cartographic centre = geo::GeographicTilingScheme::tileRectangle(kTile).center();
  const LocalFrame frame = localFrame(geo::radiansToDegrees(centre.longitudeRadians),
                                      geo::radiansToDegrees(centre.latitudeRadians));
  // Sun 60° from the zenith: light = ambient + (1 − ambient) · cos 60°.
  const glm::dvec3 sun = glm::normalize(0.5 * frame.up + std::sqrt(0.75) * frame.east);
  const terrain::RenderView view = viewOnto(kTile, 450e3, sun);
  const glm::ivec2 middle = pixelAt(view, kTile, 0.5, 0.5);
  const std::vector<terrain::TileDrapes> drapes{drapesOf({{0, kTile}})};

  const Image unlit = drawDraped(view, {kTile}, drapes);
  EXPECT_TRUE(near(unlit.at(middle.x, middle.y), kWhite, 2));

  TerrainStyle style = renderer_->style();
  style.imageryLighting = terrain::ImageryLighting::On;
  renderer_->setStyle(style);
  const Image lit = drawDraped(view, {kTile}, drapes);
  savePng(lit, "imagery_layers_lit");
  const double light = style.ambient + (1.0 - style.ambient) * 0.5;
  const auto value = static_cast<uint8_t>(std::lround(kWhite[0] * light));
  EXPECT_TRUE(near(lit.at(middle.x, middle.y), {value, value, value, 255}, 4));
  // Hill-shading off lights with "up": the same on flat ground.
  style.hillShading = false;
  renderer_->setStyle(style);
  const Image upLit = drawDraped(view, {kTile}, drapes);
  EXPECT_TRUE(near(upLit.at(middle.x, middle.y), {value, value, value, 255}, 4));
}

// Auto lighting splits the light into level ground's (the sea light) and the relief's (land light
// over level ground's). Level ground's is applied at the gentle weight to every layer, so a flat
// tile looks the same under fine and coarse imagery: no step where the weight changes. The
// relief's goes by the layer's texel over the terrain's samples: a layer as fine as the terrain
// (256 texels over 16 sample intervals) takes the gentle floor of it, one whose texels span 4
// samples (4x4 over 16) all of it. Expected values from the same tiles drawn with --lighting on
// (light = level · relief there).
TEST_F(ImageryLayers, AutoLightingWeighsTheReliefByTheTexelOverTheSampleSpacing) {
  std::vector<uint8_t> coarse;
  for (int texel = 0; texel < 4 * 4; ++texel)
    coarse.insert(coarse.end(), kWhite.begin(), kWhite.end());
  const auto drawBoth = [&](const geo::TileId& tile, bool ramp) {
    if (ramp) {
      uploadRamp(tile);
    } else {
      uploadFlat(tile);
    }
    uploadImagery(0, tile, solidImage(kWhite));
    ASSERT_TRUE(renderer_->uploadImageryTile(1, tile, coarse, 4, 4).ok());
  };
  struct Lit {
    double on, fine, coarse;
  };
  const auto measure = [&](const geo::TileId& tile, double altitudeMeters) {
    const auto [view, middle] = easternSunView(tile, altitudeMeters);
    TerrainStyle style = renderer_->style();
    Lit lit{};
    for (const auto mode : {terrain::ImageryLighting::On, terrain::ImageryLighting::Auto}) {
      style.imageryLighting = mode;
      renderer_->setStyle(style);
      const Image fine = drawDraped(view, {tile}, {drapesOf({{0, tile}})});
      const Image coarseImage = drawDraped(view, {tile}, {drapesOf({{1, tile}})});
      const double f = fine.at(middle.x, middle.y)[0], c = coarseImage.at(middle.x, middle.y)[0];
      if (mode == terrain::ImageryLighting::On) {
        EXPECT_NEAR(f, c, 1.0) << "on: the same light whatever the texel";
        lit.on = f;
      } else {
        lit.fine = f;
        lit.coarse = c;
      }
    }
    return lit;
  };
  const double ambient = renderer_->style().ambient;
  const double white = kWhite[0];
  const double levelLight = white * (ambient + (1.0 - ambient) * 0.5);  // sun 60° from zenith
  const auto levelShare = [&](double w) { return white + w * (levelLight - white); };

  drawBoth(kTile, false);
  const Lit flat = measure(kTile, 450e3);
  EXPECT_NEAR(flat.on, levelLight, 4.0);
  EXPECT_NEAR(flat.fine, levelShare(terrain::kGentleReliefWeight), 4.0);
  EXPECT_NEAR(flat.coarse, flat.fine, 1.0) << "level ground: no step where the weight changes";

  const geo::TileId rampTile{10, 1024, 448};
  drawBoth(rampTile, true);
  const Lit ramp = measure(rampTile, 40e3);
  const double relief = ramp.on / levelLight;  // the ramp faces away from the eastern sun
  ASSERT_LT(relief, 0.9) << "the test needs a slope the light shows";
  const double level = levelShare(terrain::kGentleReliefWeight);
  EXPECT_NEAR(ramp.fine, level * (1.0 + terrain::kGentleReliefWeight * (relief - 1.0)), 4.0);
  EXPECT_NEAR(ramp.coarse, level * relief, 4.0);
}

// Imagery as photographed: lit slopes brighten towards the photo's own colour and never past
// it (its highlights are its own Sun's); shadowed ones darken. A ramp rising 150 m per sample
// interval westwards faces the eastern Sun; the same ramp mirrored faces away.
TEST_F(ImageryLayers, LightNeverPushesThePhotoPastItsOwnColours) {
  constexpr Rgba kSand{210, 180, 120, 255};
  const geo::TileId sunward{10, 1024, 448};
  const geo::TileId away{10, 1026, 448};
  for (const auto& [tile, westwards] : {std::pair{sunward, true}, std::pair{away, false}}) {
    uploadRamp(tile, westwards);
    uploadImagery(0, tile, solidImage(kSand));
  }
  uploadFlat(kTile);
  uploadImagery(0, kTile, solidImage(kSand));
  const auto middleOf = [&](const geo::TileId& tile, double altitudeMeters) {
    const auto [view, middle] = easternSunView(tile, altitudeMeters);
    return drawDraped(view, {tile}, {drapesOf({{0, tile}})}).at(middle.x, middle.y);
  };
  TerrainStyle style = renderer_->style();
  for (const auto mode : {terrain::ImageryLighting::On, terrain::ImageryLighting::Auto}) {
    style.imageryLighting = mode;
    renderer_->setStyle(style);
    const Rgba lit = middleOf(sunward, 40e3), shaded = middleOf(away, 40e3),
               level = middleOf(kTile, 450e3);
    SCOPED_TRACE(std::string(terrain::toString(mode)));
    for (size_t c = 0; c < 3; ++c) {
      EXPECT_LE(lit[c], kSand[c] + 1) << "channel " << c << ": past the photo's colour";
      EXPECT_GT(lit[c], level[c] + 2) << "channel " << c << ": the lit slope must show";
      EXPECT_LT(shaded[c], level[c] - 2) << "channel " << c << ": the shaded slope must show";
    }
  }
}

// A dark photo's exposure lifts it by 1 − (1 − c)^k (terrain/imagery_exposure.hpp), unlit; a
// night-lights layer adds nothing by day and shines on the night side, covering nothing.
TEST_F(ImageryLayers, ExposureLiftsDarkPhotosAndNightLightsShineOnlyAtNight) {
  constexpr Rgba kDark{40, 60, 30, 255};
  constexpr Rgba kLights{240, 200, 120, 255};
  uploadFlat(kTile);
  uploadImagery(0, kTile, solidImage(kDark));
  uploadImagery(1, kTile, solidImage(kLights));
  terrain::RenderView view = viewOnto(kTile, 450e3);
  const glm::ivec2 middle = pixelAt(view, kTile, 0.5, 0.5);
  terrain::TileDrape photo{0, kTile};
  photo.exposure = 2.0f;
  const Rgba exposed = drawDraped(view, {kTile}, {drapesOf({photo})}).at(middle.x, middle.y);
  for (size_t c = 0; c < 3; ++c) {
    const double expected = 255.0 * terrain::exposedValue(kDark[c] / 255.0, 2.0);
    EXPECT_NEAR(exposed[c], expected, 2.0) << "channel " << c;
  }
  terrain::TileDrape lights{1, kTile};
  lights.night = true;
  const Rgba byDay = drawDraped(view, {kTile}, {drapesOf({photo, lights})}).at(middle.x, middle.y);
  EXPECT_TRUE(near(byDay, exposed, 1)) << "night lights by day";
  // The real Sun straight below the tile: deep night there.
  const geo::Cartographic centre = geo::GeographicTilingScheme::tileRectangle(kTile).center();
  view.sunDirectionEcef = -geo::geodeticSurfaceNormal(kWgs84, centre);
  view.sunIsReal = true;
  const Rgba dark = drawDraped(view, {kTile}, {drapesOf({photo})}).at(middle.x, middle.y);
  const Rgba lit = drawDraped(view, {kTile}, {drapesOf({photo, lights})}).at(middle.x, middle.y);
  for (size_t c = 0; c < 3; ++c) {
    EXPECT_LT(dark[c], exposed[c] / 2) << "channel " << c << ": the night side is dark";
    EXPECT_GT(lit[c], dark[c] + 0.8 * kLights[c] - 0.8 * dark[c]) << "channel " << c;
    EXPECT_LE(lit[c], dark[c] + kLights[c] + 1) << "channel " << c;
  }
}

TEST_F(ImageryLayers, MissingTexturesAreSkippedAndCounted) {
  uploadFlat(kTile);
  uploadFlat(kEastNeighbour);
  const terrain::RenderView view = viewOnto(kTile, 900e3);
  const std::vector<geo::TileId> tiles{kTile, kEastNeighbour};
  const Image plain = drawDraped(view, tiles, {});

  FrameStats stats;
  const Image missing = drawDraped(
      view, tiles, {drapesOf({{0, kTile}}), drapesOf({{3, kEastNeighbour}, {0, kTile}})}, &stats);
  EXPECT_EQ(stats.drapesMissing, 3u);
  EXPECT_EQ(stats.drapesDrawn, 0u);
  EXPECT_EQ(missing.rgba, plain.rgba);

  // A missing bottom layer does not hide the one above.
  uploadImagery(0, kTile, solidImage(kBlue));
  const Image partly = drawDraped(
      view, tiles, {drapesOf({{2, kTile}, {0, kTile}}), drapesOf({{0, kEastNeighbour}})}, &stats);
  EXPECT_EQ(stats.drapesMissing, 2u);
  EXPECT_EQ(stats.drapesDrawn, 1u);
  const glm::ivec2 p = pixelAt(view, kTile, 0.5, 0.5), q = pixelAt(view, kEastNeighbour, 0.5, 0.5);
  EXPECT_TRUE(near(partly.at(p.x, p.y), kBlue, 2));
  EXPECT_EQ(partly.at(q.x, q.y), plain.at(q.x, q.y));
}

TEST_F(ImageryLayers, TextureMemoryCountsTheMipChain) {
  const uint64_t perTile = uint64_t{kImagerySize} * kImagerySize * 4 * 4 / 3;
  EXPECT_EQ(mipmappedTextureBytes(kImagerySize, kImagerySize), perTile);
  const uint64_t gpuBefore = renderer_->gpuBytesResident();
  const auto image = solidImage(kRed);
  uploadImagery(0, kTile, image);
  uploadImagery(1, kTile, image);  // another layer: another texture
  uploadImagery(0, kEastNeighbour, image);
  EXPECT_EQ(renderer_->imageryTilesResident(), 3u);
  EXPECT_EQ(renderer_->imageryBytesResident(), 3 * perTile);
  EXPECT_EQ(renderer_->gpuBytesResident(), gpuBefore + 3 * perTile);
  EXPECT_TRUE(renderer_->hasImageryTile(1, kTile));
  EXPECT_FALSE(renderer_->hasImageryTile(2, kTile));

  uploadImagery(0, kTile, solidImage(kBlue));  // replaced, not added
  EXPECT_EQ(renderer_->imageryBytesResident(), 3 * perTile);
  const auto small = makeImage([](int, int) { return kGreen; }, 64);
  ASSERT_TRUE(renderer_->uploadImageryTile(0, kTile, small, 64, 64).ok());  // resized
  EXPECT_EQ(renderer_->imageryBytesResident(), 2 * perTile + 64 * 64 * 4 * 4 / 3);

  EXPECT_TRUE(renderer_->evictImageryTile(0, kTile));
  EXPECT_FALSE(renderer_->evictImageryTile(0, kTile));
  EXPECT_FALSE(renderer_->hasImageryTile(0, kTile));
  EXPECT_EQ(renderer_->imageryBytesResident(), 2 * perTile);
  EXPECT_EQ(renderer_->imageryTilesResident(), 2u);

  // Bad input is refused with a message and leaves nothing behind.
  const auto wrongSize = renderer_->uploadImageryTile(0, kSouthNeighbour, image, 128, 128);
  ASSERT_FALSE(wrongSize.ok());
  EXPECT_NE(wrongSize.error().find("6/64/29"), std::string::npos) << wrongSize.error();
  EXPECT_FALSE(renderer_->hasImageryTile(0, kSouthNeighbour));
  EXPECT_FALSE(renderer_->uploadImageryTile(0, kSouthNeighbour, {}, 0, 0).ok());

  renderer_->evictAllImageryTiles();
  EXPECT_EQ(renderer_->imageryBytesResident(), 0u);
  EXPECT_EQ(renderer_->gpuBytesResident(), gpuBefore);
}

TEST_F(ImageryLayers, FarViewsSampleTheMipChain) {
  // A one-texel black/white checker seen from far away: mipmaps average it to grey, level 0
  // alone would alias to black and white. Without anisotropic filtering, which on llvmpipe
  // averages even without mipmaps.
  TerrainRendererOptions options;
  options.maxImageryAnisotropy = 1.0f;
  renderer_.reset();
  auto created = TerrainRenderer::create(options);
  ASSERT_TRUE(created.ok()) << created.error();
  renderer_ = std::move(*created);
  uploadFlat(kTile);
  uploadImagery(0, kTile, makeImage([](int column, int row) {
                  return (column + row) % 2 == 0 ? Rgba{0, 0, 0, 255} : Rgba{255, 255, 255, 255};
                }));
  const terrain::RenderView view = viewOnto(kTile, 6000e3);
  const Image image = drawDraped(view, {kTile}, {drapesOf({{0, kTile}})});
  savePng(image, "imagery_layers_far_checker");
  const glm::ivec2 p0 = pixelAt(view, kTile, 0.1, 0.1), p1 = pixelAt(view, kTile, 0.9, 0.9);
  ASSERT_GT(p1.x - p0.x, 4);
  int pixels = 0;
  for (int y = p0.y; y <= p1.y; ++y) {
    for (int x = p0.x; x <= p1.x; ++x) {
      EXPECT_TRUE(near(image.at(x, y), {128, 128, 128, 255}, 24)) << x << "," << y;
      ++pixels;
    }
  }
  EXPECT_GT(pixels, 20);
}

// Speed, printed and not asserted: 300 flat level-6 tiles at 1280×720 looking towards the horizon,
// plain and with 1 and 4 opaque layers, with anisotropic filtering (the default) and without.

}  // namespace
}  // namespace globe::render::test
