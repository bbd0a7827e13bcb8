// Real Cesium terrain tiles (tests/data/interop, SOURCES.md there) decoded and checked: every tile
// of two ctb-made sets, their edge lists on their edges and their normals unit length; a
// producer's Web-Mercator header and swapped edge lists refused by name; heightmap-1.0 tiles raw
// and gzip; layer.json's availability; and truncated or flipped bytes never crash a decode.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <vector>

#include "compression/gzip_bytes.hpp"
#include "formats/quantized_mesh.hpp"
#include "formats/terrain_layer_json.hpp"
#include "tests/support/build_paths.hpp"

namespace {

namespace fs = std::filesystem;
using namespace globe::formats;

const fs::path kInterop = fs::path(GLOBE_SOURCE_DIR) / "tests/data/interop";

std::vector<std::byte> readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<char> chars{std::istreambuf_iterator<char>(in), {}};
  std::vector<std::byte> bytes(chars.size());
  std::memcpy(bytes.data(), chars.data(), chars.size());
  return bytes;
}

std::string readText(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), {}};
}

std::vector<fs::path> tilesOf(const fs::path& dir) {
  std::vector<fs::path> tiles;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().extension() == ".terrain") tiles.push_back(e.path());
  std::sort(tiles.begin(), tiles.end());
  return tiles;
}

TEST(QuantizedMesh, EveryTileOfTheHagueAndTexelDecodesWithItsEdgesOnItsEdges) {
  size_t tiles = 0, withNormals = 0;
  for (const char* set : {"denhaag-ahn-octnormals", "texel-ahn4"}) {
    for (const fs::path& path : tilesOf(kInterop / "quantized-mesh" / set)) {
      SCOPED_TRACE(path.string());
      auto mesh = decodeQuantizedMesh(readBytes(path), path.string());
      ASSERT_TRUE(mesh) << mesh.error();
      ++tiles;
      ASSERT_GE(mesh->vertexCount(), 3u);
      ASSERT_GE(mesh->triangleCount(), 1u);
      for (double h : mesh->heightMeters) {
        EXPECT_GE(h, mesh->minimumHeightMeters - 1e-3);
        EXPECT_LE(h, mesh->maximumHeightMeters + 1e-3);
      }
      // Every corner of the tile is a vertex, and each edge list reaches both its corners.
      for (const auto* edge :
           {&mesh->westEdge, &mesh->southEdge, &mesh->eastEdge, &mesh->northEdge}) {
        EXPECT_GE(edge->size(), 2u);
      }
      if (std::string(set) == "denhaag-ahn-octnormals") {
        ASSERT_EQ(mesh->normals.size(), mesh->vertexCount());
        ++withNormals;
        for (const auto& n : mesh->normals) {
          EXPECT_NEAR(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), 1.0, 1e-5);
        }
      } else {
        EXPECT_TRUE(mesh->normals.empty());
      }
    }
  }
  EXPECT_EQ(tiles, 235u + 254u);
  EXPECT_EQ(withNormals, 235u);
}

TEST(QuantizedMesh, TheHaguesNormalsPointUpAtTheHague) {
  // ECEF up at 4.33 E, 52.06 N. The TIN keeps its vertices where the ground bends (dune and canal
  // slopes), but most of the ground is flat: half the normals lie within 5 degrees of up.
  const double lon = 4.33 * M_PI / 180, lat = 52.06 * M_PI / 180;
  const double up[3] = {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon),
                        std::sin(lat)};
  const fs::path dir = kInterop / "quantized-mesh/denhaag-ahn-octnormals/15";
  std::vector<double> angles;
  for (const fs::path& path : tilesOf(dir)) {
    auto mesh = decodeQuantizedMesh(readBytes(path), path.string());
    ASSERT_TRUE(mesh) << mesh.error();
    for (const auto& n : mesh->normals) {
      const double cosine = n[0] * up[0] + n[1] * up[1] + n[2] * up[2];
      angles.push_back(std::acos(std::clamp(cosine, -1.0, 1.0)) * 180 / M_PI);
    }
  }
  ASSERT_GT(angles.size(), 20000u);
  std::nth_element(angles.begin(), angles.begin() + angles.size() / 2, angles.end());
  EXPECT_LT(angles[angles.size() / 2], 5.0);
}

