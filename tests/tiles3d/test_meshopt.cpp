// glTF buffer views compressed by meshoptimizer (EXT_/KHR_meshopt_compression) and positions
// quantized (KHR_mesh_quantization), made here with meshoptimizer's encoders: read through
// readTileContent, they give the triangles of the same model stored plain; hostile extensions
// are refused with errors that name the file. Draco primitives (decoded by tiles3d, not
// tinygltf) from the fuzz corpus's seed and regression files.
#include <gtest/gtest.h>
#include <meshoptimizer.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "geo/ellipsoid.hpp"
#include "tests/support/build_paths.hpp"
#include "tiles3d/tile_content.hpp"

namespace globe::tiles3d::meshopt_test {
namespace {

const geo::Ellipsoid kWgs84 = geo::Ellipsoid::wgs84();
const glm::dmat4 kIdentity(1.0);

// A unit cube's corners, scaled, and its 12 triangles.
const std::vector<float> kPositions = {0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0,
                                       0, 0, 2, 2, 0, 2, 2, 2, 2, 0, 2, 2};
const std::vector<uint32_t> kIndices = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                        1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
constexpr size_t kVertices = 8;

std::vector<unsigned char> bytesOf(const void* data, size_t size) {
  const auto* p = static_cast<const unsigned char*>(data);
  return {p, p + size};
}

std::vector<uint16_t> shortIndices() { return {kIndices.begin(), kIndices.end()}; }

// `json` and `bin` as a GLB (chunks padded to 4 bytes).
std::vector<std::byte> glb(std::string json, std::vector<unsigned char> bin) {
  while (json.size() % 4 != 0) json += ' ';
  while (bin.size() % 4 != 0) bin.push_back(0);
  std::vector<std::byte> out(12);
  const auto put = [&out](uint32_t v) {
    const auto at = out.size();
    out.resize(at + 4);
    std::memcpy(out.data() + at, &v, 4);
  };
  std::memcpy(out.data(), "glTF", 4);
  const uint32_t version = 2, total = static_cast<uint32_t>(12 + 8 + json.size() + 8 + bin.size());
  std::memcpy(out.data() + 4, &version, 4);
  std::memcpy(out.data() + 8, &total, 4);
  put(static_cast<uint32_t>(json.size()));
  put(0x4E4F534A);
  for (const char c : json) out.push_back(static_cast<std::byte>(c));
  put(static_cast<uint32_t>(bin.size()));
  put(0x004E4942);
  for (const unsigned char c : bin) out.push_back(static_cast<std::byte>(c));
  return out;
}

// The JSON around one mesh of POSITION (accessor 0) and indices (accessor 1).
std::string gltfJson(const std::string& extensions, const std::string& buffers,
                     const std::string& views, const std::string& positionAccessor,
                     const std::string& node = R"({"mesh":0})") {
  return R"({"asset":{"version":"2.0"},)" + extensions + R"("buffers":[)" + buffers +
         R"(],"bufferViews":[)" + views + R"(],"accessors":[)" + positionAccessor +
         R"(,{"bufferView":1,"componentType":5123,"count":36,"type":"SCALAR"}],)" +
         R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],)" +
         R"("nodes":[)" + node + R"(],"scenes":[{"nodes":[0]}],"scene":0})";
}

const std::string kFloatPositions =
    R"({"bufferView":0,"componentType":5126,"count":8,"type":"VEC3",)"
    R"("min":[0,0,0],"max":[2,2,2]})";

// The cube stored plain: floats and uint16 indices in the BIN chunk (the positions' accessor
// of `positionAccessor`, the first index `firstIndex`).
std::vector<std::byte> plainCube(const std::string& positionAccessor = kFloatPositions,
                                 uint16_t firstIndex = 0) {
  auto bin = bytesOf(kPositions.data(), kPositions.size() * 4);
  auto indices = shortIndices();
  indices[0] = firstIndex;
  const auto indexBytes = bytesOf(indices.data(), indices.size() * 2);
  bin.insert(bin.end(), indexBytes.begin(), indexBytes.end());
  return glb(gltfJson("", R"({"byteLength":168})",
                      R"({"buffer":0,"byteOffset":0,"byteLength":96,"byteStride":12},)"
                      R"({"buffer":0,"byteOffset":96,"byteLength":72})",
                      positionAccessor),
             bin);
}

