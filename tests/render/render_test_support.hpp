// Shared helpers for the render tests: the bundled real data tiled once per process, tile loading,
// camera set-ups, pixel projection and image statistics, PNG output next to the test binary.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "geo/ellipsoid.hpp"
#include "geo/tile_id.hpp"
#include "render/osmesa_context.hpp"
#include "render/terrain_renderer.hpp"
#include "streaming/tile_store.hpp"
#include "terrain/height_block.hpp"
#include "terrain/render_view.hpp"

namespace globe::render::test {

inline const geo::Ellipsoid kWgs84 = geo::Ellipsoid::wgs84();

// ETOPO20 + W002N52 + E138N35_FUJI from data/dem, tiled with the real tiler into a temporary
// directory on first use (removed when the process exits). nullptr (and a test failure) on error.
streaming::TileStore* bundledStore();

struct LoadedTile {
  geo::TileId id;
  terrain::HeightBlock block;
};
// The pyramid's tiles of `level` whose rectangles intersect the degree rectangle.
std::vector<LoadedTile> loadTiles(uint32_t level, double westDegrees, double southDegrees,
                                  double eastDegrees, double northDegrees);
std::vector<geo::TileId> idsOf(const std::vector<LoadedTile>& tiles);

// Image read back from the framebuffer: rows top-down, RGBA8.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgba;
  std::array<uint8_t, 4> at(int x, int y) const;
  bool isBackground(int x, int y) const;  // exactly black: nothing was drawn there
  double luminance(int x, int y) const;   // 0..255, Rec. 709 weights
  // Mean over the (2r+1)² window around (x, y), clipped to the image.
  std::array<double, 3> meanRgb(int x, int y, int r) const;
  int countNonBackground() const;
};

// Mean absolute difference of two same-sized images over all RGBA bytes (0..255).
double meanAbsoluteDifference(const Image& a, const Image& b);

// Each component rounded to the nearest float, as a renderer holding ECEF in float would have it.
glm::dvec3 roundedToFloat(const glm::dvec3& v);

// Reads the current framebuffer and writes it as <test output dir>/<name>.png.
Image readImage(int width, int height);
void savePng(const Image& image, const std::string& name);
std::filesystem::path outputDirectory();

// Pixel (top-down) where an ECEF point lands; nullopt behind the camera.
std::optional<glm::dvec2> projectToPixel(const terrain::RenderView& view,
                                         const glm::dvec3& ecefMeters);

// Whether the ray through the continuous pixel position (x, y) (pixel centres at k + 0.5, y
// top-down) hits the ellipsoid with both semi-axes grown by heightMeters.
bool rayHitsEllipsoid(const terrain::RenderView& view, double x, double y, double heightMeters);

// Camera `altitudeMeters` above (lon, lat) at height 0, looking straight down with north up.
terrain::RenderView lookDownView(double longitudeDegrees, double latitudeDegrees,
                                 double altitudeMeters, double fovYDegrees, int width, int height,
                                 const glm::dvec3& sunDirectionEcef);

// Unit vectors of the local east/north/up frame at (lon, lat).
struct LocalFrame {
  glm::dvec3 east, north, up;
};
LocalFrame localFrame(double longitudeDegrees, double latitudeDegrees);

// A 320×240 OSMesa context and a renderer with the real shaders, made in SetUp.
class RenderTest : public ::testing::Test {
 protected:
  static constexpr int kWidth = 320;
  static constexpr int kHeight = 240;
  void SetUp() override;
  void TearDown() override;
  // Builds meshes with recommendedSkirtDepthMeters and uploads them.
  void upload(const std::vector<LoadedTile>& tiles);
  Image drawAndRead(const terrain::RenderView& view, const std::vector<geo::TileId>& tiles,
                    FrameStats* stats = nullptr);

  std::unique_ptr<OsMesaContext> context_;
  std::unique_ptr<TerrainRenderer> renderer_;
};

}  // namespace globe::render::test
