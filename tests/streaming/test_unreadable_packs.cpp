// TileStore and TileLoader when a pack cannot be read for real (root ignores chmod 000): the pack
// path is a directory, a FIFO, a device, a dangling or looping symlink, empty, garbage or missing;
// or the pack is truncated or replaced after its index was read. Each is reported once, tried
// once, never blocks, and a repaired pack loads after forgetFailures().
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "geo/tiling_scheme.hpp"
#include "streaming/block_cache.hpp"
#include "streaming/tile_loader.hpp"
#include "streaming/tile_store.hpp"
#include "tests/streaming/loader_test_pyramid.hpp"
#include "tests/support/inline_runner.hpp"
#include "tests/support/test_io_util.hpp"

namespace globe::streaming {
namespace {

namespace fs = std::filesystem;
using geo::TileId;

// Three level-14 tiles in a row at Mount Fuji: present, in one pack.
std::vector<TileId> fujiTiles() {
  const auto fuji = geo::GeographicTilingScheme::positionToTile(geo::degreesToRadians(138.73),
                                                                geo::degreesToRadians(35.36), 14);
  return {*fuji, {14, fuji->x + 1, fuji->y}, {14, fuji->x + 2, fuji->y}};
}

class UnreadablePackTest : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::copy(testing::loaderTestPyramid(), dir_.path() / "pyramid", fs::copy_options::recursive);
    auto store = TileStore::open(dir_.path() / "pyramid");
    ASSERT_TRUE(store) << store.error();
    store_ = std::move(*store);
    pack_ = formats::packPath(store_->location(),
                              formats::packOf(tiles_[0], store_->manifest().packTilesPerSide));
    ASSERT_EQ(pack_,
              formats::packPath(store_->location(),
                                formats::packOf(tiles_[2], store_->manifest().packTilesPerSide)));
    fs::copy_file(pack_, dir_ / "good.pack");
  }
  // Asks for the tiles for `frames` frames; returns the loader's errors.
  std::vector<LoadError> view(TileLoader& loader, BlockCache& cache, int frames) {
    std::vector<LoadError> errors;
    for (int frame = 0; frame < frames; ++frame) {
      std::vector<LoadRequest> wanted;
      for (const TileId& tile : tiles_) wanted.push_back({tile, 1.0});
      loader.request(wanted);
      runner_.runAll();
      cache.beginFrame();
      for (LoadError& e : loader.poll().errors) errors.push_back(std::move(e));
    }
    return errors;
  }

  globe::testing::TempDir dir_;
  std::unique_ptr<TileStore> store_;
  fs::path pack_;
  const std::vector<TileId> tiles_ = fujiTiles();
  globe::testing::InlineRunner runner_;
  BlockCache cache_{16 << 20};
};

struct Damage {
  const char* name;
  void (*apply)(const fs::path& pack);
  const char* reason;  // what the error says
};

void writeGarbage(const fs::path& pack) {
  const auto size = fs::file_size(pack);
  fs::remove(pack);
  std::ofstream(pack, std::ios::binary) << std::string(size, 'x');
}

const Damage kDamages[] = {
    {"missing", [](const fs::path&) {}, "cannot open: No such file or directory"},
    {"a directory", [](const fs::path& p) { fs::create_directory(p); }, "not a regular file"},
    {"a FIFO", [](const fs::path& p) { ::mkfifo(p.c_str(), 0644); }, "not a regular file"},
    {"a character device", [](const fs::path& p) { fs::create_symlink("/dev/zero", p); },
     "not a regular file"},
    {"a dangling symlink", [](const fs::path& p) { fs::create_symlink(p.string() + "x", p); },
     "cannot open: No such file or directory"},
    {"a symlink loop", [](const fs::path& p) { fs::create_symlink(p.filename(), p); },
     "cannot open: Too many levels of symbolic links"},
    {"empty", [](const fs::path& p) { std::ofstream(p, std::ios::binary).flush(); },
     "truncated pack (0 bytes)"},
    {"garbage",
     [](const fs::path& p) { std::ofstream(p, std::ios::binary) << std::string(400000, 'x'); },
     "not a globe pack file"}};

