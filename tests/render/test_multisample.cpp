// Anti-aliasing (render/multisample_target.hpp): the globe's limb drawn through a multisampled
// target is resolved into partly covered pixels (blends of the ground and black space), where the
// single-sampled frame has only all or nothing; away from the limb the two frames agree.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "geo/ecef.hpp"
#include "render/multisample_target.hpp"
#include "tests/render/render_test_support.hpp"

namespace globe::render::test {
namespace {

class Multisample : public RenderTest {};

TEST_F(Multisample, TheLimbIsResolvedIntoPartlyCoveredPixels) {
  const auto tiles = loadTiles(3, -180, -90, 180, 90);
  upload(tiles);
  // Four earth radii from the centre, the Sun behind the camera: the limb is lit all round.
  const glm::dvec3 direction =
      geo::geodeticSurfaceNormal(kWgs84, geo::Cartographic::fromDegrees(20.0, 10.0, 0.0));
  const terrain::RenderView view =
      terrain::makeLookAtView(4.0 * kWgs84.semiMajorAxisMeters * direction, glm::dvec3(0.0),
                              glm::dvec3(0, 0, 1), geo::degreesToRadians(40.0), kWidth, kHeight,
                              direction);
  const Image single = drawAndRead(view, idsOf(tiles));

  auto target = MultisampleTarget::create(kWidth, kHeight, 4);
  ASSERT_TRUE(target) << target.error();
  EXPECT_GE((*target)->samples(), 2) << "llvmpipe offers 4 or more";
  EXPECT_LE((*target)->samples(), maximumSamples());
  (*target)->bind();
  renderer_->draw(view, idsOf(tiles));
  (*target)->resolve();
  const Image multi = readImage(kWidth, kHeight);
  savePng(multi, "multisample_limb");

  // Along the limb: pixels the single frame leaves black whose area the ground partly covers,
  // and covered ones darkened by the black around them.
  int gained = 0, dimmed = 0, limb = 0, interior = 0;
  double interiorDifference = 0;
  for (int y = 1; y + 1 < kHeight; ++y) {
    for (int x = 1; x + 1 < kWidth; ++x) {
      bool nearSpace = false, nearGround = false;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          (single.isBackground(x + dx, y + dy) ? nearSpace : nearGround) = true;
        }
      }
      if (nearSpace && nearGround) {
        ++limb;
        if (single.isBackground(x, y) && !multi.isBackground(x, y)) ++gained;
        if (!single.isBackground(x, y) && multi.luminance(x, y) < 0.9 * single.luminance(x, y))
          ++dimmed;
      } else if (nearGround) {
        ++interior;
        interiorDifference += std::abs(multi.luminance(x, y) - single.luminance(x, y));
      }
    }
  }
  ASSERT_GT(limb, 300);
  EXPECT_GT(gained, limb / 10) << "limb " << limb;
  EXPECT_GT(dimmed, limb / 10) << "limb " << limb << ", dimmed " << dimmed;
  std::printf("limb %d pixels: %d gained, %d dimmed\n", limb, gained, dimmed);
  EXPECT_LT(interiorDifference / interior, 2.0) << "the inside is not blurred";
}

TEST_F(Multisample, OneSampleAndAResizeWork) {
  auto target = MultisampleTarget::create(kWidth, kHeight, 1);
  ASSERT_TRUE(target) << target.error();
  EXPECT_EQ((*target)->samples(), 1);
  auto many = MultisampleTarget::create(kWidth, kHeight, 1000);
  ASSERT_TRUE(many) << many.error();
  EXPECT_EQ((*many)->samples(), maximumSamples()) << "clamped to what the GL offers";
  ASSERT_TRUE((*many)->resize(100, 50));
  EXPECT_EQ((*many)->widthPixels(), 100);
  EXPECT_EQ((*many)->heightPixels(), 50);
  (*many)->bind();
  glClearColor(0.0f, 1.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  (*many)->resolve();
  const Image image = readImage(kWidth, kHeight);
  EXPECT_EQ(image.at(10, kHeight - 10)[1], 255) << "the resolved rectangle, bottom left";
  EXPECT_EQ(image.at(200, 10)[1], 0) << "outside the 100x50 target nothing was written";
}

}  // namespace
}  // namespace globe::render::test
