// `globe query`: the real program as a height service on the bundled pyramid.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/build_paths.hpp"
#include "tests/support/sea_test_pyramid.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace {

struct Answer {
  int exitCode;
  std::vector<std::vector<double>> rows;  // lon, lat, level, height
  std::string errors;
};

Answer queryPyramid(const std::filesystem::path& pyramid, const std::string& input,
                    const std::string& options) {
  const auto dir = globe::testing::freshTempDir("query");
  { std::ofstream(dir / "in.txt") << input; }
  const std::string command = std::string(GLOBE_EXE) + " query " + pyramid.string() + " " +
                              options + " < " + (dir / "in.txt").string() + " > " +
                              (dir / "out.txt").string() + " 2> " + (dir / "err.txt").string();
  const int status = std::system(command.c_str());
  Answer answer{WIFEXITED(status) ? WEXITSTATUS(status) : -1, {}, {}};
  std::ifstream out(dir / "out.txt");
  for (std::string line; std::getline(out, line);) {
    std::vector<double> row;
    std::stringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) row.push_back(std::stod(field));
    answer.rows.push_back(row);
  }
  std::stringstream errors;
  errors << std::ifstream(dir / "err.txt").rdbuf();
  answer.errors = errors.str();
  return answer;
}

Answer query(const std::string& input, const std::string& options = "") {
  return queryPyramid(globe::testing::bundledPyramid(), input, options);
}

TEST(GlobeQuery, FujiSummitFromTheFinestLevelQotcdAboveExact) {
  const Answer qotcd = query("138.7275,35.3606\n");
  const Answer exact = query("138.7275,35.3606\n", "--mode exact");
  ASSERT_EQ(qotcd.exitCode, 0) << qotcd.errors;
  ASSERT_EQ(exact.exitCode, 0) << exact.errors;
  ASSERT_EQ(qotcd.rows.size(), 1u);
  EXPECT_EQ(qotcd.rows[0][2], 14);  // the 3″ SRTM level
  EXPECT_GT(qotcd.rows[0][3], 3700);
  EXPECT_LT(qotcd.rows[0][3], 3777);
  EXPECT_GE(qotcd.rows[0][3], exact.rows[0][3]);  // conservative
  EXPECT_GT(exact.rows[0][3], 3700);
}

TEST(GlobeQuery, LevelOptionPolesAntimeridianAndEngland) {
  const Answer a =
      query("138.7275,35.3606\n0,90\n45,90\n0,-90\n180,-17\n-180,-17\n-1.0,53.0\n", "");
  ASSERT_EQ(a.exitCode, 0) << a.errors;
  ASSERT_EQ(a.rows.size(), 7u);
  EXPECT_EQ(a.rows[1][3], a.rows[2][3]);  // the pole is one point
  EXPECT_GT(a.rows[3][3], 2000);          // the south pole is on the ice sheet
  EXPECT_EQ(a.rows[4][3], a.rows[5][3]);  // +180 and -180 are one meridian
  EXPECT_EQ(a.rows[6][2], 11);            // the 30″ GTOPO30 crop of England
  const Answer coarse = query("138.7275,35.3606\n", "--level 6");
  ASSERT_EQ(coarse.exitCode, 0) << coarse.errors;
  EXPECT_EQ(coarse.rows[0][2], 6);
  EXPECT_LT(coarse.rows[0][3], 3000);  // 20′ data smooths the summit away
}

TEST(GlobeQuery, BadLinesAreNamedAndGiveANonZeroExit) {
  const Answer a = query("nan,nan\n138.7,35.3\n12\n1,95\ninf,0\n");
  EXPECT_EQ(a.exitCode, 1);
  EXPECT_EQ(a.rows.size(), 1u);  // the good line is still answered
  EXPECT_NE(a.errors.find("line 1: 'nan,nan': longitude is not a finite number"), std::string::npos)
      << a.errors;
  EXPECT_NE(a.errors.find("line 3: '12'"), std::string::npos) << a.errors;
  EXPECT_NE(a.errors.find("line 4: '1,95': latitude"), std::string::npos) << a.errors;
  EXPECT_NE(a.errors.find("line 5"), std::string::npos) << a.errors;
  const Answer badLevel = query("0,0\n", "--level 40");
  EXPECT_EQ(badLevel.exitCode, 1);
  EXPECT_NE(badLevel.errors.find("levels are 0..14"), std::string::npos) << badLevel.errors;
}

// Water is 0 m by default and its sea floor with --sea-floor, in both modes; land below sea level
// and water of unknown depth read the same either way. Queried at cell centres whose four
// vertices agree (a cell's chord sags 6 cm there: the exact mode is a hair lower).
TEST(GlobeQuery, SeaFloorOptionReadsTheFloorUnderWater) {
  namespace sea = globe::testing;
  const auto pyramid = globe::testing::freshTempDir("query-sea") / "pyramid";
  ASSERT_TRUE(sea::writeSeaTestPyramid(pyramid));
  struct Place {
    globe::geo::TileId tile;
    uint32_t row, column;
    double water, floor;
  };
  const Place places[] = {
      {sea::kSeaTile, 7, 7, 0, sea::kSeaFloorMeters},
      {sea::kMixedTile, 6, 1, 0, sea::kSeaFloorMeters},
      {sea::kMixedTile, 6, 5, 0, 0},
      {sea::kMixedTile, 6, 9, sea::kMixedLandBelowSeaLevelMeters,
       sea::kMixedLandBelowSeaLevelMeters},
      {sea::kMixedTile, 6, 13, sea::kMixedLandMeters, sea::kMixedLandMeters},
  };
  std::string input;
  char line[128];
  for (const Place& p : places) {
    const auto centre = sea::cellCentreDegrees(p.tile, p.row, p.column);
    std::snprintf(line, sizeof line, "%.17g,%.17g\n", centre.longitude, centre.latitude);
    input += line;
  }
  input += "100,-60\n";  // only level 0 there: water of unknown depth
  for (const char* mode : {"qotcd", "exact"}) {
    const std::string options = std::string("--mode ") + mode;
    const Answer water = queryPyramid(pyramid, input, options);
    const Answer floor = queryPyramid(pyramid, input, options + " --sea-floor");
    ASSERT_EQ(water.exitCode, 0) << water.errors;
    ASSERT_EQ(floor.exitCode, 0) << floor.errors;
    ASSERT_EQ(water.rows.size(), std::size(places) + 1);
    ASSERT_EQ(floor.rows.size(), std::size(places) + 1);
    for (size_t k = 0; k < std::size(places); ++k) {
      SCOPED_TRACE(std::string(mode) + " place " + std::to_string(k));
      EXPECT_EQ(water.rows[k][2], 10);
      EXPECT_NEAR(water.rows[k][3], places[k].water, 0.1);
      EXPECT_NEAR(floor.rows[k][3], places[k].floor, 0.1);
    }
    // Level 0 only (exact: 11.25 deg cells, whose chords pass ~30 km below the ellipsoid).
    EXPECT_EQ(water.rows.back()[2], 0);
    if (std::string(mode) == "qotcd") {
      EXPECT_EQ(water.rows.back()[3], 0);
    }
    EXPECT_EQ(floor.rows.back()[3], water.rows.back()[3]);
  }
}

}  // namespace
