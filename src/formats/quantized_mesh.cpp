#include "formats/quantized_mesh.hpp"

#include <cmath>
#include <cstring>
#include <numbers>

namespace globe::formats {
namespace {

constexpr size_t kHeaderBytes = 88;
// The furthest an ECEF centre can lie from the Earth's (beyond Everest); coarse tiles' centres
// lie deep inside it (the middle of their chords).
constexpr double kMaxCentreRadiusMeters = 6'400'000;

// Little-endian reads with the bounds checked once per call.
class Reader {
 public:
  Reader(std::span<const std::byte> bytes, const std::string& name) : bytes_(bytes), name_(name) {}
  size_t remaining() const { return bytes_.size() - at_; }
  size_t offset() const { return at_; }
  bool has(size_t n) const { return n <= remaining(); }
  template <class T>
  T get() {
    T value;
    std::memcpy(&value, bytes_.data() + at_, sizeof(T));  // little-endian hosts only (x86, ARM)
    at_ += sizeof(T);
    return value;
  }
  void skip(size_t n) { at_ += n; }
  void alignTo(size_t n) { at_ = (at_ + n - 1) / n * n; }
  Error truncated(const std::string& what) const {
    return Error{name_ + ": truncated quantized-mesh tile (" + what + " past byte " +
                 std::to_string(bytes_.size()) + ")"};
  }

