// Each imagery layer's exposure, chosen once its level-0 tiles are read: the dark Blue Marble is
// lifted to a readable median, the bright Landsat over Zion is left as photographed, a given
// exposure is kept, and night lights are never exposed.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "geo/ellipsoid.hpp"
#include "scene/imagery_layers.hpp"
#include "terrain/imagery_exposure.hpp"
#include "tests/support/bookkeeping_gpu.hpp"
#include "tests/support/imagery_test_layers.hpp"
#include "tests/support/inline_runner.hpp"

namespace globe::scene {
namespace {

std::vector<float> exposuresOf(const std::vector<LayerOptions>& layers) {
  globe::testing::InlineRunner runner;
  globe::testing::BookkeepingGpu gpu;
  auto opened = ImageryLayers::open(layers, runner, ImageryBudget{});
  EXPECT_TRUE(opened) << opened.error();
  if (!opened) return {};
  std::vector<terrain::TileDrapes> drapes;
  const auto frame = (*opened)->update({}, 17, 2.0, 30, glm::dvec3(7e6, 0.0, 0.0),
                                       geo::Ellipsoid::wgs84(), gpu, drapes);
  EXPECT_TRUE(frame) << frame.error();
  return (*opened)->exposures();
}

TEST(LayerExposure, DarkImageryIsLiftedAndBrightImageryLeftAsPhotographed) {
  LayerOptions blueMarble(globe::testing::blueMarbleLayer());
  LayerOptions landsat(globe::testing::zionLayer());
  const std::vector<float> chosen = exposuresOf({blueMarble, landsat});
  ASSERT_EQ(chosen.size(), 2u);
  EXPECT_GT(chosen[0], 1.3f) << "the Blue Marble's land and sea are dark (median ~0.1)";
  EXPECT_LE(chosen[0], terrain::kMaximumExposure);
  EXPECT_EQ(chosen[1], 1.0f) << "Zion's sandstone is bright";

  blueMarble.exposure = 1.0f;  // --exposure off
  landsat.exposure = 2.5f;     // --exposure 2.5
  LayerOptions lights(globe::testing::blueMarbleLayer());
  lights.night = true;
  EXPECT_EQ(exposuresOf({blueMarble, landsat, lights}), (std::vector<float>{1.0f, 2.5f, 1.0f}));
}

}  // namespace
}  // namespace globe::scene
