// Named sources: the presets, a user's sources.toml (new names, a preset replaced, mistakes named
// with their line), and the real `globe` resolving names, listing them and stamping attribution.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "formats/image_io.hpp"
#include "services/named_sources.hpp"
#include "tests/apps/globe/run_globe.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace {

namespace fs = std::filesystem;
using namespace globe::services;

const fs::path kTileSetsDir = fs::path(GLOBE_SOURCE_DIR) / "tests/data/interop";

TEST(NamedSources, PresetsCoverTheOpenServices) {
  auto sources = loadNamedSources(globe::testing::freshTempDir("no-sources") / "sources.toml");
  ASSERT_TRUE(sources) << sources.error();
  EXPECT_FALSE(sources->fileRead);
  for (const char* name : {"aws-terrain", "osm", "gibs", "s2cloudless"}) {
    auto found = findNamedSource(
        *sources, name,
        std::string(name) == "aws-terrain" ? SourceKind::Terrain : SourceKind::Imagery);
    ASSERT_TRUE(found && *found) << name;
    EXPECT_FALSE((*found)->attribution.empty()) << name;
  }
  auto wrong = findNamedSource(*sources, "osm", SourceKind::Terrain);
  ASSERT_FALSE(wrong);
  EXPECT_EQ(wrong.error(), "osm is an imagery source, not terrain (give it with --layer)");
  auto none = findNamedSource(*sources, "./somewhere", SourceKind::Terrain);
  ASSERT_TRUE(none);
  EXPECT_FALSE(*none);
}

TEST(NamedSources, AUsersFileAddsAndReplacesAndItsMistakesAreNamed) {
  const fs::path dir = globe::testing::freshTempDir("sources");
  std::ofstream(dir / "sources.toml") << "# mine\n[my-terrain]\nkind = \"terrain\"\n"
                                         "url = \"quantized-mesh:https://example.org/qm\"\n"
                                         "attribution = \"Me\"\n\n[osm]\nkind = \"imagery\"\n"
                                         "url = \"xyz:https://tiles.example/{z}/{x}/{y}.png\"\n";
  auto sources = loadNamedSources(dir / "sources.toml");
  ASSERT_TRUE(sources) << sources.error();
  EXPECT_TRUE(sources->fileRead);
  auto mine = findNamedSource(*sources, "my-terrain", SourceKind::Terrain);
  ASSERT_TRUE(mine && *mine);
  EXPECT_EQ((*mine)->url, "quantized-mesh:https://example.org/qm");
  EXPECT_FALSE((*mine)->preset);
  auto osm = findNamedSource(*sources, "osm", SourceKind::Imagery);
  ASSERT_TRUE(osm && *osm);
  EXPECT_EQ((*osm)->url, "xyz:https://tiles.example/{z}/{x}/{y}.png");

  std::ofstream(dir / "bad.toml") << "[a]\nkind = \"imagery\"\nurl = \"x\"\n[b\n";
  auto bad = loadNamedSources(dir / "bad.toml");
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().rfind((dir / "bad.toml").string() + ":4: ", 0), 0u) << bad.error();
  std::ofstream(dir / "kind.toml") << "[a]\nkind = \"maps\"\nurl = \"x\"\n";
  auto kind = loadNamedSources(dir / "kind.toml");
  ASSERT_FALSE(kind);
  EXPECT_EQ(kind.error(),
            (dir / "kind.toml").string() + ": [a]: kind must be \"terrain\" or \"imagery\"");
  std::ofstream(dir / "url.toml") << "[a]\nkind = \"imagery\"\n";
  EXPECT_FALSE(loadNamedSources(dir / "url.toml"));
}

TEST(NamedSources, TheProgramResolvesNamesAndStampsTheirAttribution) {
  const fs::path dir = globe::testing::freshTempDir("sources-app");
  fs::create_directories(dir / "globe");
  std::ofstream(dir / "globe/sources.toml")
      << "[texel]\nkind = \"terrain\"\nurl = \"quantized-mesh:"
      << (kTileSetsDir / "quantized-mesh/texel-ahn4").string()
      << "\"\n\n[ne2]\nkind = \"imagery\"\n"
      << "url = \"tms:" << (kTileSetsDir / "raster-tiles/tms-geodetic-naturalearth2").string()
      << "\"\nattribution = \"Natural Earth II\"\n";
  ::setenv("XDG_CONFIG_HOME", dir.c_str(), 1);
  const auto list = globe::app::test::runGlobe("sources");
  EXPECT_EQ(list.exitCode, 0) << list.output;
  EXPECT_NE(list.output.find((dir / "globe/sources.toml").string() + " (read)"), std::string::npos)
      << list.output;
  EXPECT_NE(list.output.find("ne2            imagery  tms:"), std::string::npos) << list.output;

  const std::string view =
      "snapshot texel --layer ne2 --camera 4.8,52.5,400000,0,-50,0 "
      "--size 320x200 -o ";
  const auto with = globe::app::test::runGlobe(view + (dir / "with.png").string());
  ASSERT_EQ(with.exitCode, 0) << with.output;
  const auto without =
      globe::app::test::runGlobe(view + (dir / "without.png").string() + " --no-attribution");
  ASSERT_EQ(without.exitCode, 0) << without.output;
  const auto a = globe::formats::loadImageRgba(dir / "with.png").value();
  const auto b = globe::formats::loadImageRgba(dir / "without.png").value();
  // The stamp's text, at the bottom right and nowhere else.
  size_t inCorner = 0, elsewhere = 0;
  for (int y = 0; y < 200; ++y) {
    for (int x = 0; x < 320; ++x) {
      const size_t p = (static_cast<size_t>(y) * 320 + x) * 4;
      if (a.pixels[p] == b.pixels[p] && a.pixels[p + 1] == b.pixels[p + 1]) continue;
      (x > 160 && y > 170 ? inCorner : elsewhere) += 1;
    }
  }
  EXPECT_GT(inCorner, 100u);
  EXPECT_EQ(elsewhere, 0u);

  const auto mismatch =
      globe::app::test::runGlobe("snapshot ne2 --camera 0,0,1e7 -o " + (dir / "x.png").string());
  EXPECT_NE(mismatch.exitCode, 0) << mismatch.output;
  EXPECT_NE(mismatch.output.find("ne2 is an imagery source, not terrain (give it with --layer)"),
            std::string::npos)
      << mismatch.output;
  ::unsetenv("XDG_CONFIG_HOME");
}

}  // namespace
