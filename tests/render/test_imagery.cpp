// Image files (io/image_io) and the imagery drape: the NASA Blue Marble on the real terrain.
#include <gtest/gtest.h>

#include <fstream>

#include "formats/image_io.hpp"
#include "geo/ecef.hpp"
#include "tests/render/render_test_support.hpp"
#include "tests/support/build_paths.hpp"

namespace globe::render::test {
namespace {

const std::filesystem::path kBlueMarble =
    std::filesystem::path(GLOBE_SOURCE_DIR) / "tests/data/imagery/bmng-world-2048x1024.jpg";

TEST(ImageIo, PngRoundTripAndClearErrors) {
  const auto dir = outputDirectory();
  formats::ImageRgba image{3, 2, {}};
  for (int k = 0; k < 3 * 2 * 4; ++k) image.pixels.push_back(static_cast<uint8_t>(k * 10));
  const auto path = dir / "image_io_round_trip.png";
  ASSERT_TRUE(formats::writePngAtomically(path, image.pixels, 3, 2).ok());
  auto back = formats::loadImageRgba(path);
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(back->widthPixels, 3);
  EXPECT_EQ(back->heightPixels, 2);
  EXPECT_EQ(back->pixels, image.pixels);

  auto wrongSize = formats::writePngAtomically(dir / "never.png", image.pixels, 4, 2);
  ASSERT_FALSE(wrongSize.ok());
  EXPECT_NE(wrongSize.error().find("never.png"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "never.png"));

  auto missing = formats::loadImageRgba(dir / "no-such-image.jpg");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().find("no-such-image.jpg"), std::string::npos);

  const auto garbage = dir / "garbage.jpg";
  std::ofstream(garbage) << "this is not a JPEG";
  auto undecodable = formats::loadImageRgba(garbage);
  ASSERT_FALSE(undecodable.ok());
  EXPECT_NE(undecodable.error().find("garbage.jpg: not a readable image"), std::string::npos)
      << undecodable.error();
}

class Imagery : public RenderTest {};

TEST_F(Imagery, BlueMarbleDrapesOverTheGlobe) {
  ASSERT_TRUE(std::filesystem::exists(kBlueMarble)) << kBlueMarble << " is missing";
  auto image = formats::loadImageRgba(kBlueMarble);
  ASSERT_TRUE(image.ok()) << image.error();
  EXPECT_EQ(image->widthPixels, 2048);
  EXPECT_EQ(image->heightPixels, 1024);
  ASSERT_TRUE(renderer_->setImagery(image->pixels, image->widthPixels, image->heightPixels).ok());

  const auto tiles = loadTiles(3, -180, -90, 180, 90);
  upload(tiles);
  const glm::dvec3 direction =
      geo::geodeticSurfaceNormal(kWgs84, geo::Cartographic::fromDegrees(20.0, 10.0, 0.0));
  const terrain::RenderView view = terrain::makeLookAtView(
      3.2 * kWgs84.semiMajorAxisMeters * direction, glm::dvec3(0.0), glm::dvec3(0, 0, 1),
      geo::degreesToRadians(45.0), kWidth, kHeight, direction);
  const Image draped = drawAndRead(view, idsOf(tiles));
  savePng(draped, "globe_blue_marble");

  auto colourAt = [&](double lon, double lat) {
    const auto pixel = projectToPixel(
        view, geo::cartographicToEcef(kWgs84, geo::Cartographic::fromDegrees(lon, lat, 0.0)));
    EXPECT_TRUE(pixel.has_value());
    return draped.meanRgb(static_cast<int>(pixel->x), static_cast<int>(pixel->y), 2);
  };
  const auto sahara = colourAt(15.0, 23.0);      // sand: red over blue
  const auto atlantic = colourAt(-10.0, -10.0);  // deep ocean: dark blue
  const auto congo = colourAt(22.0, 0.0);        // rain forest: green over blue
  EXPECT_GT(sahara[0], sahara[2] + 30) << sahara[0] << " " << sahara[2];
  EXPECT_GT(atlantic[2], atlantic[0] + 10) << atlantic[0] << " " << atlantic[2];
  EXPECT_GT(congo[1], congo[2]) << congo[1] << " " << congo[2];

  // The same frame without the drape uses the hypsometric ramp: the Sahara turns green-tan.
  TerrainStyle style = renderer_->style();
  style.drapeImagery = false;
  renderer_->setStyle(style);
  const Image ramp = drawAndRead(view, idsOf(tiles));
  savePng(ramp, "globe_hypsometric");
  EXPECT_NE(ramp.rgba, draped.rgba);
}

}  // namespace
}  // namespace globe::render::test