TEST(GltfAccessors, CountNearTwoToThe64IsAnError) {
  // 12 × (count - 1) wraps to 2^64 - 4: the accessor looked 8 bytes long and index 1000 read
  // 12 KB past the buffer. The count is now bounded by its view before it is multiplied.
  const std::string huge = R"({"bufferView":0,"componentType":5126,"count":1537228672809129302,)"
                           R"("type":"VEC3"})";
  auto mesh = readTileContent(plainCube(huge, 1000), kIdentity, kWgs84, "cube.glb");
  ASSERT_FALSE(mesh);
  EXPECT_NE(mesh.error().find("reaches past its buffer"), std::string::npos) << mesh.error();
}

std::vector<unsigned char> encodeVertices(const void* vertices, size_t count, size_t stride) {
  std::vector<unsigned char> out(meshopt_encodeVertexBufferBound(count, stride));
  out.resize(meshopt_encodeVertexBuffer(out.data(), out.size(), vertices, count, stride));
  return out;
}

// The indices as TRIANGLES (meshopt_encodeIndexBuffer) or as INDICES (an index sequence).
std::vector<unsigned char> encodeTriangles(bool sequence = false) {
  std::vector<unsigned char> out(sequence
                                     ? meshopt_encodeIndexSequenceBound(kIndices.size(), kVertices)
                                     : meshopt_encodeIndexBufferBound(kIndices.size(), kVertices));
  out.resize(
      sequence
          ? meshopt_encodeIndexSequence(out.data(), out.size(), kIndices.data(), kIndices.size())
          : meshopt_encodeIndexBuffer(out.data(), out.size(), kIndices.data(), kIndices.size()));
  return out;
}

struct Compressed {
  std::string extension = "EXT_meshopt_compression";
  std::string fallbackBuffer;        // the uncompressed views' buffer; default: tagged, no data
  std::string positionFilter;        // "" or a filter name
  std::string positionStrideInView;  // the extension's byteStride (default 12)
  std::string positionCount = "8";
  std::string indexMode = "TRIANGLES";
  bool indexSequence = false;  // the indices encoded as a sequence (INDICES' bitstream)
  int positionLengthCut = 0;   // bytes taken off the compressed positions' byteLength
};

// The cube with both views compressed (positions: ATTRIBUTES, indices: `indexMode`), the
// compressed streams in the BIN chunk (buffer 0), the views' own buffer a fallback (buffer 1).
std::vector<std::byte> compressedCube(const Compressed& c,
                                      const std::vector<unsigned char>& positionsEncoded) {
  auto bin = positionsEncoded;
  const size_t positionLength = bin.size();
  const auto indicesEncoded = encodeTriangles(c.indexSequence);
  bin.insert(bin.end(), indicesEncoded.begin(), indicesEncoded.end());
  const std::string filter =
      c.positionFilter.empty() ? "" : R"(,"filter":")" + c.positionFilter + '"';
  const std::string stride = c.positionStrideInView.empty() ? "12" : c.positionStrideInView;
  const std::string views =
      R"({"buffer":1,"byteOffset":0,"byteLength":96,"byteStride":12,"extensions":{")" +
      c.extension + R"(":{"buffer":0,"byteOffset":0,"byteLength":)" +
      std::to_string(static_cast<int>(positionLength) - c.positionLengthCut) + R"(,"byteStride":)" +
      stride + R"(,"count":)" + c.positionCount + R"(,"mode":"ATTRIBUTES")" + filter + R"(}}},)" +
      R"({"buffer":1,"byteOffset":96,"byteLength":72,"extensions":{")" + c.extension +
      R"(":{"buffer":0,"byteOffset":)" + std::to_string(positionLength) + R"(,"byteLength":)" +
      std::to_string(indicesEncoded.size()) + R"(,"byteStride":2,"count":36,"mode":")" +
      c.indexMode + R"("}}})";
  const std::string fallback =
      c.fallbackBuffer.empty()
          ? R"({"byteLength":168,"extensions":{")" + c.extension + R"(":{"fallback":true}}})"
          : c.fallbackBuffer;
  const std::string buffers = R"({"byteLength":)" + std::to_string(bin.size()) + "}," + fallback;
  const std::string extensions = R"("extensionsUsed":[")" + c.extension +
                                 R"("],"extensionsRequired":[")" + c.extension + R"("],)";
  return glb(gltfJson(extensions, buffers, views, kFloatPositions), bin);
}

