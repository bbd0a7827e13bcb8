// --layer's text: a directory alone, with an opacity, a service URL whose query holds commas, and
// the mistakes, each refused naming the argument.
#include <gtest/gtest.h>

#include "apps/globe/layer_argument.hpp"

namespace globe::app {
namespace {

TEST(LayerArgument, DirectoryAndOpacity) {
  auto plain = parseLayerArgument("data/imagery/zion");
  ASSERT_TRUE(plain) << plain.error();
  EXPECT_EQ(plain->directory, "data/imagery/zion");
  EXPECT_EQ(plain->opacity, 1.0f);
  auto half = parseLayerArgument("layers/a,b,0.5");
  ASSERT_TRUE(half) << half.error();
  EXPECT_EQ(half->directory, "layers/a,b") << "only the last comma separates the opacity";
  EXPECT_EQ(half->opacity, 0.5f);
  EXPECT_EQ(parseLayerArgument("x,0")->opacity, 0.0f);
  EXPECT_EQ(parseLayerArgument("x,1")->opacity, 1.0f);
}

TEST(LayerArgument, ServiceUrlKeepsItsCommas) {
  const std::string url = "xyz:https://example.org/{z}/{x}/{y}.png?bounds=-10,40,5,50";
  auto whole = parseLayerArgument(url);
  ASSERT_TRUE(whole) << whole.error();
  EXPECT_EQ(whole->directory, url);
  auto faded = parseLayerArgument(url + ",0.25");
  ASSERT_TRUE(faded) << faded.error();
  EXPECT_EQ(faded->directory, url);
  EXPECT_EQ(faded->opacity, 0.25f);
  auto endsInFraction = parseLayerArgument("xyz:https://example.org/t?bounds=0,0,1,0.5,1");
  ASSERT_TRUE(endsInFraction) << endsInFraction.error();
  EXPECT_EQ(endsInFraction->directory, "xyz:https://example.org/t?bounds=0,0,1,0.5");
  EXPECT_EQ(endsInFraction->opacity, 1.0f);
}

TEST(LayerArgument, MistakesNameTheArgument) {
  for (const std::string bad : {"dir,1.5", "dir,-0.1", "dir,half", "dir,", "dir,nan", ",0.5"}) {
    auto layer = parseLayerArgument(bad);
    ASSERT_FALSE(layer) << bad;
    EXPECT_NE(layer.error().find("--layer " + bad), std::string::npos) << layer.error();
  }
}

}  // namespace
}  // namespace globe::app