// The Hague's tile with its normals' extension length rewritten big-endian, as tiles of the legacy
// "vertexnormals" extension write it: the same normals either way it is declared.
TEST(QuantizedMesh, LegacyVertexNormalsWithBigEndianLengthsDecode) {
  const fs::path tile = tilesOf(kInterop / "quantized-mesh/denhaag-ahn-octnormals").front();
  auto bytes = readBytes(tile);
  auto inflated = globe::compression::gunzipIfNeeded(bytes, tile.string(), 64 << 20);
  ASSERT_TRUE(inflated) << inflated.error();
  auto reference = decodeQuantizedMesh(*inflated, "t.terrain");
  ASSERT_TRUE(reference) << reference.error();
  const size_t normalsBytes = 2 * reference->vertexCount();
  ASSERT_EQ(reference->normals.size(), reference->vertexCount());
  // Find the extension header: id 1 followed by the little-endian length of 2 bytes per vertex.
  std::vector<std::byte> legacy = *inflated;
  size_t at = legacy.size();
  for (size_t k = 88; k + 5 + normalsBytes <= legacy.size(); ++k) {
    uint32_t length = 0;
    std::memcpy(&length, legacy.data() + k + 1, 4);
    if (legacy[k] == std::byte{1} && length == normalsBytes &&
        k + 5 + normalsBytes <= legacy.size()) {
      at = k;
    }
  }
  ASSERT_LT(at, legacy.size()) << "no normals extension found";
  std::reverse(legacy.begin() + static_cast<std::ptrdiff_t>(at + 1),
               legacy.begin() + static_cast<std::ptrdiff_t>(at + 5));
  for (ExtensionLengths declared : {ExtensionLengths::BigEndian, ExtensionLengths::LittleEndian}) {
    auto mesh = decodeQuantizedMesh(legacy, "legacy.terrain", declared);
    ASSERT_TRUE(mesh) << mesh.error();
    ASSERT_EQ(mesh->normals.size(), reference->normals.size());
    EXPECT_EQ(mesh->normals, reference->normals);
  }
  // A little-endian tile read where big-endian lengths are declared: the declared order does not
  // fit, the file's does.
  auto swappedDeclared = decodeQuantizedMesh(*inflated, "t.terrain", ExtensionLengths::BigEndian);
  ASSERT_TRUE(swappedDeclared) << swappedDeclared.error();
  EXPECT_EQ(swappedDeclared->normals, reference->normals);
}

TEST(QuantizedMesh, ACentreOverAnotherTileIsTold) {
  const fs::path path = kInterop / "quantized-mesh/texel-ahn4/12/4203/3255.terrain";
  auto mesh = decodeQuantizedMesh(readBytes(path), "t.terrain");
  ASSERT_TRUE(mesh) << mesh.error();
  // TMS 12/4203/3255: west -180 + 4203 * 180/4096, south -90 + 3255 * 180/4096.
  const double size = 180.0 / 4096, west = -180 + 4203 * size, south = -90 + 3255 * size;
  EXPECT_TRUE(centreLiesOverTile(*mesh, west, south, west + size, south + size));
  EXPECT_FALSE(centreLiesOverTile(*mesh, west + 3 * size, south, west + 4 * size, south + size));
  EXPECT_FALSE(centreLiesOverTile(*mesh, west, south - 3 * size, west + size, south - 2 * size));
}