std::vector<std::byte> compressedCube(const Compressed& c = {}) {
  return compressedCube(c, encodeVertices(kPositions.data(), kVertices, 12));
}

Result<TriangleMesh> read(const std::vector<std::byte>& bytes) {
  return readTileContent(bytes, kIdentity, kWgs84, "cube.glb");
}

// Triangle t of `got` is triangle t of `expected`, its corners maybe rotated (the TRIANGLES
// codec may start a triangle at another corner; the winding stays).
bool sameTriangle(const TriangleMesh& expected, const TriangleMesh& got, size_t t,
                  double tolerance) {
  for (size_t r = 0; r < 3; ++r) {
    bool same = true;
    for (size_t c = 0; c < 3; ++c) {
      const glm::dvec3 d = got.positions[3 * t + (c + r) % 3] - expected.positions[3 * t + c];
      same = same && std::abs(d.x) <= tolerance && std::abs(d.y) <= tolerance &&
             std::abs(d.z) <= tolerance;
    }
    if (same) return true;
  }
  return false;
}

void expectSameTriangles(const TriangleMesh& expected, const TriangleMesh& got,
                         double tolerance = 0) {
  ASSERT_EQ(got.triangleCount(), expected.triangleCount());
  for (size_t t = 0; t < expected.triangleCount(); ++t) {
    EXPECT_TRUE(sameTriangle(expected, got, t, tolerance)) << "triangle " << t;
  }
}

TEST(MeshoptCompression, PlainCubeReadsAsTwelveTriangles) {
  auto plain = read(plainCube());
  ASSERT_TRUE(plain) << plain.error();
  EXPECT_EQ(plain->triangleCount(), 12U);
}

TEST(MeshoptCompression, CompressedViewsGiveThePlainTriangles) {
  auto plain = read(plainCube());
  ASSERT_TRUE(plain) << plain.error();
  for (const std::string extension : {"EXT_meshopt_compression", "KHR_meshopt_compression"}) {
    Compressed c;
    c.extension = extension;
    auto mesh = read(compressedCube(c));
    ASSERT_TRUE(mesh) << extension << ": " << mesh.error();
    expectSameTriangles(*plain, *mesh);
  }
}

TEST(MeshoptCompression, UntaggedFallbackBufferWithoutDataIsNotNeeded) {
  auto plain = read(plainCube());
  ASSERT_TRUE(plain) << plain.error();
  Compressed c;
  c.fallbackBuffer = R"({"byteLength":1000000000})";  // declares 1 GB, holds nothing
  auto mesh = read(compressedCube(c));
  ASSERT_TRUE(mesh) << mesh.error();
  expectSameTriangles(*plain, *mesh);
}

TEST(MeshoptCompression, IndexSequenceModeAndExponentialFilterDecode) {
  auto plain = read(plainCube());
  ASSERT_TRUE(plain) << plain.error();
  // The cube's coordinates are small integers: 23-bit mantissas hold them exactly.
  std::vector<uint32_t> filtered(kPositions.size());
  meshopt_encodeFilterExp(filtered.data(), kVertices * 3, 4, 23, kPositions.data());
  Compressed c;
  c.positionFilter = "EXPONENTIAL";
  c.indexMode = "INDICES";
  // INDICES is its own bitstream: triangles encoded for TRIANGLES will not decode as one.
  auto wrongStream = read(compressedCube(c, encodeVertices(filtered.data(), kVertices, 12)));
  ASSERT_FALSE(wrongStream);
  EXPECT_NE(wrongStream.error().find("cube.glb"), std::string::npos);
  c.indexSequence = true;
  auto mesh = read(compressedCube(c, encodeVertices(filtered.data(), kVertices, 12)));
  ASSERT_TRUE(mesh) << mesh.error();
  expectSameTriangles(*plain, *mesh);
}

