// Render test helpers: real pyramid, tile loading, projection, ray casting, image statistics.
#include "tests/render/render_test_support.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "formats/image_io.hpp"
#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "render/read_pixels.hpp"
#include "terrain/tile_mesh.hpp"
#include "tests/support/build_paths.hpp"
#include "tiling/tiler.hpp"

namespace globe::render::test {
namespace {

// Tiles the bundled data into a temporary directory; removes it when the process ends.
struct TempPyramid {
  std::filesystem::path root;
  std::unique_ptr<streaming::TileStore> store;

  TempPyramid() {
    root = std::filesystem::temp_directory_path() /
           ("globe-render-test-pyramid-" + std::to_string(::getpid()));
    std::filesystem::remove_all(root);
    std::filesystem::create_directories(root);
    const std::string dem = std::string(GLOBE_SOURCE_DIR) + "/data/dem/";
    tiling::TilerOptions options;
    options.inputs = {dem + "ETOPO20.DEM", dem + "W002N52.DEM", dem + "E138N35_FUJI.DEM"};
    options.outputDir = root / "pyramid";
    auto report = tiling::runTiler(options);
    if (!report) {
      ADD_FAILURE() << report.error();
      return;
    }
    auto opened = streaming::TileStore::open(options.outputDir);
    if (!opened) {
      ADD_FAILURE() << opened.error();
      return;
    }
    store = std::move(*opened);
  }
  TempPyramid(const TempPyramid&) = delete;
  TempPyramid& operator=(const TempPyramid&) = delete;
  ~TempPyramid() {
    store.reset();
    std::error_code ignored;
    std::filesystem::remove_all(root, ignored);
  }
};

TempPyramid& tempPyramid() {
  static TempPyramid pyramid;
  return pyramid;
}

}  // namespace

streaming::TileStore* bundledStore() { return tempPyramid().store.get(); }

std::vector<LoadedTile> loadTiles(uint32_t level, double westDegrees, double southDegrees,
                                  double eastDegrees, double northDegrees) {
  std::vector<LoadedTile> tiles;
  streaming::TileStore* store = bundledStore();
  if (store == nullptr) return tiles;
  using Scheme = geo::GeographicTilingScheme;
  const auto nw = Scheme::positionToTile(geo::degreesToRadians(westDegrees),
                                         geo::degreesToRadians(northDegrees), level);
  const auto se = Scheme::positionToTile(geo::degreesToRadians(eastDegrees),
                                         geo::degreesToRadians(southDegrees), level);
  if (!nw || !se) return tiles;
  for (uint32_t y = nw->y; y <= se->y; ++y) {
    for (uint32_t x = nw->x; x <= se->x; ++x) {
      const geo::TileId id{level, x, y};
      auto entry = store->entry(id);
      if (!entry) {
        ADD_FAILURE() << entry.error();
        continue;
      }
      if (!entry->has_value()) continue;
      auto block = store->loadBlock(id);
      if (!block) {
        ADD_FAILURE() << block.error();
        continue;
      }
      tiles.push_back({id, std::move(*block)});
    }
  }
  return tiles;
}

std::vector<geo::TileId> idsOf(const std::vector<LoadedTile>& tiles) {
  std::vector<geo::TileId> ids;
  for (const LoadedTile& tile : tiles) ids.push_back(tile.id);
  return ids;
}

std::array<uint8_t, 4> Image::at(int x, int y) const {
  const size_t offset =
      (static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 4;
  return {rgba[offset], rgba[offset + 1], rgba[offset + 2], rgba[offset + 3]};
}

bool Image::isBackground(int x, int y) const {
  const auto p = at(x, y);
  return p[0] == 0 && p[1] == 0 && p[2] == 0;
}

double Image::luminance(int x, int y) const {
  const auto p = at(x, y);
  return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

std::array<double, 3> Image::meanRgb(int x, int y, int r) const {
  std::array<double, 3> sum{0, 0, 0};
  int count = 0;
  for (int yy = std::max(0, y - r); yy <= std::min(height - 1, y + r); ++yy) {
    for (int xx = std::max(0, x - r); xx <= std::min(width - 1, x + r); ++xx) {
      const auto p = at(xx, yy);
      for (int c = 0; c < 3; ++c) sum[static_cast<size_t>(c)] += p[static_cast<size_t>(c)];
      ++count;
    }
  }
  for (double& value : sum) value /= std::max(count, 1);
  return sum;
}

int Image::countNonBackground() const {
  int count = 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) count += isBackground(x, y) ? 0 : 1;
  }
  return count;
}

double meanAbsoluteDifference(const Image& a, const Image& b) {
  EXPECT_EQ(a.rgba.size(), b.rgba.size());
  const size_t size = std::min(a.rgba.size(), b.rgba.size());
  double sum = 0;
  for (size_t k = 0; k < size; ++k) {
    sum += std::abs(static_cast<int>(a.rgba[k]) - static_cast<int>(b.rgba[k]));
  }
  return size == 0 ? 0.0 : sum / static_cast<double>(size);
}

glm::dvec3 roundedToFloat(const glm::dvec3& v) {
  // Through volatile: GCC 12 at -O2 drops the double -> float -> double round trip of the two
  // components it vectorises together, leaving them unrounded.
  glm::dvec3 rounded;
  for (int c = 0; c < 3; ++c) {
    volatile float component = static_cast<float>(v[c]);
    rounded[c] = component;
  }
  return rounded;
}

std::filesystem::path outputDirectory() {
  return std::filesystem::path(globe::build_paths::binaryDir()) / "tests/render";
}

Image readImage(int width, int height) {
  return Image{width, height, readPixelsRgba(width, height)};
}

void savePng(const Image& image, const std::string& name) {
  const auto path = outputDirectory() / (name + ".png");
  auto written = formats::writePngAtomically(path, image.rgba, image.width, image.height);
  EXPECT_TRUE(written.ok()) << written.error();
}

std::optional<glm::dvec2> projectToPixel(const terrain::RenderView& view,
                                         const glm::dvec3& ecefMeters) {
  const glm::dvec4 clip = view.projection * view.viewMatrix * glm::dvec4(ecefMeters, 1.0);
  if (clip.w <= 0.0) return std::nullopt;
  const double ndcX = clip.x / clip.w, ndcY = clip.y / clip.w;
  return glm::dvec2((ndcX * 0.5 + 0.5) * view.widthPixels,
                    (1.0 - (ndcY * 0.5 + 0.5)) * view.heightPixels);
}

bool rayHitsEllipsoid(const terrain::RenderView& view, double x, double y, double heightMeters) {
  const double ndcX = x / view.widthPixels * 2.0 - 1.0;
  const double ndcY = 1.0 - y / view.heightPixels * 2.0;
  const glm::dmat4 inverse = glm::inverse(view.projection * view.viewMatrix);
  glm::dvec4 nearPoint = inverse * glm::dvec4(ndcX, ndcY, -1.0, 1.0);
  glm::dvec4 farPoint = inverse * glm::dvec4(ndcX, ndcY, 0.0, 1.0);
  const glm::dvec3 origin = view.cameraEcefMeters;
  const glm::dvec3 direction =
      glm::normalize(glm::dvec3(farPoint) / farPoint.w - glm::dvec3(nearPoint) / nearPoint.w);
  const glm::dvec3 scale(1.0 / (kWgs84.semiMajorAxisMeters + heightMeters),
                         1.0 / (kWgs84.semiMajorAxisMeters + heightMeters),
                         1.0 / (kWgs84.semiMinorAxisMeters + heightMeters));
  const glm::dvec3 o = origin * scale, d = direction * scale;
  const double a = glm::dot(d, d), b = 2.0 * glm::dot(o, d), c = glm::dot(o, o) - 1.0;
  const double discriminant = b * b - 4.0 * a * c;
  if (discriminant < 0.0) return false;
  return (-b - std::sqrt(discriminant)) / (2.0 * a) > 0.0;
}

LocalFrame localFrame(double longitudeDegrees, double latitudeDegrees) {
  const double lon = geo::degreesToRadians(longitudeDegrees);
  const double lat = geo::degreesToRadians(latitudeDegrees);
  LocalFrame frame;
  frame.east = {-std::sin(lon), std::cos(lon), 0.0};
  frame.up = geo::geodeticSurfaceNormal(
      kWgs84, geo::Cartographic::fromDegrees(longitudeDegrees, latitudeDegrees, 0.0));
  frame.north = glm::normalize(glm::cross(frame.up, frame.east));
  (void)lat;
  return frame;
}

terrain::RenderView lookDownView(double longitudeDegrees, double latitudeDegrees,
                                 double altitudeMeters, double fovYDegrees, int width, int height,
                                 const glm::dvec3& sunDirectionEcef) {
  const glm::dvec3 ground = geo::cartographicToEcef(
      kWgs84, geo::Cartographic::fromDegrees(longitudeDegrees, latitudeDegrees, 0.0));
  const LocalFrame frame = localFrame(longitudeDegrees, latitudeDegrees);
  return terrain::makeLookAtView(ground + altitudeMeters * frame.up, ground, frame.north,
                                 geo::degreesToRadians(fovYDegrees), width, height,
                                 sunDirectionEcef);
}

void RenderTest::SetUp() {
  auto context = OsMesaContext::create(kWidth, kHeight);
  ASSERT_TRUE(context.ok()) << context.error();
  context_ = std::move(*context);
  auto renderer = TerrainRenderer::create({});
  ASSERT_TRUE(renderer.ok()) << renderer.error();
  renderer_ = std::move(*renderer);
}

void RenderTest::TearDown() {
  renderer_.reset();  // GL objects go before their context
  context_.reset();
}

void RenderTest::upload(const std::vector<LoadedTile>& tiles) {
  for (const LoadedTile& tile : tiles) {
    const double skirt =
        terrain::recommendedSkirtDepthMeters(tile.id.level, tile.block.verticesPerSide, kWgs84);
    const terrain::TileMesh mesh = terrain::buildTileMesh(tile.id, tile.block, kWgs84, skirt);
    auto uploaded = renderer_->uploadTile(tile.id, mesh);
    ASSERT_TRUE(uploaded.ok()) << uploaded.error();
  }
}

Image RenderTest::drawAndRead(const terrain::RenderView& view,
                              const std::vector<geo::TileId>& tiles, FrameStats* stats) {
  const FrameStats frame = renderer_->draw(view, tiles);
  if (stats != nullptr) *stats = frame;
  return readImage(view.widthPixels, view.heightPixels);
}

}  // namespace globe::render::test
