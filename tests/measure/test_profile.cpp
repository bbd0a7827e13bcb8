// Lines from the files people have (a real GPX track and route, the route as GeoJSON, KML),
// geodesic lengths and areas against known values, and `globe profile` over the bundled pyramid:
// its samples' heights are `globe query --mode exact`'s, its length the geodesics', its chart
// (--png) filled highest where the summit is.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "formats/image_io.hpp"
#include "measure/chart_axis.hpp"
#include "measure/elevation_profile.hpp"
#include "measure/geodesic_path.hpp"
#include "measure/path_files.hpp"
#include "measure/profile_chart.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/command_run.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::measure {
namespace {

namespace fs = std::filesystem;
const fs::path kPaths = fs::path(GLOBE_SOURCE_DIR) / "tests/data/interop/paths";

using Exit = globe::testing::CommandExit;
using globe::testing::runCommand;

std::vector<std::vector<double>> csvRows(const std::string& text) {
  std::vector<std::vector<double>> rows;
  std::istringstream lines(text);
  std::string line;
  std::getline(lines, line);  // header
  while (std::getline(lines, line)) {
    std::vector<double> row;
    std::istringstream fields(line);
    std::string field;
    while (std::getline(fields, field, ',')) row.push_back(std::stod(field));
    rows.push_back(row);
  }
  return rows;
}

TEST(PathFiles, AGpxTrackARouteAndItsGeoJsonTwin) {
  auto track = readPathFile(kPaths / "Mojstrovka.gpx");
  ASSERT_TRUE(track) << track.error();
  EXPECT_EQ(track->size(), 184u);
  EXPECT_NEAR(track->front().latitudeDegrees, 46.434981, 1e-9);
  EXPECT_NEAR(track->front().elevationMeters, 1614.678, 1e-9);
  auto route = readPathFile(kPaths / "trek.gpx");
  ASSERT_TRUE(route) << route.error();
  EXPECT_EQ(route->size(), 120u);
  auto geojson = readPathFile(kPaths / "trek.geojson");
  ASSERT_TRUE(geojson) << geojson.error();
  ASSERT_EQ(geojson->size(), route->size());
  for (size_t i = 0; i < route->size(); ++i) {
    EXPECT_NEAR((*geojson)[i].longitudeDegrees, (*route)[i].longitudeDegrees, 1e-6);
    EXPECT_NEAR((*geojson)[i].latitudeDegrees, (*route)[i].latitudeDegrees, 1e-6);
    EXPECT_NEAR((*geojson)[i].elevationMeters, (*route)[i].elevationMeters, 1e-6);
  }
}

TEST(PathFiles, KmlLinesAndBadFilesNamed) {
  const fs::path dir = globe::testing::freshTempDir("measure-paths");
  std::ofstream(dir / "line.kml")
      << "<?xml version=\"1.0\"?><kml xmlns=\"http://www.opengis.net/kml/2.2\"><Document>"
         "<Placemark><LineString><coordinates>138.7,35.3,100 138.8,35.4,200\n 138.9,35.5"
         "</coordinates></LineString></Placemark></Document></kml>";
  auto kml = readPathFile(dir / "line.kml");
  ASSERT_TRUE(kml) << kml.error();
  ASSERT_EQ(kml->size(), 3u);
  EXPECT_DOUBLE_EQ((*kml)[1].elevationMeters, 200);
  EXPECT_TRUE(std::isnan((*kml)[2].elevationMeters));
  const std::pair<const char*, const char*> bad[] = {
      {"<gpx><wpt lat=\"1\" lon=\"2\"/></gpx>", "no line"},
      {"<gpx><trk><trkseg><trkpt lat=\"1\"/><trkpt lat=\"2\" lon=\"3\"/></trkseg></trk></gpx>",
       "without lat and lon"},
      {"<kml><LineString><coordinates>1;2 3,4</coordinates></LineString></kml>", "coordinate"},
      {"<svg/>", "neither GPX nor KML"},
      {"<gpx><trk>", "not XML"},
      {"{\"type\":\"LineString\",\"coordinates\":[[0,0],[200,95]]}", "outside"},
      {"[1, 2]", "neither GPX, KML nor GeoJSON"},
  };
  for (const auto& [text, says] : bad) {
    std::ofstream(dir / "bad.txt") << text;
    auto read = readPathFile(dir / "bad.txt");
    ASSERT_FALSE(read) << text;
    EXPECT_EQ(read.error().rfind((dir / "bad.txt").string(), 0), 0u) << read.error();
    EXPECT_NE(read.error().find(says), std::string::npos) << read.error();
  }
  EXPECT_FALSE(readPathFile(dir / "missing.gpx"));
}

// Devices write empty or one-point tracks before the one that matters, and 1e308 or NaN where
// they had no elevation: the first line of two points, the elevations read as not given.
TEST(PathFiles, GpxEmptyAndOnePointTracksAndImpossibleElevations) {
  const fs::path dir = globe::testing::freshTempDir("measure-gpx-cases");
  const struct {
    const char* body;
    double firstLatitude;
    size_t points;
  } cases[] = {
      {"<trk><name>empty</name></trk><trk><trkseg><trkpt lat=\"1\" lon=\"2\"/>"
       "<trkpt lat=\"1.1\" lon=\"2\"/></trkseg></trk>",
       1.0, 2},
      {"<trk><trkseg><trkpt lat=\"9\" lon=\"9\"/></trkseg></trk>"
       "<rte><rtept lat=\"3\" lon=\"4\"/><rtept lat=\"3.1\" lon=\"4\"/>"
       "<rtept lat=\"3.2\" lon=\"4\"/></rte>",
       3.0, 3},
  };
  for (const auto& c : cases) {
    std::ofstream(dir / "t.gpx") << "<gpx version=\"1.1\">" << c.body << "</gpx>";
    auto line = readPathFile(dir / "t.gpx");
    ASSERT_TRUE(line) << c.body << ": " << line.error();
    ASSERT_EQ(line->size(), c.points) << c.body;
    EXPECT_EQ(line->front().latitudeDegrees, c.firstLatitude) << c.body;
  }
  std::ofstream(dir / "ele.gpx")
      << "<gpx><trk><trkseg><trkpt lat=\"1\" lon=\"2\"><ele>1e308</ele></trkpt>"
         "<trkpt lat=\"1.1\" lon=\"2\"><ele>NaN</ele></trkpt>"
         "<trkpt lat=\"1.2\" lon=\"2\"><ele>-1e9</ele></trkpt>"
         "<trkpt lat=\"1.3\" lon=\"2\"><ele>812.5</ele></trkpt></trkseg></trk></gpx>";
  std::vector<std::string> warnings;
  auto line = readPathFile(dir / "ele.gpx", [&](const std::string& w) { warnings.push_back(w); });
  ASSERT_TRUE(line) << line.error();
  ASSERT_EQ(line->size(), 4u);
  for (size_t k = 0; k < 3; ++k) EXPECT_TRUE(std::isnan((*line)[k].elevationMeters)) << k;
  EXPECT_EQ((*line)[3].elevationMeters, 812.5);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("ele.gpx: 2 of 4 elevations outside -12000..100000 m"),
            std::string::npos)
      << warnings[0];
}