// int16 positions (KHR_mesh_quantization), stride 8, scaled back by the node, plain or
// normalized, and the same compressed.
std::vector<std::byte> quantizedCube(bool normalized, bool compressed) {
  std::vector<int16_t> shorts;
  for (size_t v = 0; v < kVertices; ++v) {
    for (size_t c = 0; c < 3; ++c)
      shorts.push_back(static_cast<int16_t>(kPositions[v * 3 + c] * 1000));
    shorts.push_back(0);
  }
  const auto indices = shortIndices();
  std::vector<unsigned char> positionBytes = bytesOf(shorts.data(), shorts.size() * 2);
  if (compressed) positionBytes = encodeVertices(shorts.data(), kVertices, 8);
  std::vector<unsigned char> indexBytes = bytesOf(indices.data(), indices.size() * 2);
  if (compressed) indexBytes = encodeTriangles();
  auto bin = positionBytes;
  while (bin.size() % 4 != 0) bin.push_back(0);
  const size_t indexOffset = bin.size();
  bin.insert(bin.end(), indexBytes.begin(), indexBytes.end());
  const std::string ext = R"(,"extensions":{"EXT_meshopt_compression":{"buffer":0,)";
  const std::string views =
      compressed ? R"({"buffer":1,"byteLength":64,"byteStride":8)" + ext + R"("byteLength":)" +
                       std::to_string(positionBytes.size()) +
                       R"(,"byteStride":8,"count":8,"mode":"ATTRIBUTES"}}},)" +
                       R"({"buffer":1,"byteOffset":64,"byteLength":72)" + ext + R"("byteOffset":)" +
                       std::to_string(indexOffset) + R"(,"byteLength":)" +
                       std::to_string(indexBytes.size()) +
                       R"(,"byteStride":2,"count":36,"mode":"TRIANGLES"}}})"
                 : R"({"buffer":0,"byteLength":64,"byteStride":8},{"buffer":0,"byteOffset":)" +
                       std::to_string(indexOffset) + R"(,"byteLength":72})";
  const std::string buffers = R"({"byteLength":)" + std::to_string(bin.size()) + "}" +
                              (compressed ? R"(,{"byteLength":136})" : "");
  const std::string used = compressed ? R"(,"EXT_meshopt_compression")" : "";
  const std::string extensions = R"("extensionsUsed":["KHR_mesh_quantization")" + used +
                                 R"(],"extensionsRequired":["KHR_mesh_quantization")" + used + "],";
  const std::string accessor =
      std::string(R"({"bufferView":0,"componentType":5122,"count":8,"type":"VEC3",)") +
      (normalized ? R"("normalized":true,)" : "") + R"("min":[0,0,0],"max":[2000,2000,2000]})";
  // 1000 units a metre; normalized, a unit is 1/32767.
  const std::string scale = normalized ? "32.767" : "0.001";
  return glb(gltfJson(extensions, buffers, views, accessor,
                      R"({"mesh":0,"scale":[)" + scale + "," + scale + "," + scale + "]}"),
             bin);
}

TEST(MeshoptCompression, QuantizedShortPositionsAreScaledByTheirNode) {
  auto plain = read(plainCube());
  ASSERT_TRUE(plain) << plain.error();
  for (const bool normalized : {false, true}) {
    for (const bool compressed : {false, true}) {
      auto mesh = read(quantizedCube(normalized, compressed));
      ASSERT_TRUE(mesh) << mesh.error();
      SCOPED_TRACE(std::string("normalized ") + (normalized ? "yes" : "no") + ", compressed " +
                   (compressed ? "yes" : "no"));
      expectSameTriangles(*plain, *mesh, 1e-9);
    }
  }
}

void expectError(const std::vector<std::byte>& bytes, const std::string& words) {
  auto mesh = read(bytes);
  ASSERT_FALSE(mesh);
  EXPECT_NE(mesh.error().find("cube.glb"), std::string::npos) << mesh.error();
  EXPECT_NE(mesh.error().find(words), std::string::npos) << mesh.error();
}

