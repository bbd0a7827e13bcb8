// Tile URL templates and a service argument's own options.
#include <gtest/gtest.h>

#include "services/url_reader.hpp"
#include "services/url_template.hpp"

namespace {

using namespace globe::services;

TEST(UrlTemplate, XyzTmsRowsSubdomainsAndVersion) {
  const TileUrlValues v{3, 5, 1, "1.1.0", {"a", "b", "c"}};
  EXPECT_EQ(expandTileUrl("https://{s}.tile.example/{z}/{x}/{y}.png", v),
            "https://a.tile.example/3/5/1.png");  // (5 + 1) % 3
  EXPECT_EQ(expandTileUrl("/t/{z}/{x}/{-y}.png", v), "/t/3/5/6.png");
  EXPECT_EQ(expandTileUrl("{z}/{x}/{y}.terrain?v={version}", v), "3/5/1.terrain?v=1.1.0");
  // Unknown keys and an unclosed brace are left as they are.
  EXPECT_EQ(expandTileUrl("{z}/{q}/{x", v), "3/{q}/{x");
  const TileUrlValues noSubdomains{0, 0, 0, "", {}};
  EXPECT_EQ(expandTileUrl("{s}/{z}", noSubdomains), "{s}/0");
}

TEST(UrlTemplate, OwnOptionsAreTakenOutAndTheRestOfTheQueryStays) {
  std::string url = "https://h/{z}/{x}/{y}.png?maxzoom=12&key=abc&sea=none";
  auto options = takeQueryOptions(url, {"maxzoom", "sea"});
  EXPECT_EQ(url, "https://h/{z}/{x}/{y}.png?key=abc");
  EXPECT_EQ(options["maxzoom"], "12");
  EXPECT_EQ(options["sea"], "none");
  std::string plain = "/t/{z}.png?minzoom=3";
  EXPECT_EQ(takeQueryOptions(plain, {"minzoom"}).at("minzoom"), "3");
  EXPECT_EQ(plain, "/t/{z}.png");
  auto number = optionNumber({{"maxzoom", "99"}}, "maxzoom", 15, 24);
  ASSERT_FALSE(number);
  EXPECT_EQ(number.error(), "maxzoom=99: expected a whole number 0..24");
  EXPECT_FALSE(optionNumber({{"maxzoom", "1x"}}, "maxzoom", 15, 24));
  EXPECT_EQ(*optionNumber({}, "maxzoom", 15, 24), 15u);
}

TEST(UrlTemplate, ReferencesResolveBesideTheirFile) {
  EXPECT_EQ(resolveUrl("http://h:8/a/b/layer.json?x=1", "{z}/{x}/{y}.terrain"),
            "http://h:8/a/b/{z}/{x}/{y}.terrain");
  EXPECT_EQ(resolveUrl("http://h:8/a/b/layer.json", "/c/{z}.t"), "http://h:8/c/{z}.t");
  EXPECT_EQ(resolveUrl("http://h/a/layer.json", "https://o/{z}"), "https://o/{z}");
  EXPECT_EQ(resolveUrl("/data/qm/layer.json", "{z}/{x}/{y}.terrain"),
            "/data/qm/{z}/{x}/{y}.terrain");
  EXPECT_EQ(splitOrigin("https://a.b:9/c/d?e=f").first, "https://a.b:9");
  EXPECT_EQ(splitOrigin("https://a.b:9/c/d?e=f").second, "c/d?e=f");
  EXPECT_EQ(splitOrigin("/x/y.png?v=1").second, "x/y.png");
}

}  // namespace
