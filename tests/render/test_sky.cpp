// The sky: its model (render/sky_model.hpp) behaves as designed at every height, and the sky pass
// draws that model: the zenith, the horizon and space, read back from real OSMesa frames.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>

#include "geo/cartographic.hpp"
#include "geo/ecef.hpp"
#include "render/sky_model.hpp"
#include "tests/render/render_test_support.hpp"

namespace globe::render::test {
namespace {

constexpr double kRadius = 6'371'000.0;

float luminance(const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

TEST(SkyModel, DarkensUpwardsAndTurnsToSpace) {
  const SkyParameters ground = skyAt(0.0, kRadius), tenKm = skyAt(10'000.0, kRadius),
                      high = skyAt(40'000.0, kRadius), space = skyAt(2e7, kRadius);
  EXPECT_GT(luminance(ground.zenithRgb), luminance(tenKm.zenithRgb));
  EXPECT_GT(luminance(tenKm.zenithRgb), luminance(high.zenithRgb));
  EXPECT_EQ(luminance(space.zenithRgb), 0.0f);
  EXPECT_GT(ground.zenithRgb.b, ground.zenithRgb.r);                     // blue
  EXPECT_GT(luminance(ground.horizonRgb), luminance(ground.zenithRgb));  // pale haze below
  EXPECT_EQ(ground.spaceBlend, 0.0f);
  EXPECT_EQ(tenKm.spaceBlend, 0.0f);
  EXPECT_EQ(space.spaceBlend, 1.0f);
  // The horizon dips as the camera rises: ~3.2° at 10 km.
  EXPECT_EQ(ground.horizonCosine, 0.0f);
  EXPECT_NEAR(std::acos(tenKm.horizonCosine) * 180 / 3.141592653589793, 90.0 + 3.2, 0.05);
  // Fog: strongest near the ground, none from space.
  EXPECT_GT(ground.fogMaximum, tenKm.fogMaximum);
  EXPECT_GT(tenKm.fogMaximum, 0.0f);
  EXPECT_EQ(space.fogMaximum, 0.0f);
}

// Under the real Sun: day's sky and full light with the Sun up, twilight in between, the night's
// floor (and a near-black sky, the fog with it) once the Sun is well below the horizon.
TEST(SkyModel, TheSunsHeightDarkensTheSkyAndTheGround) {
  const double degree = std::acos(-1.0) / 180;
  const SkyParameters day = skyAt(1000.0, 6'371'000.0);
  const SkyParameters noon = skyUnderSun(day, std::sin(60 * degree));
  EXPECT_EQ(noon.zenithRgb, day.zenithRgb);
  EXPECT_EQ(noon.horizonRgb, day.horizonRgb);
  EXPECT_EQ(daylight(std::sin(60 * degree)), 1.0f);
  const SkyParameters dusk = skyUnderSun(day, std::sin(-3 * degree));
  const SkyParameters night = skyUnderSun(day, std::sin(-30 * degree));
  EXPECT_LT(dusk.horizonRgb.b, day.horizonRgb.b);
  EXPECT_GT(dusk.horizonRgb.b, night.horizonRgb.b);
  EXPECT_LT(night.zenithRgb.r + night.zenithRgb.g + night.zenithRgb.b, 0.05f);
  EXPECT_LT(night.horizonRgb.g, 0.05f) << "the fog darkens with the sky";
  EXPECT_EQ(daylight(std::sin(-30 * degree)), kNightLight);
  const float twilight = daylight(std::sin(-1 * degree));
  EXPECT_GT(twilight, kNightLight);
  EXPECT_LT(twilight, 1.0f);
  for (double c = -1; c <= 1; c += 0.01) {
    EXPECT_LE(daylight(c), daylight(c + 0.01)) << "brighter as the Sun rises";
  }
  EXPECT_EQ(daylight(std::numeric_limits<double>::quiet_NaN()), 1.0f);
}

TEST(SkyModel, NeverNaNWhateverTheHeight) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const double h : {0.0, 1e-3, -100.0, 1e9, 1e300, nan, inf, -inf}) {
    const SkyParameters s = skyAt(h, kRadius);
    for (const float v :
         {s.zenithRgb.r, s.zenithRgb.g, s.zenithRgb.b, s.horizonRgb.r, s.horizonRgb.g,
          s.horizonRgb.b, s.spaceBlend, s.horizonCosine, s.fogDensityPerMeter, s.fogMaximum}) {
      EXPECT_TRUE(std::isfinite(v)) << h;
    }
    EXPECT_GE(s.horizonCosine, -1.0f);
    EXPECT_LE(s.horizonCosine, 0.0f);
  }
  EXPECT_EQ(skyAt(-100.0, kRadius).zenithRgb, skyAt(0.0, kRadius).zenithRgb);  // under: as 0 m
}

class SkyPassTest : public RenderTest {
 protected:
  // The colour at the image centre looking from `heightMeters` above (0°, 0°) in `direction`
  // (east-north-up), nothing but the sky drawn.
  // With `sun`: lit by the real Sun from that direction (ECEF), as --time does.
  std::array<uint8_t, 4> centre(double heightMeters, const glm::dvec3& enu,
                                std::optional<glm::dvec3> sun = std::nullopt) {
    TerrainStyle style = renderer_->style();
    style.sky = true;
    renderer_->setStyle(style);
    const LocalFrame f = localFrame(0.0, 0.0);
    const glm::dvec3 eye = geo::cartographicToEcef(kWgs84, {0.0, 0.0, heightMeters});
    const glm::dvec3 direction = enu.x * f.east + enu.y * f.north + enu.z * f.up;
    const glm::dvec3 screenUp = std::abs(enu.z) > 0.9 ? f.north : f.up;
    terrain::RenderView view =
        terrain::makeLookAtView(eye, eye + 1000.0 * direction, screenUp,
                                geo::degreesToRadians(30.0), kWidth, kHeight, sun.value_or(f.up));
    view.sunIsReal = sun.has_value();
    const Image image = drawAndRead(view, {});
    return image.at(kWidth / 2, kHeight / 2);
  }
  static void expectColour(const std::array<uint8_t, 4>& pixel, const glm::vec3& rgb) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(pixel[c], 255.0 * rgb[c], 3.0) << "channel " << c;
  }
};

TEST_F(SkyPassTest, DrawsTheZenithAndTheHorizonOfTheModel) {
  const double radius = 6'378'137.0;  // at the equator the WGS84 surface lies at a
  expectColour(centre(100.0, {0, 0, 1}), skyAt(100.0, radius).zenithRgb);
  expectColour(centre(10'000.0, {0, 0, 1}), skyAt(10'000.0, radius).zenithRgb);
  // Straight along the horizon from the ground: the horizon's haze.
  expectColour(centre(0.5, {0, 1, 0}), skyAt(0.5, radius).horizonRgb);
}

TEST_F(SkyPassTest, SpaceIsBlackAwayFromTheGlobeAndGlowsAtItsLimb) {
  // 20,000 km up, looking away from the globe: black.
  const auto away = centre(2e7, {0, 0, 1});
  EXPECT_EQ(away[0] + away[1] + away[2], 0);
  // Looking down past the limb: the ray grazes the air, a bluish glow.
  const double h = 2e7, r = 6'378'137.0;
  const double limbAngle = std::asin(r / (r + h));  // from straight down to the limb
  const double pastLimb = limbAngle + 0.002;        // a little above it: ~50 km above the surface
  const auto glow = centre(h, {0, std::sin(pastLimb), -std::cos(pastLimb)});
  EXPECT_GT(glow[2], 40);
  EXPECT_GT(glow[2], glow[0]);
  // Under the real Sun the glow is the lit air's: that limb (north of the camera) glows with the
  // Sun over the north, and is dark with it over the south, where its air is in the night.
  const glm::dvec3 north(0.0, 0.0, 1.0);
  const auto lit = centre(h, {0, std::sin(pastLimb), -std::cos(pastLimb)}, north);
  const auto night = centre(h, {0, std::sin(pastLimb), -std::cos(pastLimb)}, -north);
  EXPECT_GT(lit[2], 40);
  EXPECT_EQ(night[0] + night[1] + night[2], 0) << int{night[2]};
}

// Under the real Sun the pass draws the physically based sky (atmosphere/sky_view.hpp): from
// 100 m, blue overhead with the Sun high, and towards a Sun on the horizon a horizon redder than
// blue and a darker zenith; without a real Sun the model's gradient as before.
TEST_F(SkyPassTest, UnderTheRealSunTheSkyIsPhysical) {
  const LocalFrame f = localFrame(0.0, 0.0);
  const glm::dvec3 highSun = glm::normalize(f.up + 0.3 * f.north);
  const auto noon = centre(100.0, {0, 0, 1}, highSun);
  EXPECT_GT(noon[2], noon[1]);
  EXPECT_GT(noon[1], noon[0]);
  EXPECT_GT(noon[2], 120);
  const glm::dvec3 setting = glm::normalize(f.north + 0.005 * f.up);
  const auto sunsetHorizon = centre(100.0, {0, 1, 0.03}, setting);
  const auto sunsetZenith = centre(100.0, {0, 0, 1}, setting);
  EXPECT_GT(sunsetHorizon[0], sunsetHorizon[2]) << "red towards the setting Sun";
  EXPECT_LT(sunsetZenith[2], noon[2]) << "a darker zenith";
  // Without --time: exactly the model's zenith, as the goldens have it.
  expectColour(centre(100.0, {0, 0, 1}), skyAt(100.0, 6'378'137.0).zenithRgb);
}

}  // namespace
}  // namespace globe::render::test