 private:
  std::span<const std::byte> bytes_;
  const std::string& name_;
  size_t at_ = 0;
};

// An extension's length as read little-endian, in the order the layer declares; the other order
// where only that one fits in what is left.
uint32_t extensionLength(uint32_t readLittleEndian, ExtensionLengths declared, size_t remaining) {
  const uint32_t swapped = __builtin_bswap32(readLittleEndian);
  const uint32_t first = declared == ExtensionLengths::BigEndian ? swapped : readLittleEndian;
  const uint32_t second = first == swapped ? readLittleEndian : swapped;
  return first > remaining && second <= remaining ? second : first;
}

int32_t zigZag(uint16_t value) { return (value >> 1) ^ -static_cast<int32_t>(value & 1); }

Result<std::vector<uint16_t>> readDeltas(Reader& r, uint32_t count, const char* what,
                                         const std::string& name) {
  std::vector<uint16_t> out(count);
  int32_t value = 0;
  for (uint32_t k = 0; k < count; ++k) {
    value += zigZag(r.get<uint16_t>());
    if (value < 0 || value > static_cast<int32_t>(kQuantizedMax)) {
      return makeError(name + ": vertex " + std::to_string(k) + "'s " + what + " " +
                       std::to_string(value) + " lies outside 0..32767");
    }
    out[k] = static_cast<uint16_t>(value);
  }
  return out;
}

// Decodes oct-encoded unit vectors (Cigolle et al. 2014), as CesiumJS's AttributeCompression.
std::array<float, 3> octDecode(uint8_t xByte, uint8_t yByte) {
  float x = xByte / 255.0f * 2 - 1;
  float y = yByte / 255.0f * 2 - 1;
  const float z = 1 - (std::fabs(x) + std::fabs(y));
  if (z < 0) {
    const float ox = x;
    x = (1 - std::fabs(y)) * (ox >= 0 ? 1.0f : -1.0f);
    y = (1 - std::fabs(ox)) * (y >= 0 ? 1.0f : -1.0f);
  }
  const float length = std::sqrt(x * x + y * y + z * z);
  return {x / length, y / length, z / length};
}

Result<std::vector<uint8_t>> readWaterMask(std::span<const std::byte> bytes,
                                           const std::string& name) {
  if (bytes.size() != 1 && bytes.size() != 256 * 256) {
    return makeError(name + ": a water mask of " + std::to_string(bytes.size()) +
                     " bytes (1 or 65536 expected)");
  }
  std::vector<uint8_t> mask(bytes.size());
  std::memcpy(mask.data(), bytes.data(), bytes.size());
  return mask;
}

}  // namespace

Result<QuantizedMesh> decodeQuantizedMesh(std::span<const std::byte> bytes, const std::string& name,
                                          ExtensionLengths lengths) {
  Reader r(bytes, name);
  QuantizedMesh mesh;
  if (!r.has(kHeaderBytes + 4)) return r.truncated("the header");
  for (double& c : mesh.centerEcefMeters) c = r.get<double>();
  mesh.minimumHeightMeters = r.get<float>();
  mesh.maximumHeightMeters = r.get<float>();
  r.skip(kHeaderBytes - 32);  // bounding sphere and horizon occlusion point: recomputed, not used
  const double radius =
      std::hypot(mesh.centerEcefMeters[0], mesh.centerEcefMeters[1], mesh.centerEcefMeters[2]);
  if (!(radius <= kMaxCentreRadiusMeters)) {
    char centre[128];
    std::snprintf(centre, sizeof centre, "(%.1f, %.1f, %.1f)", mesh.centerEcefMeters[0],
                  mesh.centerEcefMeters[1], mesh.centerEcefMeters[2]);
    return makeError(name + ": the header's centre " + centre +
                     " is not an ECEF point on the Earth, as quantized-mesh-1.0 requires (tiles "
                     "written in Web-Mercator metres?)");
  }
  if (!std::isfinite(mesh.minimumHeightMeters) || !std::isfinite(mesh.maximumHeightMeters) ||
      mesh.maximumHeightMeters < mesh.minimumHeightMeters ||
      std::fabs(mesh.minimumHeightMeters) > 20'000 ||
      std::fabs(mesh.maximumHeightMeters) > 20'000) {
    return makeError(name + ": the header's height range " +
                     std::to_string(mesh.minimumHeightMeters) + ".." +
                     std::to_string(mesh.maximumHeightMeters) + " m is not a terrain's");
  }

  const uint32_t vertexCount = r.get<uint32_t>();
  if (!r.has(size_t{vertexCount} * 6)) return r.truncated("the vertices");
  auto u = readDeltas(r, vertexCount, "u", name);
  if (!u) return Error{u.error()};
  auto v = readDeltas(r, vertexCount, "v", name);
  if (!v) return Error{v.error()};
  auto h = readDeltas(r, vertexCount, "height", name);
  if (!h) return Error{h.error()};
  mesh.u = std::move(*u);
  mesh.v = std::move(*v);
  mesh.heightMeters.resize(vertexCount);
  const double span = double{mesh.maximumHeightMeters} - mesh.minimumHeightMeters;
  for (uint32_t k = 0; k < vertexCount; ++k)
    mesh.heightMeters[k] = mesh.minimumHeightMeters + span * (*h)[k] / kQuantizedMax;

  // 32-bit indices beyond 65536 vertices, aligned to their size.
  const bool wide = vertexCount > 65536;
  const size_t indexBytes = wide ? 4 : 2;
  r.alignTo(indexBytes);
  auto readIndex = [&]() -> uint32_t { return wide ? r.get<uint32_t>() : r.get<uint16_t>(); };
  if (!r.has(4)) return r.truncated("the triangle count");
  const uint32_t triangleCount = r.get<uint32_t>();
  if (!r.has(size_t{triangleCount} * 3 * indexBytes)) return r.truncated("the triangles");
  mesh.triangles.resize(size_t{triangleCount} * 3);
  uint32_t highest = 0;
  for (uint32_t& index : mesh.triangles) {
    const uint32_t code = readIndex();
    if (code > highest) {
      return makeError(name + ": a triangle index code " + std::to_string(code) +
                       " above the high-water mark " + std::to_string(highest));
    }
    index = highest - code;
    if (code == 0) ++highest;
    if (index >= vertexCount) {
      return makeError(name + ": triangle index " + std::to_string(index) + " beyond " +
                       std::to_string(vertexCount) + " vertices");
    }
  }

  // The edge lists, checked against the edge they name (a producer that swaps them is refused:
  // the skirts and the neighbours' seams would be wrong).
  struct EdgeList {
    std::vector<uint32_t>* list;
    const char* edge;
    bool onU;
    uint16_t value;
  };
  const EdgeList edges[] = {{&mesh.westEdge, "west", true, 0},
                            {&mesh.southEdge, "south", false, 0},
                            {&mesh.eastEdge, "east", true, kQuantizedMax},
                            {&mesh.northEdge, "north", false, kQuantizedMax}};
  for (const EdgeList& e : edges) {
    if (!r.has(4)) return r.truncated(std::string("the ") + e.edge + " edge");
    const uint32_t count = r.get<uint32_t>();
    if (!r.has(size_t{count} * indexBytes))
      return r.truncated(std::string("the ") + e.edge + " edge");
    e.list->resize(count);
    for (uint32_t& index : *e.list) {
      index = readIndex();
      if (index >= vertexCount) {
        return makeError(name + ": " + e.edge + " edge index " + std::to_string(index) +
                         " beyond " + std::to_string(vertexCount) + " vertices");
      }
      const uint16_t coordinate = e.onU ? mesh.u[index] : mesh.v[index];
      if (coordinate != e.value) {
        return makeError(name + ": vertex " + std::to_string(index) + " of the " + e.edge +
                         " edge list has " + (e.onU ? "u" : "v") + " = " +
                         std::to_string(coordinate) + ", not on that edge (edge lists swapped?)");
      }
    }
  }

  while (r.remaining() > 0) {
    if (!r.has(5)) return r.truncated("an extension header");
    const auto id = r.get<uint8_t>();
    const uint32_t length = extensionLength(r.get<uint32_t>(), lengths, r.remaining());
    if (!r.has(length)) return r.truncated("extension " + std::to_string(id));
    const std::span<const std::byte> body = bytes.subspan(r.offset(), length);
    if (id == 1) {
      if (length != size_t{vertexCount} * 2) {
        return makeError(name + ": an oct-normals extension of " + std::to_string(length) +
                         " bytes for " + std::to_string(vertexCount) + " vertices");
      }
      mesh.normals.resize(vertexCount);
      for (uint32_t k = 0; k < vertexCount; ++k) {
        mesh.normals[k] =
            octDecode(static_cast<uint8_t>(body[2 * k]), static_cast<uint8_t>(body[2 * k + 1]));
      }
    } else if (id == 2) {
      auto mask = readWaterMask(body, name);
      if (!mask) return Error{mask.error()};
      mesh.waterMask = std::move(*mask);
    } else if (id == 4) {
      if (length < 4) return r.truncated("the metadata extension");
      uint32_t jsonBytes = 0;
      std::memcpy(&jsonBytes, body.data(), 4);
      if (jsonBytes > length - 4) return r.truncated("the metadata JSON");
      mesh.metadataJson.assign(reinterpret_cast<const char*>(body.data()) + 4, jsonBytes);
    }  // other extensions are skipped, as the spec asks of clients that do not know them
    r.skip(length);
  }
  return mesh;
}

bool centreLiesOverTile(const QuantizedMesh& mesh, double west, double south, double east,
                        double north) {
  const auto& c = mesh.centerEcefMeters;
  const double width = east - west, height = north - south;
  const double lon = std::atan2(c[1], c[0]) * 180 / std::numbers::pi;
  // Geodetic latitude of a point on the WGS84 surface; a coarse tile's centre lies deep below it
  // (its chords' middle), where this is rough, but its tile is large.
  constexpr double kWgs84E2 = 6.69437999014e-3;
  const double lat =
      std::atan2(c[2], std::hypot(c[0], c[1]) * (1 - kWgs84E2)) * 180 / std::numbers::pi;
  double offset = std::fmod(lon - (west + east) / 2 + 540, 360) - 180;  // across ±180°
  if (std::hypot(c[0], c[1]) < 1) offset = 0;                           // over a pole
  return std::fabs(offset) <= width && lat >= south - height - 0.01 && lat <= north + height + 0.01;
}

Result<HeightmapTile> decodeHeightmapTile(std::span<const std::byte> bytes,
                                          const std::string& name) {
  constexpr size_t kHeights = size_t{HeightmapTile::kSide} * HeightmapTile::kSide;
  if (bytes.size() < kHeights * 2 + 1) {
    return makeError(name + ": a heightmap-1.0 tile of " + std::to_string(bytes.size()) +
                     " bytes (at least " + std::to_string(kHeights * 2 + 1) + " expected)");
  }
  HeightmapTile tile;
  tile.heightMeters.resize(kHeights);
  for (size_t k = 0; k < kHeights; ++k) {
    const auto raw = static_cast<uint16_t>(static_cast<unsigned>(bytes[2 * k]) |
                                           static_cast<unsigned>(bytes[2 * k + 1]) << 8);
    tile.heightMeters[k] = raw / 5.0 - 1000.0;
  }
  tile.childMask = static_cast<uint8_t>(bytes[kHeights * 2]);
  const auto rest = bytes.subspan(kHeights * 2 + 1);
  if (!rest.empty()) {
    auto mask = readWaterMask(rest, name);
    if (!mask) return Error{mask.error()};
    tile.waterMask = std::move(*mask);
  }
  return tile;
}

}  // namespace globe::formats
