#include "terrain/edge_heights.hpp"

#include <bit>

#include "terrain/tile_mesh.hpp"

namespace globe::terrain {
namespace {

// FNV-1a over the bytes of each height's bit pattern.
constexpr uint64_t kFnvOffset = 14695981039346656037ull;
constexpr uint64_t kFnvPrime = 1099511628211ull;

uint64_t mix(uint64_t hash, double heightMeters) {
  const auto bits = std::bit_cast<uint64_t>(heightMeters + 0.0);  // -0 + 0 = +0
  for (int byte = 0; byte < 8; ++byte) {
    hash ^= (bits >> (8 * byte)) & 0xFF;
    hash *= kFnvPrime;
  }
  return hash;
}

}  // namespace

EdgeHeightHashes edgeHeightHashes(const HeightBlock& block) {
  const uint32_t n = block.verticesPerSide;
  EdgeHeightHashes hashes{};
  if (!isValidBlockSize(n) || block.heights.size() != static_cast<size_t>(n) * n) return hashes;
  hashes.fill(kFnvOffset);
  for (uint32_t edge = 0; edge < 4; ++edge) {
    for (uint32_t k = 0; k < n; ++k) {  // in the skirts' order (tile_mesh.hpp)
      const uint32_t index = edgeGridIndex(static_cast<TileEdge>(edge), k, n);
      hashes[edge] = mix(hashes[edge], block.surfaceHeightMetersAt(index / n, index % n));
    }
  }
  return hashes;
}

}  // namespace globe::terrain
