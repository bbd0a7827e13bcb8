// The pack file, version 6 (compressed blocks in Morton order, a column index) and the versions
// still read: round trips of every sample value, the storage order a viewer relies on to read
// neighbours with one request, the sizes it saves, and damaged or hostile packs refused by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "core/big_endian.hpp"
#include "compression/deflate_bytes.hpp"
#include "formats/pack_block_codec.hpp"
#include "formats/pack_format.hpp"
#include "formats/pack_index_codec.hpp"

namespace globe::formats {
namespace {

constexpr uint32_t kSide = 17;

// Smooth terrain with a sea in one corner (as the tiler writes it), or random samples of every
// int16 value (the codec's worst case).
Pack makePack(uint32_t tilesPerSide, uint32_t version, double presentFraction, bool noise,
              uint32_t seed) {
  Pack pack = Pack::empty({9, 3, 4}, {tilesPerSide, kSide, version});
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> any(INT16_MIN, INT16_MAX);
  for (size_t slot = 0; slot < pack.layout.slotCount(); ++slot) {
    if (unit(random) >= presentFraction) continue;
    const double x0 = static_cast<double>(slot % tilesPerSide);
    const double y0 = static_cast<double>(slot / tilesPerSide);
    const auto height = [&](int row, int column) -> int16_t {
      if (noise) return static_cast<int16_t>(any(random));
      const double x = x0 + column / 16.0;
      const double y = y0 + row / 16.0;
      const double h = 900 * std::sin(x * 0.7) * std::cos(y * 0.4) + 300 * std::sin(x * 3.1 + y);
      if (h < -600) return terrain::kNoDataHeight;                // sea, depth unknown
      if (h < -300) return static_cast<int16_t>(-20000 + h / 4);  // sea over a floor
      return static_cast<int16_t>(std::lround(h));
    };
    std::span<int16_t> block = pack.block(slot);
    for (int row = 0; row < static_cast<int>(kSide); ++row) {
      for (int column = 0; column < static_cast<int>(kSide); ++column) {
        block[static_cast<size_t>(row) * kSide + static_cast<size_t>(column)] = height(row, column);
      }
    }
    std::span<int16_t> apron = pack.apron(slot);
    for (size_t i = 0; i < apron.size(); ++i) {
      apron[i] = height(-2, static_cast<int>(i % (kSide + 4)) - 2);
    }
    const auto [low, high] = std::minmax_element(block.begin(), block.end());
    PackEntry& entry = pack.entries[slot];
    entry.blockOffset = 1;
    entry.vertexRange = {*low, *high};
    entry.subtreeRange = {static_cast<int16_t>(*low - 7), static_cast<int16_t>(*high + 3)};
    entry.geometricErrorMeters = static_cast<float>(unit(random) * 40);
  }
  return pack;
}

void expectSamePack(const Pack& a, const Pack& b) {
  ASSERT_EQ(a.entries.size(), b.entries.size());
  for (size_t slot = 0; slot < a.entries.size(); ++slot) {
    SCOPED_TRACE("slot " + std::to_string(slot));
    ASSERT_EQ(a.entries[slot].present(), b.entries[slot].present());
    if (!a.entries[slot].present()) continue;
    EXPECT_EQ(a.entries[slot].vertexRange.minimumMeters, b.entries[slot].vertexRange.minimumMeters);
    EXPECT_EQ(a.entries[slot].vertexRange.maximumMeters, b.entries[slot].vertexRange.maximumMeters);
    EXPECT_EQ(a.entries[slot].subtreeRange.minimumMeters,
              b.entries[slot].subtreeRange.minimumMeters);
    EXPECT_EQ(a.entries[slot].subtreeRange.maximumMeters,
              b.entries[slot].subtreeRange.maximumMeters);
    EXPECT_EQ(a.entries[slot].geometricErrorMeters, b.entries[slot].geometricErrorMeters);
    ASSERT_TRUE(std::equal(a.block(slot).begin(), a.block(slot).end(), b.block(slot).begin()));
    ASSERT_TRUE(std::equal(a.apron(slot).begin(), a.apron(slot).end(), b.apron(slot).begin()));
  }
}

TEST(PackFormat, EveryVersionWrittenReadsBackExactly) {
  for (const uint32_t version : {4U, 5U, 6U}) {
    for (const bool noise : {false, true}) {
      SCOPED_TRACE("version " + std::to_string(version) + (noise ? ", noise" : ", terrain"));
      const Pack pack = makePack(16, version, 0.6, noise, version * 7 + noise);
      const std::vector<std::byte> bytes = encodePack(pack);
      auto decoded = decodePack(bytes, "round.pack");
      ASSERT_TRUE(decoded) << decoded.error();
      EXPECT_EQ(decoded->layout.formatVersion, version);
      expectSamePack(pack, *decoded);
      // Each block decodes alone from the bytes its entry points at, as a viewer reads it.
      for (size_t slot = 0; slot < pack.layout.slotCount(); ++slot) {
        const PackEntry& e = decoded->entries[slot];
        if (!e.present()) continue;
        std::vector<int16_t> heights(size_t{kSide} * kSide);
        std::vector<int16_t> apron(terrain::apronSampleCount(kSide));
        ASSERT_TRUE(decodeStoredBlock(std::span(bytes).subspan(e.blockOffset, e.storedBytes),
                                      decoded->layout, e, heights, apron));
        ASSERT_TRUE(std::equal(heights.begin(), heights.end(), pack.block(slot).begin()));
      }
    }
  }
}

TEST(PackFormat, TheCodecKeepsExtremeSamples) {
  // Every residual the predictor can make: alternating extremes wrap around 2^16 both ways.
  const size_t side = kSide + 4;
  std::vector<std::byte> samples(2 * side * side);
  const int16_t values[] = {INT16_MIN, INT16_MAX, 0, -1, terrain::kNoDataHeight, -32767, 8848};
  for (size_t i = 0; i < side * side; ++i) {
    core::storeBigEndian16(&samples[2 * i], static_cast<uint16_t>(values[(i * 5 + i / side) % 7]));
  }
  const std::vector<std::byte> stored = encodeCompressedBlock(samples, side);
  std::vector<std::byte> back(samples.size());
  ASSERT_TRUE(decodeCompressedBlock(stored, side, back));
  EXPECT_EQ(back, samples);
}

TEST(PackFormat, Version6StoresEverySquareOfNeighboursTogether) {
  const Pack pack = makePack(64, 6, 1.0, false, 1);
  auto decoded = decodePack(encodePack(pack), "order.pack");
  ASSERT_TRUE(decoded) << decoded.error();
  // Any aligned 2^k × 2^k square of tiles (a tile's children, grandchildren...) is one run of
  // bytes: its blocks end to end with nothing between.
  for (const uint32_t square : {2U, 4U, 8U, 64U}) {
    for (uint32_t y0 = 0; y0 < 64; y0 += square) {
      for (uint32_t x0 = 0; x0 < 64; x0 += square) {
        uint64_t first = UINT64_MAX;
        uint64_t end = 0;
        uint64_t bytes = 0;
        for (uint32_t y = y0; y < y0 + square; ++y) {
          for (uint32_t x = x0; x < x0 + square; ++x) {
            const PackEntry& e = decoded->entries[size_t{y} * 64 + x];
            first = std::min(first, e.blockOffset);
            end = std::max(end, e.blockOffset + e.storedBytes);
            bytes += e.storedBytes;
          }
        }
        ASSERT_EQ(end - first, bytes) << square << "-square at " << x0 << "," << y0;
      }
    }
  }
  EXPECT_EQ(mortonKey(1, 0), 1U);
  EXPECT_EQ(mortonKey(0, 1), 2U);
  EXPECT_EQ(mortonKey(3, 3), 15U);
}

TEST(PackFormat, Version6IsSmallerThanVersion5) {
  // A full pack of terrain-like blocks: the column index and the predicted blocks shrink it.
  const Pack v5 = makePack(64, 5, 1.0, false, 3);
  Pack v6 = v5;
  v6.layout.formatVersion = 6;
  const std::vector<std::byte> bytes5 = encodePack(v5);
  const std::vector<std::byte> bytes6 = encodePack(v6);
  auto index5 = decodePackIndex(bytes5, bytes5.size(), "v5.pack");
  auto index6 = decodePackIndex(bytes6, bytes6.size(), "v6.pack");
  ASSERT_TRUE(index5 && index6);
  std::printf("[ sizes    ] full 64x64 pack: index %u -> %u bytes, file %zu -> %zu bytes\n",
              index5->layout.indexBytes, index6->layout.indexBytes, bytes5.size(), bytes6.size());
  EXPECT_LT(index6->layout.indexBytes * 2, index5->layout.indexBytes);
  EXPECT_LT(bytes6.size() * 2, bytes5.size());
}

// The pack with its index columns edited, recompressed and its header's index size fixed.
std::vector<std::byte> withColumns(const std::vector<std::byte>& pack,
                                   const std::function<void(std::vector<std::byte>&)>& edit) {
  const uint32_t present = core::loadBigEndian32(&pack[32]);
  const uint32_t indexBytes = core::loadBigEndian32(&pack[36]);
  const uint32_t perSide = core::loadBigEndian32(&pack[24]);
  std::vector<std::byte> columns(presenceBitmapBytes(perSide) + indexColumnBytes(present));
  EXPECT_TRUE(globe::compression::zlibInflateExactly(std::span(pack).subspan(kPackHeaderBytes, indexBytes), columns));
  edit(columns);
  const std::vector<std::byte> index = globe::compression::zlibCompress(columns, 6);
  std::vector<std::byte> out(pack.begin(), pack.begin() + kPackHeaderBytes);
  core::storeBigEndian32(&out[36], static_cast<uint32_t>(index.size()));
  out.insert(out.end(), index.begin(), index.end());
  out.insert(out.end(), pack.begin() + kPackHeaderBytes + indexBytes, pack.end());
  return out;
}

TEST(PackFormat, DamagedVersion6PacksAreRefusedNamingTheFile) {
  const Pack pack = makePack(8, 6, 0.5, false, 5);
  const std::vector<std::byte> good = encodePack(pack);
  const uint32_t present = core::loadBigEndian32(&good[32]);
  ASSERT_GT(present, 2U);
  const size_t sizes = presenceBitmapBytes(8);
  const auto expectRefused = [](const std::vector<std::byte>& bytes, const std::string& says) {
    auto index = decodePackIndex(bytes, bytes.size(), "bad.pack");
    auto whole = decodePack(bytes, "bad.pack");
    ASSERT_FALSE(index.ok() && whole.ok()) << says;
    const std::string& error = index.ok() ? whole.error() : index.error();
    EXPECT_EQ(error.rfind("bad.pack: ", 0), 0U) << error;
    EXPECT_NE(error.find(says), std::string::npos) << error;
  };
  // A block size that would run past the file, or past any block's bound.
  expectRefused(withColumns(good, [&](auto& c) { core::storeBigEndian32(&c[sizes], 5000); }),
                "impossible block size");
  expectRefused(withColumns(good,
                            [&](auto& c) {
                              core::storeBigEndian32(&c[sizes],
                                                     core::loadBigEndian32(&c[sizes]) + 1);
                            }),
                "index says");
  // One slot more in the bitmap than the header counts.
  expectRefused(withColumns(good,
                            [&](auto& c) {
                              for (size_t i = 0; i < sizes; ++i) {
                                if (c[i] != std::byte{0xFF}) {
                                  c[i] |= std::byte{0xFF};
                                  break;
                                }
                              }
                            }),
                "disagrees");
  // An index that does not inflate.
  std::vector<std::byte> garbled = good;
  garbled[kPackHeaderBytes + 3] ^= std::byte{0x5A};
  expectRefused(garbled, "pack index");
  // A file cut short.
  expectRefused(std::vector<std::byte>(good.begin(), good.end() - 9), "truncated");
  // One flipped bit inside a block: its CRC names it (the whole file's CRC would too, but a
  // viewer reading the block alone relies on the block's own).
  auto index = decodePackIndex(good, good.size(), "good.pack");
  ASSERT_TRUE(index) << index.error();
  const auto slot =
      static_cast<size_t>(std::find_if(index->entries.begin(), index->entries.end(),
                                       [](const PackEntry& e) { return e.present(); }) -
                          index->entries.begin());
  const PackEntry& e = index->entries[slot];
  std::vector<std::byte> flipped = good;
  flipped[e.blockOffset + e.storedBytes / 2] ^= std::byte{0x10};
  std::vector<int16_t> heights(size_t{kSide} * kSide);
  std::vector<int16_t> apron(terrain::apronSampleCount(kSide));
  auto block = decodeStoredBlock(std::span(flipped).subspan(e.blockOffset, e.storedBytes),
                                 index->layout, e, heights, apron);
  ASSERT_FALSE(block);
  EXPECT_NE(block.error().find("fails its CRC"), std::string::npos) << block.error();
}

}  // namespace
}  // namespace globe::formats
