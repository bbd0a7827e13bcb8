// 3D Tiles 1.1 implicit tiling expanded into explicit tiles: CesiumGS's sparse quadtree and
// octree samples (their content files counted independently), regions subdivided, bounds, and
// hostile subtree files.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <set>
#include <tuple>

#include "tests/support/tiler_test_fixture.hpp"
#include "tests/tiles3d/box_tileset.hpp"
#include "tiles3d/implicit_tiling.hpp"
#include "tiles3d/tileset.hpp"
#include "tiles3d/tileset_surface.hpp"
#include "transport/atomic_file.hpp"

namespace globe::tiles3d {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using testing::eastNorthUp;
using testing::transformJson;
using testing::writeFile;

const fs::path kImplicitSamples = fs::path(GLOBE_SOURCE_DIR) / "tests/data/interop/3dtiles";

ReadRelativeFile readUnder(const fs::path& dir) {
  return [dir](const std::string& uri) -> Result<std::optional<std::vector<std::byte>>> {
    const fs::path file = dir / uri;
    if (!fs::exists(file)) return std::optional<std::vector<std::byte>>{};
    auto bytes = transport::readWholeFile(file, 1u << 24);
    if (!bytes) return Error{bytes.error()};
    return std::optional<std::vector<std::byte>>(std::move(*bytes));
  };
}

Json rootOf(const fs::path& dir) {
  auto bytes = transport::readWholeFile(dir / "tileset.json", 1u << 20);
  EXPECT_TRUE(bytes) << bytes.error();
  const auto* text = reinterpret_cast<const char*>(bytes->data());
  return Json::parse(text, text + bytes->size())["root"];
}

Result<Json> expandSample(const std::string& sample) {
  const fs::path dir = kImplicitSamples / sample;
  return expandImplicitTiling(rootOf(dir), readUnder(dir), 100000, sample + "/tileset.json");
}

std::vector<double> numbers(const Json& j) { return j.get<std::vector<double>>(); }

// What the expanded tree holds, its tiles' (level, x, y, z) found from their boxes (the samples'
// roots are the unit square and cube, axis-aligned at (0.5, 0.5)).
struct Walked {
  size_t tiles = 0;
  std::map<std::string, int> uris;
  std::set<std::tuple<int, int, int, int>> coords;
};

void walkBoxes(const Json& tile, int level, int dims, const std::string& pattern, Walked& w) {
  ++w.tiles;
  const auto box = numbers(tile["boundingVolume"]["box"]);
  const double cells = std::ldexp(1.0, level);
  const auto cell = [&](int axis) {
    return dims > axis ? static_cast<int>(std::lround(box[static_cast<size_t>(axis)] * cells - 0.5))
                       : 0;
  };
  const int x = cell(0), y = cell(1), z = cell(2);
  w.coords.emplace(level, x, y, z);
  if (tile.contains("content")) {
    const std::string uri = tile["content"]["uri"];
    ++w.uris[uri];
    std::string expected = "content/content_" + std::to_string(level) + "__" + std::to_string(x) +
                           "_" + std::to_string(y) + (dims == 3 ? "_" + std::to_string(z) : "");
    EXPECT_EQ(uri, expected + ".glb");
  }
  EXPECT_FALSE(tile.contains("implicitTiling"));
  if (!tile.contains("children")) return;
  for (const Json& child : tile["children"]) {
    const auto inner = numbers(child["boundingVolume"]["box"]);
    // Half-axes halve where the scheme splits (x, y; octree z too), the rest stays.
    for (size_t axis = 0; axis < 3; ++axis) {
      const double parentHalf = box[3 + 4 * axis], childHalf = inner[3 + 4 * axis];
      EXPECT_DOUBLE_EQ(childHalf, static_cast<int>(axis) < dims ? parentHalf / 2 : parentHalf);
      EXPECT_GE(inner[axis] - childHalf, box[axis] - parentHalf - 1e-12);  // inside its parent
      EXPECT_LE(inner[axis] + childHalf, box[axis] + parentHalf + 1e-12);
    }
    EXPECT_DOUBLE_EQ(child["geometricError"].get<double>(),
                     tile["geometricError"].get<double>() / 2);
    EXPECT_EQ(child.value("refine", ""), "ADD");
    walkBoxes(child, level + 1, dims, pattern, w);
  }
}

std::map<std::string, int> contentFiles(const std::string& sample) {
  std::map<std::string, int> files;
  for (const auto& e : fs::directory_iterator(kImplicitSamples / sample / "content"))
    files["content/" + e.path().filename().string()] = 1;
  return files;
}

TEST(ImplicitTiling, TheSparseQuadtreeNamesExactlyItsContentFiles) {
  auto tree = expandSample("SparseImplicitQuadtree");
  ASSERT_TRUE(tree) << tree.error();
  Walked w;
  walkBoxes(*tree, 0, 2, "", w);
  const auto files = contentFiles("SparseImplicitQuadtree");
  EXPECT_EQ(files.size(), 32u);
  EXPECT_EQ(w.uris, files);  // each once
  EXPECT_EQ(w.tiles, 63u);   // the 32 at level 5 and their ancestors
  // screenshot/subtreeInfo.md: the root subtree's bits 2, 3, 9, 12 are (1, 1, 0), (1, 0, 1),
  // (2, 2, 0), (2, 3, 1); its child subtree (3, 5, 0) holds content at bits 6 and 18: (5, 21, 0)
  // and (5, 23, 2). Tile (1, 0, 0) (bit 1) and (2, 0, 0) (bit 5) are not available.
  for (const auto& [level, x, y] : {std::tuple{0, 0, 0},
                                    {1, 1, 0},
                                    {1, 0, 1},
                                    {2, 2, 0},
                                    {2, 3, 1},
                                    {3, 5, 0},
                                    {5, 21, 0},
                                    {5, 23, 2}})
    EXPECT_TRUE(w.coords.count({level, x, y, 0})) << level << " " << x << " " << y;
  EXPECT_FALSE(w.coords.count({1, 0, 0, 0}));
  EXPECT_FALSE(w.coords.count({2, 0, 0, 0}));
  EXPECT_EQ(tree->value("geometricError", 0.0), 32.0);
}

TEST(ImplicitTiling, TheSparseOctreeNamesExactlyItsContentFiles) {
  auto tree = expandSample("SparseImplicitOctree");
  ASSERT_TRUE(tree) << tree.error();
  Walked w;
  walkBoxes(*tree, 0, 3, "", w);
  const auto files = contentFiles("SparseImplicitOctree");
  EXPECT_EQ(files.size(), 31u);
  EXPECT_EQ(w.uris, files);
  EXPECT_EQ(w.tiles, 58u);
  EXPECT_TRUE(w.coords.count({4, 10, 10, 2}));
  EXPECT_TRUE(w.coords.count({1, 0, 0, 0}));
  EXPECT_TRUE(w.coords.count({5, 31, 31, 31}));
  EXPECT_TRUE(w.coords.count({1, 1, 1, 1}));   // above level 5's contents
  EXPECT_FALSE(w.coords.count({1, 0, 0, 1}));  // nothing below it
}

TEST(ImplicitTiling, TheMaximumTileCountIsAClearError) {
  const fs::path dir = kImplicitSamples / "SparseImplicitQuadtree";
  auto tree = expandImplicitTiling(rootOf(dir), readUnder(dir), 62, "q/tileset.json");
  ASSERT_FALSE(tree);
  EXPECT_NE(tree.error().find("q/tileset.json: implicit tiling expands to more than 62 tiles"),
            std::string::npos)
      << tree.error();
  EXPECT_TRUE(expandImplicitTiling(rootOf(dir), readUnder(dir), 63, "q/tileset.json"));
}

// A region quadtree in JSON subtree files: the root subtree (levels 0 and 1, every tile and
// content available) names child subtrees (2, 0, 0) and (2, 3, 3) in an external buffer one
// folder up from the subtree's.
TEST(ImplicitTiling, RegionsSplitWestEastSouthNorthAndOctreesTheirHeights) {
  const fs::path dir = globe::testing::freshTempDir("implicit-region");
  const std::vector<double> region = {0.1, 0.2, 0.5, 0.4, -10, 90};
  Json root = {{"boundingVolume", {{"region", region}}},
               {"geometricError", 64},
               {"refine", "REPLACE"},
               {"content", {{"uri", "c/{level}/{x}/{y}.glb"}}},
               {"implicitTiling",
                {{"subdivisionScheme", "QUADTREE"},
                 {"subtreeLevels", 2},
                 {"availableLevels", 3},
                 {"subtrees", {{"uri", "subtrees/{level}.{x}.{y}.json"}}}}}};
  writeFile(dir / "subtrees/0.0.0.json",
            R"({"buffers":[{"uri":"../bits/children.bin","byteLength":2}],)"
            R"("bufferViews":[{"buffer":0,"byteLength":2}],"tileAvailability":{"constant":1},)"
            R"("contentAvailability":[{"constant":1}],"childSubtreeAvailability":{"bitstream":0},)"
            R"("propertyTables":[{"class":"x","count":1}],"tileMetadata":0})");
  writeFile(dir / "bits/children.bin", std::vector<std::byte>{std::byte{0x01}, std::byte{0x80}});
  for (const char* leaf : {"2.0.0", "2.3.3"})
    writeFile(dir / "subtrees" / (std::string(leaf) + ".json"),
              R"({"tileAvailability":{"constant":1},"contentAvailability":[{"constant":0}],)"
              R"("childSubtreeAvailability":{"constant":0}})");
  auto tree = expandImplicitTiling(root, readUnder(dir), 1000, "r/tileset.json");
  ASSERT_TRUE(tree) << tree.error();
  ASSERT_EQ((*tree)["children"].size(), 4u);
  EXPECT_EQ((*tree)["content"]["uri"], "c/0/0/0.glb");
  size_t tiles = 1, contents = 1;
  for (const Json& child : (*tree)["children"]) {
    ++tiles, contents += child.contains("content");
    const auto r = numbers(child["boundingVolume"]["region"]);
    EXPECT_NEAR(r[2] - r[0], 0.2, 1e-12);  // half the width and height, the same heights
    EXPECT_NEAR(r[3] - r[1], 0.1, 1e-12);
    EXPECT_TRUE(r[0] >= 0.1 && r[2] <= 0.5 + 1e-12 && r[1] >= 0.2 && r[3] <= 0.4 + 1e-12);
    EXPECT_EQ(r[4], -10);
    EXPECT_EQ(r[5], 90);
    EXPECT_EQ(child["geometricError"], 32.0);
    EXPECT_EQ(child["refine"], "REPLACE");
    for (const Json& grandchild : child.value("children", Json::array())) {
      ++tiles, contents += grandchild.contains("content");
      EXPECT_EQ(grandchild["geometricError"], 16.0);
    }
  }
  EXPECT_EQ(tiles, 7u);     // 1 + 4 + the two child subtrees' roots
  EXPECT_EQ(contents, 5u);  // the child subtrees have none
  const Json& last = (*tree)["children"][3]["children"][0];  // (2, 3, 3): the north-east corner
  const auto r = numbers(last["boundingVolume"]["region"]);
  EXPECT_NEAR(r[0], 0.4, 1e-12);
  EXPECT_NEAR(r[1], 0.35, 1e-12);
  EXPECT_NEAR(r[2], 0.5, 1e-12);
  EXPECT_NEAR(r[3], 0.4, 1e-12);

  // An octree splits the heights too: child 5 = (x 1, y 0, z 1).
  root["implicitTiling"]["subdivisionScheme"] = "OCTREE";
  root["implicitTiling"]["availableLevels"] = 2;
  root["implicitTiling"]["subtrees"]["uri"] = "subtrees/{level}.{x}.{y}.{z}.json";
  writeFile(dir / "subtrees/0.0.0.0.json",
            R"({"tileAvailability":{"constant":1},"contentAvailability":[{"constant":1}],)"
            R"("childSubtreeAvailability":{"constant":0}})");
  root["content"]["uri"] = "c/{level}/{x}/{y}/{z}.glb";
  auto octree = expandImplicitTiling(root, readUnder(dir), 1000, "o/tileset.json");
  ASSERT_TRUE(octree) << octree.error();
  ASSERT_EQ((*octree)["children"].size(), 8u);
  const Json& five = (*octree)["children"][5];
  EXPECT_EQ(five["content"]["uri"], "c/1/1/0/1.glb");
  const auto o = numbers(five["boundingVolume"]["region"]);
  EXPECT_NEAR(o[0], 0.3, 1e-12);
  EXPECT_NEAR(o[2], 0.5, 1e-12);
  EXPECT_NEAR(o[1], 0.2, 1e-12);
  EXPECT_NEAR(o[3], 0.3, 1e-12);
  EXPECT_NEAR(o[4], 40, 1e-12);
  EXPECT_NEAR(o[5], 90, 1e-12);
}

// The sample copied and placed east-north-up at 100 m to its unit (it stands in a local frame).
fs::path placedSample(const std::string& sample) {
  const fs::path dir = globe::testing::freshTempDir("implicit-placed-" + sample);
  fs::copy(kImplicitSamples / sample, dir, fs::copy_options::recursive);
  glm::dmat4 m = eastNorthUp(138.6, 35.0, 0);
  for (int c = 0; c < 3; ++c) m[c] *= 100.0;
  auto bytes = transport::readWholeFile(dir / "tileset.json", 1u << 20);
  EXPECT_TRUE(bytes);
  const auto* text = reinterpret_cast<const char*>(bytes->data());
  Json tileset = Json::parse(text, text + bytes->size());
  tileset["root"]["transform"] = Json::parse(transformJson(m));
  writeFile(dir / "tileset.json", tileset.dump());
  return dir;
}

TEST(ImplicitTiling, ReadTilesetAndTheSurfaceReadEveryContent) {
  for (const auto& [sample, glbs, tiles] : {std::tuple{"SparseImplicitQuadtree", 32u, 63u},
                                            std::tuple{"SparseImplicitOctree", 31u, 58u}}) {
    auto tileset = readTileset(placedSample(sample));
    ASSERT_TRUE(tileset) << tileset.error();
    EXPECT_EQ(tileset->tileCount, tiles) << sample;
    EXPECT_TRUE(tileset->root.additive);
    auto surface = TilesetSurface::load(*tileset, geo::Ellipsoid::wgs84());
    ASSERT_TRUE(surface) << surface.error();
    EXPECT_EQ(surface->contentsRead(), glbs) << sample;
    EXPECT_TRUE(surface->warnings().empty()) << surface->warnings()[0];
  }
}

// A binary subtree file: header, JSON padded to 8 bytes, binary chunk.
std::vector<std::byte> subtreeFile(std::string json, const std::vector<uint8_t>& binary) {
  while (json.size() % 8 != 0) json += ' ';
  std::vector<std::byte> out(24 + json.size() + binary.size());
  const uint32_t version = 1;
  const uint64_t jsonBytes = json.size(), binaryBytes = binary.size();
  std::memcpy(out.data(), "subt", 4);
  std::memcpy(out.data() + 4, &version, 4);
  std::memcpy(out.data() + 8, &jsonBytes, 8);
  std::memcpy(out.data() + 16, &binaryBytes, 8);
  std::memcpy(out.data() + 24, json.data(), json.size());
  if (!binary.empty()) std::memcpy(out.data() + 24 + json.size(), binary.data(), binary.size());
  return out;
}

// A quadtree tileset whose root subtree is `subtree`; readTileset's error (empty: it read).
std::string readWithSubtree(const std::vector<std::byte>& subtree, int availableLevels = 4) {
  const fs::path root = globe::testing::freshTempDir("implicit-hostile");
  const fs::path dir = root / "set";
  writeFile(root / "secret.bin", std::vector<std::byte>(8, std::byte{0xff}));
  writeFile(dir / "tileset.json",
            R"({"asset":{"version":"1.1"},"geometricError":10,"root":{"boundingVolume":)"
            R"({"box":[0,0,0,1,0,0,0,1,0,0,0,1]},"geometricError":8,"refine":"ADD",)"
            R"("content":{"uri":"{level}_{x}_{y}.glb"},"implicitTiling":{)"
            R"("subdivisionScheme":"QUADTREE","subtreeLevels":3,"availableLevels":)" +
                std::to_string(availableLevels) +
                R"(,"subtrees":{"uri":"st/{level}.{x}.{y}.subtree"}}}})");
  writeFile(dir / "st/0.0.0.subtree", subtree);
  auto tileset = readTileset(dir);
  return tileset ? std::string() : tileset.error();
}

void expectError(const std::string& error, const std::string& what) {
  EXPECT_NE(error.find(what), std::string::npos) << error;
  EXPECT_NE(error.find("tileset.json"), std::string::npos) << error;
  EXPECT_NE(error.find("st/0.0.0.subtree"), std::string::npos) << error;
}

TEST(ImplicitTiling, HostileSubtreesAreClearErrors) {
  // 21 tiles in 3 levels: 3 bytes of tile bits; 64 child subtrees: 8 bytes.
  const std::string good =
      R"({"buffers":[{"byteLength":16}],"bufferViews":[{"buffer":0,"byteLength":3},)"
      R"({"buffer":0,"byteOffset":8,"byteLength":8}],"tileAvailability":{"bitstream":0},)"
      R"("contentAvailability":[{"bitstream":0}],"childSubtreeAvailability":{"constant":0}})";
  const std::vector<uint8_t> bits = {0x1f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  const auto file = subtreeFile(good, bits);
  EXPECT_EQ(readWithSubtree(file), "");

  expectError(readWithSubtree({file.begin(), file.begin() + 40}), "truncated");
  expectError(readWithSubtree({file.begin(), file.begin() + 10}), "truncated");
  auto magic = file;
  magic[0] = std::byte{'x'};
  expectError(readWithSubtree(magic), "not a subtree file");
  std::string shortBits = good;
  shortBits.replace(shortBits.find("\"byteLength\":3"), 14, "\"byteLength\":2");
  expectError(readWithSubtree(subtreeFile(shortBits, bits)), "shorter than the 3 its 21 bits need");
  std::string past = good;
  past.replace(past.find("\"byteOffset\":8"), 14, "\"byteOffset\":9");
  expectError(readWithSubtree(subtreeFile(past, bits)), "past the end of its buffer");
  expectError(readWithSubtree(subtreeFile(good, {0x1f})), "holds only 1 bytes");
  const std::string outside =
      R"({"buffers":[{"uri":"../../secret.bin","byteLength":8}],)"
      R"("bufferViews":[{"buffer":0,"byteLength":8}],"tileAvailability":{"bitstream":0},)"
      R"("childSubtreeAvailability":{"constant":0}})";
  expectError(readWithSubtree(subtreeFile(outside, {})), "outside the tileset's folder");
  expectError(readWithSubtree(subtreeFile(R"({"tileAvailability":{"constant":7}})", {})),
              "neither a bitstream nor a constant");
  expectError(readWithSubtree(subtreeFile("{not json", {})), "does not parse");
  const std::string levels = readWithSubtree(file, 100);
  EXPECT_NE(levels.find("availableLevels is not an integer from 1 to 32"), std::string::npos)
      << levels;
}

TEST(ImplicitTiling, MissingSubtreesAndOtherVolumesAreClearErrors) {
  const fs::path dir = kImplicitSamples / "SparseImplicitQuadtree";
  Json root = rootOf(dir);
  const auto none = [](const std::string&) -> Result<std::optional<std::vector<std::byte>>> {
    return std::optional<std::vector<std::byte>>{};
  };
  auto missing = expandImplicitTiling(root, none, 100, "q/tileset.json");
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error(), "q/tileset.json: subtree 'subtrees/0.0.0.subtree': no such file");
  root["boundingVolume"] = {{"sphere", {0, 0, 0, 1}}};
  auto sphere = expandImplicitTiling(root, readUnder(dir), 100, "q/tileset.json");
  ASSERT_FALSE(sphere);
  EXPECT_NE(sphere.error().find("a box or region"), std::string::npos) << sphere.error();
  root["boundingVolume"] = {{"extensions", {{"3DTILES_bounding_volume_S2", Json::object()}}}};
  auto s2 = expandImplicitTiling(root, readUnder(dir), 100, "q/tileset.json");
  ASSERT_FALSE(s2);
  EXPECT_NE(s2.error().find("3DTILES_bounding_volume_S2"), std::string::npos) << s2.error();
  root["implicitTiling"]["subdivisionScheme"] = "S2";
  EXPECT_FALSE(expandImplicitTiling(root, readUnder(dir), 100, "q/tileset.json"));
}

}  // namespace
}  // namespace globe::tiles3d
