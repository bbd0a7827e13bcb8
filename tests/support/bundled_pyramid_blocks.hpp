// Test fixture: every block (index entry, samples, apron) of the bundled pyramid in memory, read
// through decodePack, for the tests that check the pyramid vertex by vertex.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "formats/pack_format.hpp"
#include "formats/pyramid_manifest.hpp"
#include "tests/support/tiler_test_fixture.hpp"
#include "transport/atomic_file.hpp"

namespace globe::testing {

class BundledPyramid : public ::testing::Test {
 public:
  struct Block {
    formats::PackEntry entry;
    std::vector<int16_t> samples;  // N×N
    std::vector<int16_t> apron;    // terrain::apronSampleCount(N)
  };

 protected:
  static void SetUpTestSuite() {
    const auto& dir = globe::testing::bundledPyramid();
    auto manifest = formats::readManifest(dir);
    ASSERT_TRUE(manifest) << manifest.error();
    manifest_ = new formats::PyramidManifest(*manifest);
    tiles_ = new std::map<geo::TileId, Block>();
    blocks_ = new std::map<geo::TileId, std::pair<formats::PackEntry, std::vector<int16_t>>>();
    for (const formats::LevelInfo& level : manifest_->levels) {
      for (const formats::PackId& id : level.packs) {
        const auto path = formats::packPath(dir, id);
        auto bytes = transport::readWholeFile(path, 1ULL << 32);
        ASSERT_TRUE(bytes) << bytes.error();
        auto pack = formats::decodePack(*bytes, path);
        ASSERT_TRUE(pack) << pack.error();
        for (size_t slot = 0; slot < pack->entries.size(); ++slot) {
          if (!pack->entries[slot].present()) continue;
          const auto block = pack->block(slot);
          const auto apron = pack->apron(slot);
          const geo::TileId tile = formats::tileOfSlot(id, slot, pack->layout.tilesPerSide);
          (*tiles_)[tile] = {
              pack->entries[slot], {block.begin(), block.end()}, {apron.begin(), apron.end()}};
          (*blocks_)[tile] = {pack->entries[slot], {block.begin(), block.end()}};
        }
      }
    }
  }
  static void TearDownTestSuite() {
    delete manifest_;
    delete tiles_;
    delete blocks_;
  }
  static const std::vector<int16_t>* find(const geo::TileId& t) {
    auto it = blocks_->find(t);
    return it == blocks_->end() ? nullptr : &it->second.second;
  }
  static const Block* findBlock(const geo::TileId& t) {
    auto it = tiles_->find(t);
    return it == tiles_->end() ? nullptr : &it->second;
  }
  static constexpr uint32_t n = 17;
  static inline formats::PyramidManifest* manifest_ = nullptr;
  static inline std::map<geo::TileId, Block>* tiles_ = nullptr;
  // The same blocks as (entry, samples) pairs, as the older tests read them.
  static inline std::map<geo::TileId, std::pair<formats::PackEntry, std::vector<int16_t>>>*
      blocks_ = nullptr;
};

}  // namespace globe::testing
