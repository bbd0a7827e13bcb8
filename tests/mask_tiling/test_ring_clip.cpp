// Clipping rings to a tile's rectangle: what is inside is kept exactly, what runs outside runs
// along the sides, and a ring that only runs along the sides is recognised.
#include <gtest/gtest.h>

#include <cmath>

#include "mask_tiling/ring_clip.hpp"

namespace globe::mask_tiling {
namespace {

const RectangleDegrees kBox{0, 0, 10, 10};

double area(const Ring& ring) {
  double twice = 0;
  for (size_t i = 0; i < ring.size(); ++i) {
    const glm::dvec2 a = ring[i], b = ring[(i + 1) % ring.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return std::abs(twice) / 2;
}

TEST(RingClip, ARingInsideIsKeptAsItIs) {
  const Ring ring{{2, 2}, {4, 2}, {3, 5}};
  EXPECT_EQ(clipRing(ring, kBox), ring);
  EXPECT_FALSE(runsAlongSides(clipRing(ring, kBox), kBox));
}

TEST(RingClip, ARingOutsideVanishes) {
  EXPECT_TRUE(clipRing({{12, 2}, {14, 2}, {13, 5}}, kBox).empty());
  EXPECT_TRUE(clipRing({{1, 1}, {2, 2}}, kBox).empty());  // not a ring
}

TEST(RingClip, ARingAcrossASideIsCutOnIt) {
  // A square from x = 5 to 15: the half inside is left, its new edge on x = 10.
  const Ring clipped = clipRing({{5, 2}, {15, 2}, {15, 8}, {5, 8}}, kBox);
  EXPECT_DOUBLE_EQ(area(clipped), 30.0);
  for (const glm::dvec2& p : clipped) EXPECT_LE(p.x, 10.0);
  EXPECT_FALSE(runsAlongSides(clipped, kBox));
}

TEST(RingClip, ARingAroundTheBoxBecomesTheBox) {
  const Ring clipped = clipRing({{-5, -5}, {15, -5}, {15, 15}, {-5, 15}}, kBox);
  EXPECT_DOUBLE_EQ(area(clipped), 100.0);
  EXPECT_TRUE(runsAlongSides(clipped, kBox));
}

TEST(RingClip, AHookAroundACornerLeavesATraceWithoutArea) {
  // An L-shaped ring wrapping round the box's north-west corner without entering it.
  const Ring hook{{-5, -5}, {-1, -5}, {-1, 11}, {15, 11}, {15, 15}, {-5, 15}};
  const Ring clipped = clipRing(hook, kBox);
  EXPECT_NEAR(area(clipped), 0.0, 1e-12);
  EXPECT_TRUE(runsAlongSides(clipped, kBox));
}

TEST(RingClip, ADiagonalCutAcrossACornerIsAShoreline) {
  // Land south-west of the line x + y = 5: its clipped edge crosses the box's inside.
  const Ring clipped = clipRing({{-5, -5}, {10, -5}, {-5, 10}}, kBox);
  EXPECT_DOUBLE_EQ(area(clipped), 12.5);
  EXPECT_FALSE(runsAlongSides(clipped, kBox));
}

}  // namespace
}  // namespace globe::mask_tiling
