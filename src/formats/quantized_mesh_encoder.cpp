// quantized-mesh-1.0 written as the spec lays it out (little-endian), for the exporter. Vertices
// are renumbered in the order the triangles first use them, as the index code requires.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <utility>
#include <vector>

#include "formats/quantized_mesh.hpp"

namespace globe::formats {
namespace {

class Writer {
 public:
  template <class T>
  void put(T value) {
    const size_t at = bytes.size();
    bytes.resize(at + sizeof(T));
    std::memcpy(&bytes[at], &value, sizeof(T));  // the host is little-endian, as the reader assumes
  }
  void alignTo(size_t size) {
    while (bytes.size() % size != 0) bytes.push_back(std::byte{0});
  }
  std::vector<std::byte> bytes;
};

uint16_t zigZag(int32_t value) {
  return static_cast<uint16_t>((static_cast<uint32_t>(value) << 1) ^
                               static_cast<uint32_t>(value >> 31));
}

// A unit vector's octahedral encoding in two bytes (the spec's, and what decoders invert).
std::pair<uint8_t, uint8_t> octEncode(const std::array<float, 3>& n) {
  const double sum = std::fabs(n[0]) + std::fabs(n[1]) + std::fabs(n[2]);
  double x = sum > 0 ? n[0] / sum : 0, y = sum > 0 ? n[1] / sum : 0;
  if (n[2] < 0) {
    const double ox = x;
    x = (1 - std::fabs(y)) * (ox >= 0 ? 1.0 : -1.0);
    y = (1 - std::fabs(ox)) * (y >= 0 ? 1.0 : -1.0);
  }
  const auto toByte = [](double v) {
    return static_cast<uint8_t>(std::lround((std::clamp(v, -1.0, 1.0) * 0.5 + 0.5) * 255.0));
  };
  return {toByte(x), toByte(y)};
}

void putDeltas(Writer& w, const std::vector<uint16_t>& values) {
  int32_t previous = 0;
  for (uint16_t value : values) {
    w.put(zigZag(static_cast<int32_t>(value) - previous));
    previous = value;
  }
}

}  // namespace

std::vector<std::byte> encodeQuantizedMesh(const QuantizedMesh& given,
                                           const QuantizedMeshCulling& culling) {
  // The high-water-mark code needs vertices numbered in the order triangles first use them.
  const size_t count = given.vertexCount();
  std::vector<uint32_t> renamed(count, UINT32_MAX);
  std::vector<uint32_t> order;
  order.reserve(count);
  for (uint32_t index : given.triangles) {
    if (renamed[index] == UINT32_MAX) {
      renamed[index] = static_cast<uint32_t>(order.size());
      order.push_back(index);
    }
  }
  for (uint32_t k = 0; k < count; ++k) {
    if (renamed[k] == UINT32_MAX) {
      renamed[k] = static_cast<uint32_t>(order.size());
      order.push_back(k);
    }
  }
  QuantizedMesh mesh = given;
  for (size_t k = 0; k < count; ++k) {
    mesh.u[k] = given.u[order[k]];
    mesh.v[k] = given.v[order[k]];
    mesh.heightMeters[k] = given.heightMeters[order[k]];
  }
  for (uint32_t& index : mesh.triangles) index = renamed[index];
  for (std::vector<uint32_t>* edge :
       {&mesh.westEdge, &mesh.southEdge, &mesh.eastEdge, &mesh.northEdge}) {
    for (uint32_t& index : *edge) index = renamed[index];
  }

  Writer w;
  for (double c : mesh.centerEcefMeters) w.put(c);
  w.put(mesh.minimumHeightMeters);
  w.put(mesh.maximumHeightMeters);
  for (double c : culling.boundingSphereCenterEcefMeters) w.put(c);
  w.put(culling.boundingSphereRadiusMeters);
  for (double c : culling.horizonOcclusionPointScaled) w.put(c);

  const auto vertexCount = static_cast<uint32_t>(mesh.vertexCount());
  w.put(vertexCount);
  putDeltas(w, mesh.u);
  putDeltas(w, mesh.v);
  std::vector<uint16_t> quantized(vertexCount);
  const double span = double{mesh.maximumHeightMeters} - mesh.minimumHeightMeters;
  for (uint32_t k = 0; k < vertexCount; ++k) {
    const double t = span > 0 ? (mesh.heightMeters[k] - mesh.minimumHeightMeters) / span : 0.0;
    quantized[k] = static_cast<uint16_t>(std::lround(std::clamp(t, 0.0, 1.0) * kQuantizedMax));
  }
  putDeltas(w, quantized);

  const bool wide = vertexCount > 65536;
  w.alignTo(wide ? 4 : 2);
  const auto putIndex = [&](uint32_t index) {
    if (wide) {
      w.put(index);
    } else {
      w.put(static_cast<uint16_t>(index));
    }
  };
  w.put(static_cast<uint32_t>(mesh.triangles.size() / 3));
  uint32_t highest = 0;
  for (uint32_t index : mesh.triangles) {
    // High-water mark: each index as its distance below the highest index yet plus one.
    putIndex(highest - index);
    if (index == highest) ++highest;
  }
  for (const std::vector<uint32_t>* edge :
       {&mesh.westEdge, &mesh.southEdge, &mesh.eastEdge, &mesh.northEdge}) {
    w.put(static_cast<uint32_t>(edge->size()));
    for (uint32_t index : *edge) putIndex(index);
  }
  // Extensions, each an id, its length and its bytes.
  if (!mesh.normals.empty()) {
    w.put(uint8_t{1});
    w.put(static_cast<uint32_t>(2 * count));
    for (size_t k = 0; k < count; ++k) {
      const auto [x, y] = octEncode(given.normals[order[k]]);
      w.put(x);
      w.put(y);
    }
  }
  if (!mesh.waterMask.empty()) {
    w.put(uint8_t{2});
    w.put(static_cast<uint32_t>(mesh.waterMask.size()));
    for (uint8_t m : mesh.waterMask) w.put(m);
  }
  if (!mesh.metadataJson.empty()) {
    w.put(uint8_t{4});
    w.put(static_cast<uint32_t>(4 + mesh.metadataJson.size()));
    w.put(static_cast<uint32_t>(mesh.metadataJson.size()));
    for (char c : mesh.metadataJson) w.put(c);
  }
  return std::move(w.bytes);
}

}  // namespace globe::formats