TEST(MeshoptCompression, TruncatedCompressedRangeIsAnError) {
  Compressed c;
  c.positionLengthCut = 20;
  expectError(compressedCube(c), "will not decode");
}

TEST(MeshoptCompression, RangePastItsBufferIsAnError) {
  Compressed c;
  c.positionLengthCut = -4000;
  expectError(compressedCube(c), "reaches past buffer 0");
}

TEST(MeshoptCompression, DecodedSizeOverTheLimitIsRefusedBeforeAllocating) {
  Compressed c;
  c.positionCount = "100000000";  // 100M × 12 bytes: 1.2 GB
  expectError(compressedCube(c), "decodes past 256 MiB");
  c.positionCount = "18446744073709551615";
  expectError(compressedCube(c), "decodes past 256 MiB");
}

TEST(MeshoptCompression, BadModesFiltersAndStridesAreErrors) {
  Compressed c;
  c.indexMode = "QUADS";
  expectError(compressedCube(c), "unknown mode 'QUADS'");
  c = {};
  c.positionFilter = "COLOR";
  expectError(compressedCube(c), "unsupported filter 'COLOR'");
  c = {};
  c.positionFilter = "QUATERNION";  // needs a stride of 8
  expectError(compressedCube(c), "not allowed for ATTRIBUTES/QUATERNION");
  c = {};
  c.positionStrideInView = "6";
  expectError(compressedCube(c), "not allowed for ATTRIBUTES/NONE");
  c = {};
  c.positionStrideInView = "16";  // its bufferView says 12 and 96 bytes
  expectError(compressedCube(c), "disagrees");
  c = {};
  c.positionCount = "-8";
  expectError(compressedCube(c), "not a non-negative integer");
}

std::vector<std::byte> corpusFile(const std::string& file) {
  std::ifstream in(std::string(GLOBE_SOURCE_DIR) + "/tests/fuzz/corpus/tile_content/" + file,
                   std::ios::binary);
  const std::vector<char> chars{std::istreambuf_iterator<char>(in), {}};
  std::vector<std::byte> out(chars.size());
  if (!chars.empty()) std::memcpy(out.data(), chars.data(), chars.size());
  return out;
}

TEST(DracoCompression, CubeDecodesToItsTwelveTriangles) {
  // The cube's 12 triangles, positions quantized to 14 bits by the encoder (made by libdraco).
  auto mesh = read(corpusFile("seed-draco-cube.glb"));
  ASSERT_TRUE(mesh) << mesh.error();
  ASSERT_EQ(mesh->triangleCount(), 12U);
  for (const glm::dvec3& p : mesh->positions) {
    for (int a = 0; a < 3; ++a) {
      EXPECT_TRUE(std::abs(p[a]) < 1e-3 || std::abs(std::abs(p[a]) - 2) < 1e-3) << p[a];
    }
  }
}

TEST(DracoCompression, UnknownAttributeIdIsAnError) {
  // tinygltf called through a null Draco attribute here (read in its code, UBSan in the fuzz
  // build).
  auto mesh = read(corpusFile("regression-draco-unknown-attribute-id.glb"));
  ASSERT_FALSE(mesh);
  EXPECT_NE(mesh.error().find("no Draco attribute 7"), std::string::npos) << mesh.error();
}

TEST(TileContentRegression, I3dmInstancesLengthOfAWrongTypeIsAnError) {
  // {"INSTANCES_LENGTH": {"byteOffset": 0}}: nlohmann's value() threw out of readTileContent and
  // ended the program (the fuzz campaign's second finding).
  auto mesh = readTileContent(corpusFile("regression-i3dm-instances-length-an-object.i3dm"),
                              kIdentity, kWgs84, "x.i3dm");
  ASSERT_FALSE(mesh);
  EXPECT_NE(mesh.error().find("x.i3dm: INSTANCES_LENGTH is not a whole number"), std::string::npos)
      << mesh.error();
}

}  // namespace
}  // namespace globe::tiles3d::meshopt_test