TEST(QuantizedMesh, WebMercatorHeaderFromAHostileProducerIsRefusedByName) {
  for (const fs::path& path : tilesOf(kInterop / "quantized-mesh/craterlake-usgs-webmercator")) {
    auto mesh = decodeQuantizedMesh(readBytes(path), "cl.terrain");
    ASSERT_FALSE(mesh) << path;
    EXPECT_NE(mesh.error().find("cl.terrain: the header's centre ("), std::string::npos)
        << mesh.error();
    EXPECT_NE(mesh.error().find("is not an ECEF point on the Earth"), std::string::npos);
  }
}

TEST(QuantizedMesh, SwappedEdgeListsAreRefused) {
  // The Hague tile with its south list's first index pointed at a north vertex.
  const fs::path path = kInterop / "quantized-mesh/texel-ahn4/12/4203/3255.terrain";
  auto bytes = readBytes(path);
  auto mesh = decodeQuantizedMesh(bytes, "t.terrain");
  ASSERT_TRUE(mesh) << mesh.error();
  ASSERT_FALSE(mesh->northEdge.empty());
  ASSERT_LE(mesh->vertexCount(), 65536u);
  // Offsets: header, vertices, (aligned) triangles, then the west list and the south list.
  size_t at = 88 + 4 + 6 * mesh->vertexCount();
  at += at % 2;
  at += 4 + 2 * mesh->triangles.size();
  at += 4 + 2 * mesh->westEdge.size();
  ASSERT_FALSE(mesh->southEdge.empty());
  const auto north = static_cast<uint16_t>(mesh->northEdge.front());
  std::memcpy(bytes.data() + at + 4, &north, 2);
  auto swapped = decodeQuantizedMesh(bytes, "t.terrain");
  ASSERT_FALSE(swapped);
  EXPECT_NE(swapped.error().find("of the south edge list has v = 32767"), std::string::npos)
      << swapped.error();
}

TEST(QuantizedMesh, TruncatedAndFlippedTilesFailCleanly) {
  const auto bytes =
      readBytes(kInterop / "quantized-mesh/denhaag-ahn-octnormals/15/33556/25861.terrain");
  ASSERT_GT(bytes.size(), 200u);
  for (size_t size = 0; size < bytes.size(); size += 7) {
    auto mesh = decodeQuantizedMesh(std::span(bytes).first(size), "cut.terrain");
    // A cut between extensions can still be a whole tile; anywhere else it is refused.
    if (!mesh) {
      EXPECT_EQ(mesh.error().rfind("cut.terrain: ", 0), 0u) << mesh.error();
    }
  }
  std::mt19937 random(7);
  for (int k = 0; k < 2000; ++k) {
    auto copy = bytes;
    for (int flips = 0; flips < 4; ++flips) {
      copy[random() % copy.size()] = static_cast<std::byte>(random() & 0xff);
    }
    auto mesh = decodeQuantizedMesh(copy, "flipped.terrain");
    if (mesh) {
      for (uint32_t index : mesh->triangles) ASSERT_LT(index, mesh->vertexCount());
    }
  }
}