TEST(Geodesics, KnownLengthsAndAreas) {
  // One degree of the equator: a·π/180; a quarter meridian of WGS84: 10,001,965.729 m.
  EXPECT_NEAR(geodesicLengthMeters({{0, 0}, {1, 0}}), 6378137.0 * std::numbers::pi / 180, 1e-6);
  EXPECT_NEAR(geodesicLengthMeters({{0, 0}, {0, 90}}), 10001965.729, 1e-3);
  // Samples: every vertex kept, no gap wider than asked, the last at the full length.
  const std::vector<PathPoint> path{{0, 0, 0}, {0.5, 0, 100}, {0.5, 0.3, 40}};
  const auto samples = sampleGeodesic(path, 1000);
  EXPECT_NEAR(samples.back().distanceMeters, geodesicLengthMeters(path), 1e-6);
  for (size_t i = 1; i < samples.size(); ++i) {
    EXPECT_LE(samples[i].distanceMeters - samples[i - 1].distanceMeters, 1000 + 1e-9);
  }
  EXPECT_NEAR(samples[28].sourceElevationMeters, 100 * 28 / 56.0, 1e-9);  // 56 steps on leg 1
  // A 1°×1° cell at the equator: the authalic sphere says 1.2363e10 m²; the ellipsoid a little
  // less.
  const double area = ringAreaSquareMeters({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  EXPECT_NEAR(area, 1.2363e10, 0.01 * 1.2363e10);
}

TEST(GlobeProfile, HeightsAreTheExactSurfaceAndTheLengthTheGeodesics) {
  const fs::path dir = globe::testing::freshTempDir("measure-profile");
  // Across Mount Fuji's summit (the bundled 3″ DEM), west to east.
  std::ofstream(dir / "fuji.geojson")
      << R"({"type":"Feature","geometry":{"type":"LineString","coordinates":)"
      << R"([[138.68,35.355],[138.7274,35.3606],[138.78,35.37]]}})";
  const std::string pyramid = globe::testing::bundledPyramid().string();
  const Exit profile =
      runCommand(std::string(GLOBE_EXE) + " profile " + pyramid + " " +
                 (dir / "fuji.geojson").string() + " -o " + (dir / "fuji.csv").string());
  ASSERT_EQ(profile.exitCode, 0) << profile.output;
  std::ifstream in(dir / "fuji.csv");
  const std::string csv{std::istreambuf_iterator<char>(in), {}};
  EXPECT_EQ(csv.rfind("distance_m,lon,lat,height_m,slope_deg\n", 0), 0u) << csv.substr(0, 200);
  const auto rows = csvRows(csv);
  ASSERT_GT(rows.size(), 100u);
  // Sampled at least at the pyramid's finest spacing (level 14: 0.000687°, ~62 m east-west here).
  double widest = 0;
  for (size_t i = 1; i < rows.size(); ++i) widest = std::max(widest, rows[i][0] - rows[i - 1][0]);
  EXPECT_LT(widest, 63.0);
  EXPECT_NEAR(rows.back()[0],
              geodesicLengthMeters({{138.68, 35.355}, {138.7274, 35.3606}, {138.78, 35.37}}), 0.01);
  // The heights are `globe query --mode exact`'s at the same points; the summit is ~3,776 m.
  {
    std::ofstream points(dir / "points.txt");
    points.precision(12);
    for (const auto& r : rows) points << r[1] << "," << r[2] << "\n";
  }
  const Exit query = runCommand(std::string(GLOBE_EXE) + " query --mode exact " + pyramid + " < " +
                                (dir / "points.txt").string());
  ASSERT_EQ(query.exitCode, 0) << query.output;
  std::istringstream answers(query.output);
  std::string line;
  size_t compared = 0;
  double highest = 0;
  while (std::getline(answers, line) && compared < rows.size()) {
    double lon = 0, lat = 0, h = 0;
    int level = 0;
    if (std::sscanf(line.c_str(), "%lf,%lf,%d,%lf", &lon, &lat, &level, &h) != 4) continue;
    // Within 1 cm: the CSV gives positions to 1e-7 degrees (1 cm), on slopes up to ~40 degrees.
    EXPECT_NEAR(rows[compared][3], h, 0.01) << line;
    highest = std::max(highest, rows[compared][3]);
    ++compared;
  }
  EXPECT_EQ(compared, rows.size());
  EXPECT_NEAR(highest, 3776, 60);
  // Slopes: the rise over the run to the next sample, in degrees.
  EXPECT_NEAR(
      rows[10][4],
      std::atan2(rows[11][3] - rows[10][3], rows[11][0] - rows[10][0]) * 180 / std::numbers::pi,
      0.01);
}

TEST(GlobeProfile, AGpxTrackKeepsItsOwnElevationsBeside) {
  const fs::path dir = globe::testing::freshTempDir("measure-gpx");
  const Exit profile =
      runCommand(std::string(GLOBE_EXE) + " profile " + globe::testing::bundledPyramid().string() +
                 " " + (kPaths / "Mojstrovka.gpx").string() + " -o " + (dir / "m.csv").string());
  ASSERT_EQ(profile.exitCode, 0) << profile.output;
  std::ifstream in(dir / "m.csv");
  const std::string csv{std::istreambuf_iterator<char>(in), {}};
  EXPECT_EQ(csv.rfind("distance_m,lon,lat,height_m,slope_deg,path_elevation_m\n", 0), 0u);
  const auto rows = csvRows(csv);
  ASSERT_GE(rows.size(), 184u);
  EXPECT_NEAR(rows.front()[5], 1614.678, 1e-3);  // the track's first <ele>
  const Exit bad =
      runCommand(std::string(GLOBE_EXE) + " profile " + globe::testing::bundledPyramid().string() +
                 " /nonexistent.gpx -o " + (dir / "x.csv").string());
  EXPECT_EQ(bad.exitCode, 1);
  EXPECT_NE(bad.output.find("/nonexistent.gpx"), std::string::npos) << bad.output;
  EXPECT_FALSE(fs::exists(dir / "x.csv"));
}

TEST(ChartAxis, StepsOfOneTwoOrFiveTimesAPowerOfTen) {
  EXPECT_DOUBLE_EQ(niceStep(3776, 5), 1000);
  EXPECT_DOUBLE_EQ(niceStep(3776, 8), 500);
  EXPECT_DOUBLE_EQ(niceStep(9.87, 10), 1);
  EXPECT_DOUBLE_EQ(niceStep(0.3, 3), 0.1);
  EXPECT_DOUBLE_EQ(niceStep(130, 10), 20);
  const AxisRange range = niceAxis(1234, 3776, 6, 10);
  EXPECT_DOUBLE_EQ(range.step, 500);
  EXPECT_DOUBLE_EQ(range.low, 1000);
  EXPECT_DOUBLE_EQ(range.high, 4000);
  // A flat profile still gets a span to draw in.
  const AxisRange flat = niceAxis(0, 0, 5, 10);
  EXPECT_LT(flat.low, 0);
  EXPECT_GT(flat.high, 0);
}

// A pixel of the chart's colours (the terrain's fill, the file's line), not the white
// background, the grey grid or the black text.
bool coloured(const formats::ImageRgba& image, int x, int y) {
  const uint8_t* p = &image.pixels[(static_cast<size_t>(y) * image.widthPixels + x) * 4];
  return std::max({p[0], p[1], p[2]}) - std::min({p[0], p[1], p[2]}) > 25;
}

// The first coloured row from the plot's top down in column x (the plot's bottom without one).
int topOfFill(const formats::ImageRgba& image, const ChartPlotArea& area, int x) {
  const int bottom = static_cast<int>(area.top + area.height) - 1;
  for (int y = static_cast<int>(area.top) + 1; y < bottom; ++y) {
    if (coloured(image, x, y)) return y;
  }
  return bottom;
}

TEST(GlobeProfile, APngChartFilledHighestAtTheSummit) {
  const fs::path dir = globe::testing::freshTempDir("measure-chart");
  std::ofstream(dir / "fuji.geojson")
      << R"({"type":"Feature","geometry":{"type":"LineString","coordinates":)"
      << R"([[138.68,35.355],[138.7274,35.3606],[138.78,35.37]]}})";
  const std::string command = std::string(GLOBE_EXE) + " profile " +
                              globe::testing::bundledPyramid().string() + " " +
                              (dir / "fuji.geojson").string();
  const Exit profile = runCommand(command + " -o " + (dir / "fuji.csv").string() + " --png " +
                                  (dir / "fuji.png").string() + " --png-size 900x360");
  ASSERT_EQ(profile.exitCode, 0) << profile.output;
  auto image = formats::loadImageRgba(dir / "fuji.png");
  ASSERT_TRUE(image) << image.error();
  EXPECT_EQ(image->widthPixels, 900);
  EXPECT_EQ(image->heightPixels, 360);
  std::ifstream in(dir / "fuji.csv");
  const auto rows = csvRows(std::string{std::istreambuf_iterator<char>(in), {}});
  ASSERT_GT(rows.size(), 100u);
  const auto summit = std::max_element(rows.begin(), rows.end(),
                                       [](const auto& a, const auto& b) { return a[3] < b[3]; });
  const ChartPlotArea area = profileChartPlotArea(900, 360);
  const int summitX = static_cast<int>(area.left + area.width * (*summit)[0] / rows.back()[0]);
  const int startX = static_cast<int>(area.left) + 3;
  const int summitTop = topOfFill(*image, area, summitX);
  const int startTop = topOfFill(*image, area, startX);
  // The summit (~3,776 m) stands well above the start (~1,400 m) on a 0..4,000-ish m axis.
  EXPECT_LT(summitTop + area.height / 4, startTop) << summitTop << " " << startTop;
  // Filled down to the axis under both, white outside the plot, no second line without <ele>.
  EXPECT_TRUE(coloured(*image, summitX, static_cast<int>(area.top + area.height) - 3));
  EXPECT_TRUE(coloured(*image, startX, static_cast<int>(area.top + area.height) - 3));
  EXPECT_EQ(image->pixels[0], 255);
  int orange = 0;
  for (size_t i = 0; i < image->pixels.size(); i += 4) {
    const auto* p = &image->pixels[i];
    orange += p[0] > p[1] + 60 && p[0] > p[2] + 100;
  }
  EXPECT_EQ(orange, 0);

  // Bad sizes are refused before any work, naming the option; nothing is written.
  for (const char* size : {"100x50", "wide", "800x", "800x400x2"}) {
    const Exit bad =
        runCommand(command + " --png " + (dir / "bad.png").string() + " --png-size " + size);
    EXPECT_EQ(bad.exitCode, 1) << size;
    EXPECT_NE(bad.output.find("--png-size"), std::string::npos) << bad.output;
    EXPECT_FALSE(fs::exists(dir / "bad.png")) << size;
  }
  EXPECT_NE(runCommand(command + " --png x.png --png-size 100x50").output.find("at least 300x150"),
            std::string::npos);
  const Exit nothing = runCommand(command);
  EXPECT_EQ(nothing.exitCode, 1);
  EXPECT_NE(nothing.output.find("nothing to write"), std::string::npos) << nothing.output;
  // An unwritable place is named.
  const Exit unwritable = runCommand(command + " --png /nonexistent-dir/p.png");
  EXPECT_EQ(unwritable.exitCode, 1);
  EXPECT_NE(unwritable.output.find("/nonexistent-dir/p.png"), std::string::npos)
      << unwritable.output;
}

// The chart drawn in memory (the window's): its size, white margins, the terrain filled.
TEST(ProfileChart, DrawnIntoAnImageInMemory) {
  std::vector<ProfileRow> rows;
  for (int i = 0; i <= 100; ++i) {
    ProfileRow row;
    row.sample.distanceMeters = 50.0 * i;
    row.heightMeters = 1000 + 800 * std::sin(i * std::numbers::pi / 100);
    rows.push_back(row);
  }
  auto image = drawProfileChart(rows, 320, 150);
  ASSERT_TRUE(image) << image.error();
  EXPECT_EQ(image->widthPixels, 320);
  EXPECT_EQ(image->heightPixels, 150);
  ASSERT_EQ(image->pixels.size(), 320u * 150 * 4);
  size_t green = 0, dark = 0;
  for (size_t i = 0; i < image->pixels.size(); i += 4) {
    const uint8_t* p = &image->pixels[i];
    EXPECT_EQ(p[3], 255);
    green += p[1] > p[0] + 30 && p[1] > p[2] + 30;
    dark += p[0] < 100 && p[1] < 100 && p[2] < 100;
  }
  EXPECT_GT(green, 320u * 150 / 20) << "the terrain's fill";
  EXPECT_GT(dark, 300u) << "axes and text";
  EXPECT_EQ(image->pixels[0], 255) << "white at the corner";
  // The plot's middle column is filled near the axis, white near the top (the hump's at 1,800 m).
  const ChartPlotArea area = profileChartPlotArea(320, 150);
  EXPECT_TRUE(coloured(*image, static_cast<int>(area.left + area.width / 2),
                       static_cast<int>(area.top + area.height) - 3));
  // Bad sizes and too few rows are errors, without a file to name.
  EXPECT_FALSE(drawProfileChart(rows, 100, 50));
  EXPECT_FALSE(drawProfileChart({rows[0]}, 320, 150));
}

TEST(GlobeProfile, AGpxTracksChartDrawsItsOwnElevationsToo) {
  const fs::path dir = globe::testing::freshTempDir("measure-gpx-chart");
  const Exit profile =
      runCommand(std::string(GLOBE_EXE) + " profile " + globe::testing::bundledPyramid().string() +
                 " " + (kPaths / "Mojstrovka.gpx").string() + " --png " + (dir / "m.png").string());
  ASSERT_EQ(profile.exitCode, 0) << profile.output;
  auto image = formats::loadImageRgba(dir / "m.png");
  ASSERT_TRUE(image) << image.error();
  EXPECT_EQ(image->widthPixels, 1000);  // the default size
  EXPECT_EQ(image->heightPixels, 400);
  int orange = 0;
  for (size_t i = 0; i < image->pixels.size(); i += 4) {
    const auto* p = &image->pixels[i];
    orange += p[0] > p[1] + 60 && p[0] > p[2] + 100;
  }
  EXPECT_GT(orange, 500);  // the <ele> line along the chart, and its legend
}

}  // namespace
}  // namespace globe::measure