// One process for every kind (each test process tiles the pyramid once): a fresh store each.
TEST_F(UnreadablePackTest, EachKindIsReportedOnceTriedOnceAndLoadsAgainAfterARepair) {
  for (const Damage& damage : kDamages) {
    SCOPED_TRACE(std::string("the pack is ") + damage.name);
    auto opened = TileStore::open(dir_ / "pyramid");
    ASSERT_TRUE(opened) << opened.error();
    TileStore& store = **opened;
    BlockCache cache(16 << 20);
    fs::remove(pack_);
    damage.apply(pack_);
    TileLoader loader(store, runner_, cache);
    ::alarm(30);  // a blocking open (a FIFO) fails the test instead of hanging it
    const auto errors = view(loader, cache, 6);
    for (int call = 0; call < 50; ++call) EXPECT_FALSE(store.entry(tiles_[0]));  // look-ups
    ::alarm(0);

    ASSERT_EQ(errors.size(), tiles_.size()) << "each tile once, not once per frame";
    for (const LoadError& e : errors) {
      EXPECT_EQ(e.file, pack_);
      EXPECT_NE(e.message.find(pack_.string()), std::string::npos) << e.message;
      EXPECT_NE(e.message.find(damage.reason), std::string::npos) << e.message;
    }
    for (const TileId& tile : tiles_) EXPECT_EQ(loader.state(tile), TileState::Failed);
    EXPECT_EQ(store.packOpenFailures(), 1U) << "the damaged pack is opened once, not per call";
    const auto reported = store.takeNewPackErrors();
    ASSERT_EQ(reported.size(), 1U) << "one message for the pack";
    EXPECT_EQ(reported[0], errors[0].message.substr(errors[0].message.find(pack_.string())));
    EXPECT_TRUE(store.takeNewPackErrors().empty());
    EXPECT_EQ(store.blockReads(), 0U);

    // Still damaged: a retry asked for reports it again, once.
    loader.forgetFailures();
    ::alarm(30);
    EXPECT_EQ(view(loader, cache, 3).size(), tiles_.size());
    ::alarm(0);
    EXPECT_EQ(store.packOpenFailures(), 2U);
    EXPECT_EQ(store.takeNewPackErrors().size(), 1U);

    // Repaired: the same store and loader load it.
    fs::remove_all(pack_);
    fs::copy_file(dir_ / "good.pack", pack_);
    loader.forgetFailures();
    EXPECT_TRUE(view(loader, cache, 1).empty());
    for (const TileId& tile : tiles_) EXPECT_TRUE(loader.isResident(tile));
    EXPECT_TRUE(store.takeNewPackErrors().empty());
  }
}

TEST_F(UnreadablePackTest, TruncatedAfterItsIndexWasReadIsReportedOnceAndReopenedAfterARepair) {
  ASSERT_TRUE(store_->entry(tiles_[0]));  // the viewer has read the pack's index
  fs::resize_file(pack_, store_->manifest().packLayout().indexEndOffset() + 100);
  TileLoader loader(*store_, runner_, cache_);
  const auto errors = view(loader, cache_, 5);
  ASSERT_EQ(errors.size(), tiles_.size());
  for (const LoadError& e : errors) {
    EXPECT_NE(e.message.find("unexpected end of file"), std::string::npos) << e.message;
  }
  const auto reported = store_->takeNewPackErrors();
  ASSERT_EQ(reported.size(), 1U);
  EXPECT_NE(reported[0].find(pack_.string()), std::string::npos) << reported[0];
  const uint64_t indexReads = store_->packIndexReads();  // this pack's, and level 0's at open
  EXPECT_LE(indexReads, 2U);

  // Repaired by renaming a good copy in: the store reads the new file, not the truncated one.
  fs::copy_file(dir_ / "good.pack", dir_ / "repaired.pack");
  fs::rename(dir_ / "repaired.pack", pack_);
  loader.forgetFailures();
  EXPECT_TRUE(view(loader, cache_, 1).empty());
  for (const TileId& tile : tiles_) EXPECT_TRUE(loader.isResident(tile));
  EXPECT_EQ(store_->packIndexReads(), indexReads + 1);
}

TEST_F(UnreadablePackTest, ReplacedAfterItsIndexWasReadKeepsServingTheFileItOpened) {
  auto before = store_->loadBlock(tiles_[0]);
  ASSERT_TRUE(before) << before.error();
  // A new file renamed over the pack (as the tiler does): the open descriptor keeps the old one.
  const fs::path replacement = pack_.string() + ".new";
  fs::copy_file(pack_, replacement);
  writeGarbage(replacement);
  fs::rename(replacement, pack_);
  for (const TileId& tile : tiles_) {
    auto block = store_->loadBlock(tile);
    ASSERT_TRUE(block) << block.error();
    auto fresh = TileStore::open(dir_ / "pyramid");
    ASSERT_TRUE(fresh) << fresh.error();
    EXPECT_FALSE((*fresh)->loadBlock(tile)) << "a new store sees the garbage";
    if (tile == tiles_[0]) {
      EXPECT_EQ(block->heights, before->heights);
    }
  }
  EXPECT_TRUE(store_->takeNewPackErrors().empty());
}

}  // namespace
}  // namespace globe::streaming