TEST(HeightmapTile, RawAndGzipTilesDecodeToDutchLowlands) {
  for (const char* name : {"51617.terrain", "51618.terrain", "1608.terrain"}) {
    SCOPED_TRACE(name);
    const auto stored = readBytes(kInterop / "heightmap-1.0" / name);
    EXPECT_EQ(globe::compression::isGzip(stored), std::string(name) == "1608.terrain");
    auto bytes = globe::compression::gunzipIfNeeded(stored, name, 1 << 20);
    ASSERT_TRUE(bytes) << bytes.error();
    EXPECT_EQ(bytes->size(), 8452u);
    auto tile = decodeHeightmapTile(*bytes, name);
    ASSERT_TRUE(tile) << tile.error();
    EXPECT_EQ(tile->childMask, 0b1111);
    EXPECT_EQ(tile->waterMask.size(), 1u);
    const auto [low, high] =
        std::minmax_element(tile->heightMeters.begin(), tile->heightMeters.end());
    if (std::string(name) == "1608.terrain") {
      EXPECT_NEAR(*low, 21, 1.5);
      EXPECT_NEAR(*high, 35, 1.5);
    } else {
      EXPECT_GE(*low, 1.5);
      EXPECT_LE(*high, 5.5);
    }
  }
  auto damaged = readBytes(kInterop / "heightmap-1.0/1608.terrain");
  damaged[damaged.size() / 2] ^= std::byte{0x5a};
  damaged[damaged.size() / 2 + 1] ^= std::byte{0xa5};
  auto inflated = globe::compression::gunzipIfNeeded(damaged, "1608.terrain", 1 << 20);
  EXPECT_FALSE(inflated);
  auto small = globe::compression::gunzipIfNeeded(readBytes(kInterop / "heightmap-1.0/1608.terrain"), "b", 1000);
  ASSERT_FALSE(small);
  EXPECT_EQ(small.error(), "b: inflates to more than 1000 bytes");
}

TEST(TerrainLayerJson, TheHaguesAvailabilityAndExtensions) {
  auto layer = parseTerrainLayerJson(
      readText(kInterop / "quantized-mesh/denhaag-ahn-octnormals/layer.json"), "layer.json");
  ASSERT_TRUE(layer) << layer.error();
  EXPECT_EQ(layer->format, TerrainLayerJson::Format::QuantizedMesh);
  EXPECT_EQ(layer->maxZoom, 15u);
  ASSERT_EQ(layer->available.size(), 16u);
  EXPECT_EQ(layer->available[15].front().startX, 33549u);
  EXPECT_EQ(layer->available[15].front().endY, 25866u);
  EXPECT_TRUE(layer->hasExtension("octvertexnormals"));
  EXPECT_EQ(layer->tiles.front(), "{z}/{x}/{y}.terrain?v={version}");
  EXPECT_EQ(layer->version, "1.1.0");
}

TEST(TerrainLayerJson, WhatThisViewerCannotUseIsRefusedByName) {
  auto mercator = parseTerrainLayerJson(
      R"({"tiles":["{z}/{x}/{y}.terrain"],"projection":"EPSG:3857"})", "m.json");
  ASSERT_FALSE(mercator);
  EXPECT_NE(mercator.error().find("m.json: projection EPSG:3857"), std::string::npos);
  auto noTiles = parseTerrainLayerJson(R"({"format":"quantized-mesh-1.0"})", "n.json");
  ASSERT_FALSE(noTiles);
  EXPECT_EQ(noTiles.error(), "n.json: no tile URL template (\"tiles\")");
  auto outside = parseTerrainLayerJson(
      R"({"tiles":["t"],"available":[[{"startX":0,"startY":0,"endX":2,"endY":0}]]})", "o.json");
  ASSERT_FALSE(outside);
  EXPECT_NE(outside.error().find("level 0 lists tiles outside the level's 2×1 grid"),
            std::string::npos)
      << outside.error();
  auto notJson = parseTerrainLayerJson("<html>", "h.json");
  ASSERT_FALSE(notJson);
  EXPECT_EQ(notJson.error().rfind("h.json: not JSON", 0), 0u);
  // Any 1.x quantized mesh, as CesiumJS reads it.
  for (const char* minor : {"quantized-mesh-1.0", "quantized-mesh-1.1"}) {
    auto layer = parseTerrainLayerJson(
        std::string(R"({"tiles":["t"],"format":")") + minor + R"("})", "q.json");
    ASSERT_TRUE(layer) << minor << ": " << layer.error();
    EXPECT_EQ(layer->format, TerrainLayerJson::Format::QuantizedMesh);
  }
  auto two = parseTerrainLayerJson(R"({"tiles":["t"],"format":"quantized-mesh-2.0"})", "2.json");
  EXPECT_FALSE(two);
  auto format = parseTerrainLayerJson(R"({"tiles":["t"],"format":"pbf"})", "f.json");
  ASSERT_FALSE(format);
  EXPECT_NE(format.error().find("format \"pbf\""), std::string::npos);
}

}  // namespace

