// Cesium's quantized-mesh-1.0 terrain tile (github.com/CesiumGS/quantized-mesh): a TIN over the
// tile with u, v, h quantized to 0..32767, its edge vertex lists and optional extensions
// (oct-encoded vertex normals, a water mask, JSON metadata). Decoded and checked, never trusted:
// every count is bounded by the bytes present and every index by the vertex count.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/result.hpp"

namespace globe::formats {

inline constexpr uint32_t kQuantizedMax = 32767;

struct QuantizedMesh {
  std::array<double, 3> centerEcefMeters{};
  float minimumHeightMeters = 0;
  float maximumHeightMeters = 0;
  // Per vertex: u grows east, v grows north, both 0..32767 across the tile.
  std::vector<uint16_t> u, v;
  std::vector<double> heightMeters;
  std::vector<uint32_t> triangles;  // three vertex indices each, counter-clockwise
  std::vector<uint32_t> westEdge, southEdge, eastEdge, northEdge;
  // Extension 1: unit normals per vertex (x, y, z in ECEF), empty when absent.
  std::vector<std::array<float, 3>> normals;
  // Extension 2: 1 byte (0 land, 255 water for the whole tile) or 256×256 rows from the north,
  // 0..255 = land..water; empty when absent.
  std::vector<uint8_t> waterMask;
  std::string metadataJson;  // extension 4, empty when absent

  size_t vertexCount() const { return u.size(); }
  size_t triangleCount() const { return triangles.size() / 3; }
};

// Decodes a tile (already inflated). Errors name `name` and the problem; a tile whose header
// centre lies beyond the Earth (a producer writing Web-Mercator metres) or whose edge lists hold
// vertices off their edge is refused.
// How a tile writes its extensions' lengths: little-endian, as the format says, or big-endian,
// as tiles of the legacy "vertexnormals" extension do (CesiumJS reads them so where layer.json
// lists "vertexnormals" and not "octvertexnormals"). A length that cannot be read the declared
// way but fits the other way is read the other way (a producer that got the order wrong).
enum class ExtensionLengths { LittleEndian, BigEndian };
Result<QuantizedMesh> decodeQuantizedMesh(
    std::span<const std::byte> bytes, const std::string& name,
    ExtensionLengths lengths = ExtensionLengths::LittleEndian);
// Whether the header's centre lies over the tile (west..east, south..north in degrees, with a
// tile's size of margin): a tile served under another tile's name, or another tiling's, is not.
bool centreLiesOverTile(const QuantizedMesh& mesh, double westDegrees, double southDegrees,
                        double eastDegrees, double northDegrees);

// What a producer writes in the header beyond QuantizedMesh: the culling volumes a client such
// as CesiumJS uses (globe recomputes its own).
struct QuantizedMeshCulling {
  std::array<double, 3> boundingSphereCenterEcefMeters{};
  double boundingSphereRadiusMeters = 0;
  // In the ellipsoid-scaled space (ECEF divided by the radii), as the format specifies.
  std::array<double, 3> horizonOcclusionPointScaled{};
};

// Encodes a tile (not gzip-compressed): u, v as given, heights quantized into the mesh's
// minimum..maximum, indices high-water-mark coded (32-bit beyond 65536 vertices), the edge lists
// as given; the extensions the mesh holds (oct-encoded normals, the water mask, metadata). The
// caller keeps every index below the vertex count and heights in range.
std::vector<std::byte> encodeQuantizedMesh(const QuantizedMesh& mesh,
                                           const QuantizedMeshCulling& culling);

// Cesium's heightmap-1.0 tile: 65×65 heights (uint16 LE, h/5 - 1000 m) from the north-west,
// then a child mask and an optional water mask.
struct HeightmapTile {
  static constexpr uint32_t kSide = 65;
  std::vector<double> heightMeters;  // kSide², row 0 the north edge
  uint8_t childMask = 0;             // bits: 1 SW, 2 SE, 4 NW, 8 NE
  std::vector<uint8_t> waterMask;    // as QuantizedMesh::waterMask
};
Result<HeightmapTile> decodeHeightmapTile(std::span<const std::byte> bytes,
                                          const std::string& name);
// Encodes a tile (not gzip-compressed): each height as round((h + 1000) · 5) clamped to
// 0..65535 (0.2 m steps), the child mask, then the water mask when the tile has one (1 or
// 256×256 bytes). heightMeters holds kSide² values.
std::vector<std::byte> encodeHeightmapTile(const HeightmapTile& tile);

}  // namespace globe::formats
