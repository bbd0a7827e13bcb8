// TerrainScene over a damaged pyramid: the pack under the camera missing, truncated, a directory,
// a FIFO, a dangling symlink, or truncated after its index was read. The view still completes,
// the damaged pack's tiles are drawn from their ancestors (no hole), everything else is drawn as
// before, collision still knows the ground, and one message names the pack however many frames.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "geo/tiling_scheme.hpp"
#include "scene/terrain_scene.hpp"
#include "tests/support/bookkeeping_gpu.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::scene {
namespace {

namespace fs = std::filesystem;
using geo::TileId;

constexpr int kWidth = 320, kHeight = 180;
constexpr int kExtraFrames = 30;  // after the view completed: a message per frame would show

// Straight down over Mount Fuji from 6 km: level-14 tiles from a few packs are drawn.
camera::CameraPose fujiPose() {
  return camera::CameraPose::fromDegrees(138.73, 35.36, 6000, 0, -90, 0);
}

struct SceneRun {
  std::vector<TileId> tiles;
  std::string messages;
  bool hasNadir = false;  // collision knows the ground under the camera
  uint32_t nadirLevel = 0;
};

// Opens the scene, runs `beforeViewing` (which may damage the pyramid), completes the view and
// draws kExtraFrames more frames.
template <class Hook>
SceneRun view(const fs::path& pyramid, Hook beforeViewing) {
  SceneRun run;
  globe::testing::BookkeepingGpu gpu;
  SceneOptions options;
  options.hysteresis = false;
  // The scene's warnings, one a line (a program prints them on stderr).
  auto messages = std::make_shared<std::string>();
  options.warnings = [messages](const std::string& warning) { *messages += warning + "\n"; };
  auto scene = TerrainScene::open(pyramid, options);
  EXPECT_TRUE(scene) << scene.error();
  if (!scene) return run;
  beforeViewing(**scene);
  auto frame =
      (*scene)->updateUntilComplete(fujiPose(), kWidth, kHeight, gpu, std::chrono::seconds(60));
  EXPECT_TRUE(frame) << frame.error();
  for (int i = 0; i < kExtraFrames; ++i) {
    (*scene)->update(fujiPose(), kWidth, kHeight, gpu);
  }
  run.messages = *messages;
  run.tiles = (*scene)->tiles();
  const auto pose = fujiPose();
  const auto found = (*scene)->renderingTileArray().lookupIndexed(pose.position.longitudeRadians,
                                                                  pose.position.latitudeRadians);
  run.hasNadir = found.tile != nullptr;
  run.nadirLevel = found.tile ? found.tile->id.level : 0;
  return run;
}

bool isAncestor(const TileId& ancestor, TileId tile) {
  while (tile.level > ancestor.level) tile = tile.parent();
  return tile == ancestor;
}

struct Damage {
  const char* name;
  void (*apply)(const fs::path& pack);  // null: truncated once the scene has read the index
  const char* reason;
};

const Damage kDamages[] = {
    {"missing", [](const fs::path&) {}, "No such file or directory"},
    {"truncated", [](const fs::path& p) { std::ofstream(p) << std::string(30, 'x'); },
     "truncated pack (30 bytes)"},
    {"a directory", [](const fs::path& p) { fs::create_directory(p); }, "not a regular file"},
    {"a FIFO", [](const fs::path& p) { ::mkfifo(p.c_str(), 0644); }, "not a regular file"},
    {"a dangling symlink", [](const fs::path& p) { fs::create_symlink("/nonexistent", p); },
     "No such file or directory"},
    {"truncated after its index was read", nullptr, "unexpected end of file"}};

// One process for every kind (each test process tiles the pyramid once), repaired in between.
TEST(SceneFaults, EachDamagedPackIsReportedOnceAndItsParentsAreDrawn) {
  const fs::path dir = globe::testing::freshTempDir("scene-faults");
  const SceneRun reference = view(globe::testing::bundledPyramid(), [](auto&) {});
  ASSERT_TRUE(reference.messages.empty()) << reference.messages;
  ASSERT_EQ(reference.nadirLevel, 14U);

  const fs::path pyramid = dir / "pyramid";
  fs::copy(globe::testing::bundledPyramid(), pyramid, fs::copy_options::recursive);
  const auto pose = fujiPose();
  const auto nadir = geo::GeographicTilingScheme::positionToTile(pose.position.longitudeRadians,
                                                                 pose.position.latitudeRadians, 14);
  ASSERT_TRUE(nadir);
  const formats::PackLayout layout;  // the bundled pyramid's
  const formats::PackId damaged = formats::packOf(*nadir, layout.tilesPerSide);
  const fs::path pack = formats::packPath(pyramid, damaged);
  fs::copy_file(pack, dir / "good.pack");
  auto inDamagedPack = [&](const TileId& t) {
    return t.level == damaged.level && formats::packOf(t, layout.tilesPerSide) == damaged;
  };
  ASSERT_GT(std::count_if(reference.tiles.begin(), reference.tiles.end(), inDamagedPack), 10)
      << "the reference view must draw the damaged pack's tiles";

  for (const Damage& damage : kDamages) {
    SCOPED_TRACE(std::string("the pack is ") + damage.name);
    if (damage.apply) {
      fs::remove(pack);
      damage.apply(pack);
    }
    ::alarm(120);  // a FIFO that blocked an open would hang the frame loop: fail instead
    const SceneRun run = view(pyramid, [&](TerrainScene& scene) {
      if (damage.apply) return;
      auto entry = scene.store().summary(*nadir);  // the viewer has read the pack's index
      ASSERT_TRUE(entry && *entry) << (entry ? "absent" : entry.error());
      // Every block is gone: the file ends where its index does (as its header says).
      std::ifstream in(pack, std::ios::binary);
      std::vector<std::byte> head(formats::kPackHeaderBytes);
      in.read(reinterpret_cast<char*>(head.data()), static_cast<std::streamsize>(head.size()));
      const auto indexEnd = formats::packIndexEndOffset(head);
      ASSERT_TRUE(indexEnd);
      fs::resize_file(pack, *indexEnd);
    });
    ::alarm(0);

    // One message naming the pack and the reason, after the view and kExtraFrames more frames.
    EXPECT_EQ(std::count(run.messages.begin(), run.messages.end(), '\n'), 1) << run.messages;
    EXPECT_EQ(run.messages.rfind(pack.string(), 0), 0U) << run.messages;
    EXPECT_NE(run.messages.find("; drawing coarser tiles there\n"), std::string::npos)
        << run.messages;
    EXPECT_NE(run.messages.find(damage.reason), std::string::npos) << run.messages;

    // Nothing of the damaged pack is drawn; each of its tiles is covered by an ancestor; every
    // other tile is drawn as before.
    EXPECT_TRUE(std::none_of(run.tiles.begin(), run.tiles.end(), inDamagedPack));
    for (const TileId& tile : reference.tiles) {
      const std::string name =
          std::to_string(tile.level) + "/" + std::to_string(tile.x) + "/" + std::to_string(tile.y);
      if (inDamagedPack(tile)) {
        EXPECT_TRUE(std::any_of(
            run.tiles.begin(), run.tiles.end(),
            [&](const TileId& d) { return d.level < tile.level && isAncestor(d, tile); }))
            << "hole where " << name << " was";
      } else {
        EXPECT_NE(std::find(run.tiles.begin(), run.tiles.end(), tile), run.tiles.end())
            << "undamaged tile " << name << " not drawn";
      }
    }
    // Collision still has the ground under the camera, from the parent level.
    EXPECT_TRUE(run.hasNadir);
    EXPECT_EQ(run.nadirLevel, 13U);

    fs::remove_all(pack);
    fs::copy_file(dir / "good.pack", pack);
  }
}

}  // namespace
}  // namespace globe::scene