namespace {

// A 3×3-vertex tile with every extension, as the exporter's encoder writes it.
QuantizedMesh smallTile() {
  QuantizedMesh mesh;
  mesh.centerEcefMeters = {-3'900'000, 3'400'000, 3'670'000};
  mesh.minimumHeightMeters = -12;
  mesh.maximumHeightMeters = 3776;
  for (uint16_t row = 0; row < 3; ++row) {
    for (uint16_t column = 0; column < 3; ++column) {
      mesh.u.push_back(static_cast<uint16_t>(column * 16383 + column / 2));
      mesh.v.push_back(static_cast<uint16_t>((2 - row) * 16383 + (2 - row) / 2));
      mesh.heightMeters.push_back(row * 3 + column == 4 ? 3776.0 : -12.0 + row * 100 + column);
      const float tilt = 0.1f * static_cast<float>(column) - 0.1f;
      mesh.normals.push_back({tilt, -0.2f, -std::sqrt(1 - tilt * tilt - 0.04f)});
    }
  }
  // Counter-clockwise, first uses out of order: the encoder renumbers.
  mesh.triangles = {4, 3, 7, 4, 7, 8, 0, 3, 4, 0, 4, 1, 1, 4, 5, 1, 5, 2, 3, 6, 7, 5, 8, 2};
  mesh.westEdge = {6, 3, 0};
  mesh.southEdge = {6, 7, 8};
  mesh.eastEdge = {8, 5, 2};
  mesh.northEdge = {0, 1, 2};
  mesh.waterMask.assign(256 * 256, 0);
  for (size_t row = 0; row < 256; ++row) std::fill_n(&mesh.waterMask[row * 256], 128, 255);
  mesh.metadataJson = R"({"available":[[{"startX":0,"startY":0,"endX":1,"endY":1}]]})";
  return mesh;
}

}  // namespace

TEST(QuantizedMeshEncoder, WhatItWritesDecodesToTheSameTile) {
  const QuantizedMesh made = smallTile();
  auto decoded = decodeQuantizedMesh(encodeQuantizedMesh(made, {}), "made.terrain");
  ASSERT_TRUE(decoded) << decoded.error();
  ASSERT_EQ(decoded->vertexCount(), 9u);
  ASSERT_EQ(decoded->triangleCount(), 8u);
  // Vertices renumbered: compare them by their place (u, v) and each triangle by its corners.
  const auto place = [](const QuantizedMesh& m, uint32_t k) {
    return std::pair<uint16_t, uint16_t>{m.u[k], m.v[k]};
  };
  const double step = (3776.0 + 12.0) / kQuantizedMax;
  for (uint32_t k = 0; k < 9; ++k) {
    const auto p = place(*decoded, k);
    uint32_t original = 0;
    while (original < 9 && place(made, original) != p) ++original;
    ASSERT_LT(original, 9u);
    EXPECT_NEAR(decoded->heightMeters[k], made.heightMeters[original], step);
    for (size_t c = 0; c < 3; ++c) {
      EXPECT_NEAR(decoded->normals[k][c], made.normals[original][c], 0.02) << k << " " << c;
    }
  }
  for (size_t t = 0; t < 8; ++t) {
    for (size_t c = 0; c < 3; ++c) {
      EXPECT_EQ(place(*decoded, decoded->triangles[3 * t + c]),
                place(made, made.triangles[3 * t + c]));
    }
  }
  EXPECT_EQ(decoded->waterMask, made.waterMask);
  EXPECT_EQ(decoded->metadataJson, made.metadataJson);
  EXPECT_EQ(decoded->westEdge.size(), 3u);  // the decoder checks each lies on its edge
}
