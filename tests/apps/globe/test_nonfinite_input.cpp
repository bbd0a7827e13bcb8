// Non-finite and absurd numbers at every entry point of the real `globe` program: each is refused
// with a message naming the option or field and its value (the file and line for files), and a
// non-zero exit status; never a crash (a signal) or a hang.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/build_paths.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace {

namespace fs = std::filesystem;
using globe::testing::bundledPyramid;
using globe::testing::freshTempDir;

struct GlobeRun {
  bool exited = false;  // false: killed by a signal (a crash, or the timeout)
  int exitCode = -1;
  std::string output;  // stdout and stderr
};

// Runs `globe ARGUMENTS` with `input` on stdin, under a 60 s timeout (a hang fails the test).
GlobeRun runGlobeOnInput(const std::string& arguments, const std::string& input = "") {
  static int counter = 0;
  const fs::path dir = freshTempDir("nonfinite-" + std::to_string(++counter));
  { std::ofstream(dir / "in.txt") << input; }
  const std::string command = "timeout -s KILL 60 " + std::string(GLOBE_EXE) + " " + arguments +
                              " < " + (dir / "in.txt").string() + " > " +
                              (dir / "out.txt").string() + " 2>&1";
  const int status = std::system(command.c_str());
  std::stringstream text;
  text << std::ifstream(dir / "out.txt").rdbuf();
  // timeout's own status for a killed child is 128 + 9; a crash inside globe is 128 + signal.
  const bool exited = WIFEXITED(status) && WEXITSTATUS(status) < 128;
  return {exited, WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

struct Case {
  // After "globe". OUT stands for a directory, BUNDLED for the bundled pyramid (tiled once per
  // process: only where the input gets that far), PYRAMID for a path that is never opened (the
  // arguments are refused before).
  std::string arguments;
  std::string expected;  // a part of the message
  int exitCode;
};

std::string substitute(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

void expectRefused(const std::vector<Case>& cases) {
  const fs::path out = freshTempDir("nonfinite-out");
  for (const Case& c : cases) {
    std::string arguments = substitute(c.arguments, "OUT", out.string());
    arguments = substitute(arguments, "PYRAMID", "/nonexistent-pyramid");
    if (arguments.find("BUNDLED") != std::string::npos) {
      arguments = substitute(arguments, "BUNDLED", bundledPyramid().string());
    }
    const GlobeRun run = runGlobeOnInput(arguments);
    SCOPED_TRACE("globe " + c.arguments);
    EXPECT_TRUE(run.exited) << run.output;
    EXPECT_EQ(run.exitCode, c.exitCode) << run.output;
    EXPECT_NE(run.output.find(c.expected), std::string::npos)
        << "expected '" << c.expected << "' in: " << run.output;
  }
}

TEST(NonFiniteInput, CameraArgumentsOfSnapshotAndViewAreNamed) {
  const std::string snapshot = "snapshot PYRAMID -o OUT/x.png --size 32x18 --camera ";
  expectRefused({
      {snapshot + "nan,35,1000", "--camera 'nan,35,1000': 'nan' is not a finite number", 2},
      {snapshot + "138,inf,1000", "'inf' is not a finite number", 2},
      {snapshot + "138,35,-inf", "'-inf' is not a finite number", 2},
      {snapshot + "138,35,1e999", "'1e999' is not a finite number", 2},
      {snapshot + "138,35,-1e999", "'-1e999' is not a finite number", 2},
      {snapshot + "138,,1000", "--camera '138,,1000': '' is not a number", 2},
      {snapshot + "138,35,1000,", "--camera '138,35,1000,': '' is not a number", 2},
      {snapshot + "''", "expected LON,LAT,HEIGHT", 2},
      {snapshot + "138,35,1000,nan,0,0", "'nan' is not a finite number", 2},
      {snapshot + "138,35,1000,0,-infinity,0", "'-infinity' is not a finite number", 2},
      {snapshot + "138,35,1000,0,0,NaN", "'NaN' is not a finite number", 2},
      {snapshot + "138,35,1e300", "height must be between", 2},
      {snapshot + "1e300,35,1000", "longitude out of range", 2},
      {snapshot + "200,35,1000", "longitude out of range (-180..180)", 2},
      {snapshot + "-180.5,35,1000", "longitude out of range (-180..180)", 2},
      {"view PYRAMID --frames 1 --camera nan,nan,nan", "globe view: --camera 'nan,nan,nan'", 2},
      {"view PYRAMID --frames 1 --camera 0,0,inf", "'inf' is not a finite number", 2},
      {"view PYRAMID --frames 1 --camera 0,0,1e999,0,0,0", "'1e999' is not a finite number", 2},
  });
}

TEST(NonFiniteInput, NumericOptionsAreNamed) {
  const std::string snapshot = "snapshot PYRAMID -o OUT/x.png --camera 138,35,1000 ";
  const std::string play = "play PYRAMID " + std::string(GLOBE_SOURCE_DIR) +
                           "/data/paths/fuji-demo.json --no-frames --out OUT/play ";
  expectRefused({
      {snapshot + "--sse nan", "globe snapshot: --sse 'nan': not a finite number", 2},
      {snapshot + "--sse inf", "--sse 'inf': not a finite number", 2},
      {snapshot + "--sse -inf", "--sse '-inf': not a finite number", 2},
      {snapshot + "--sse 1e999", "--sse '1e999': not a finite number", 2},
      {snapshot + "--sse ''", "--sse '': not a number", 2},
      {snapshot + "--sse 0", "--sse '0': must be in [0.1, 10000]", 2},
      {snapshot + "--sse -2", "--sse '-2': must be in [0.1, 10000]", 2},
      {snapshot + "--size nanx100", "--size 'nanx100': expected WxH", 2},
      {snapshot + "--size 1e999x100", "--size '1e999x100': expected WxH", 2},
      {snapshot + "--size 0x100", "width and height must be 1..16384", 2},
      {snapshot + "--max-load-level nan", "--max-load-level", 2},  // CLI11: could not convert
      {snapshot + "--max-load-level -1", "--max-load-level", 2},
      {snapshot + "--globe nan", "--globe must be wgs84 or sphere, not 'nan'", 2},
      {play + "--fps nan", "globe play: --fps 'nan': not a finite number", 2},
      {play + "--fps inf", "--fps 'inf': not a finite number", 2},
      {play + "--fps -inf", "--fps '-inf': not a finite number", 2},
      {play + "--fps 1e999", "--fps '1e999': not a finite number", 2},
      {play + "--fps ''", "--fps '': not a number", 2},
      {play + "--fps 0", "--fps '0': must be in (0, 1000]", 2},
      {play + "--fps 1001", "--fps '1001': must be in (0, 1000]", 2},
      {play + "--size 10xinf", "--size '10xinf': expected WxH", 2},
      {"view PYRAMID --frames nan", "--frames", 2},
      {"view PYRAMID --frames 1e999", "--frames", 2},
      {"view PYRAMID --frames -1", "globe view: --frames -1: must be at least 0", 2},
      {"view PYRAMID --size infxinf", "--size 'infxinf': expected WxH", 2},
      {"query PYRAMID --level nan", "--level", 2},
      {"query PYRAMID --level 1e999", "--level", 2},
      {"info PYRAMID --globe inf", "--globe must be wgs84 or sphere, not 'inf'", 2},
  });
}

// A path file whose keyframe 1 has `field` set to `value` (as written in the JSON).
std::string jsonPathWith(const std::string& field, const std::string& value) {
  std::string second = R"({"t": 5, "lon": 138.7, "lat": 35.3, "height": 5000, "heading": 0})";
  const std::string key = "\"" + field + "\": ";
  const size_t at = second.find(key);
  if (at == std::string::npos) {
    second.insert(second.size() - 1, ", " + key + value);
  } else {
    const size_t end = second.find_first_of(",}", at);
    second.replace(at + key.size(), end - at - key.size(), value);
  }
  return "{\"keyframes\": [\n"
         "  {\"t\": 0, \"lon\": 138.7, \"lat\": 35.2, \"height\": 8000},\n  " +
         second + "\n]}\n";
}

TEST(NonFiniteInput, PlayRefusesPathFilesNamingFileLineAndField) {
  const fs::path dir = freshTempDir("nonfinite-paths");
  std::vector<Case> cases;
  struct JsonCase {
    std::string field, value, expected;
  };
  const JsonCase json[] = {
      {"t", "1e999", "keyframes[1].t: 1e999 is not a finite number"},
      {"t", "-1e999", "keyframes[1].t: -1e999 is not a finite number"},
      {"lon", "1e999", "keyframes[1].lon: 1e999 is not a finite number"},
      {"lat", "-1e999", "keyframes[1].lat: -1e999 is not a finite number"},
      {"height", "1e999", "keyframes[1].height: 1e999 is not a finite number"},
      {"height", "1e300", "keyframes[1].height: 1e300 is outside -11000..40000000"},
      {"heading", "1e999", "keyframes[1].heading: 1e999 is not a finite number"},
      {"pitch", "-1e999", "keyframes[1].pitch: -1e999 is not a finite number"},
      {"roll", "1E999", "keyframes[1].roll: 1E999 is not a finite number"},
      {"lat", "NaN", "not valid JSON"},  // JSON has no NaN literal
      {"t", "Infinity", "not valid JSON"},
  };
  for (size_t k = 0; k < std::size(json); ++k) {
    const fs::path file = dir / ("bad" + std::to_string(k) + ".json");
    std::ofstream(file) << jsonPathWith(json[k].field, json[k].value);
    cases.push_back({"play PYRAMID " + file.string() + " --no-frames --out OUT/p",
                     file.string() + ":3: " + json[k].expected, 1});
  }
  // A path 1e300 s long is finite but has too many frames.
  const fs::path longPath = dir / "long.json";
  std::ofstream(longPath) << jsonPathWith("t", "1e300");
  cases.push_back({"play BUNDLED " + longPath.string() + " --no-frames --out OUT/p",
                   "more than 10000000 frames", 1});
  expectRefused(cases);
}

// A two-FlyTo tour whose second Camera has `element` holding `value`.
std::string kmlTourWith(const std::string& element, const std::string& value) {
  std::string camera =
      "<longitude>138.72</longitude><latitude>35.3</latitude><altitude>4000</altitude>"
      "<heading>10</heading><tilt>60</tilt><roll>0</roll><altitudeMode>absolute</altitudeMode>";
  std::string duration = "3";
  const std::string open = "<" + element + ">", close = "</" + element + ">";
  if (element == "gx:duration") {
    duration = value;
  } else {
    const size_t at = camera.find(open);
    camera.replace(at, camera.find(close) - at + close.size(), open + value + close);
  }
  return "<kml xmlns:gx=\"http://www.google.com/kml/ext/2.2\">\n<gx:Tour>\n<gx:Playlist>\n"
         "<gx:FlyTo><gx:duration>1</gx:duration><Camera><longitude>138.7</longitude>"
         "<latitude>35.2</latitude><altitude>8000</altitude><altitudeMode>absolute</altitudeMode>"
         "</Camera></gx:FlyTo>\n"
         "<gx:FlyTo>\n<gx:duration>" +
         duration + "</gx:duration>\n<Camera>\n" + camera +
         "\n</Camera>\n</gx:FlyTo>\n</gx:Playlist>\n</gx:Tour>\n</kml>\n";
}

TEST(NonFiniteInput, PlayRefusesKmlToursNamingFileLineAndElement) {
  const fs::path dir = freshTempDir("nonfinite-tours");
  struct KmlCase {
    std::string element, value, expected;
  };
  const KmlCase kml[] = {
      {"longitude", "nan", ":8: Camera.longitude: nan is not a finite number"},
      {"latitude", "-inf", ":8: Camera.latitude: -inf is not a finite number"},
      {"altitude", "1e999", ":8: Camera.altitude: 1e999 is not a finite number"},
      {"altitude", "1e300", ":8: Camera.altitude: 1e300 is outside -11000..40000000"},
      {"heading", "infinity", ":8: Camera.heading: infinity is not a finite number"},
      {"tilt", "NAN", ":8: Camera.tilt: NAN is not a finite number"},
      {"roll", "-1e999", ":8: Camera.roll: -1e999 is not a finite number"},
      {"gx:duration", "nan", ":6: gx:FlyTo.duration: nan is not a finite number"},
      {"gx:duration", "inf", ":6: gx:FlyTo.duration: inf is not a finite number"},
      {"gx:duration", "", ":6: gx:FlyTo.duration: '' is not a number"},
      {"latitude", "", ":8: Camera.latitude: '' is not a number"},
  };
  std::vector<Case> cases;
  for (size_t k = 0; k < std::size(kml); ++k) {
    const fs::path file = dir / ("bad" + std::to_string(k) + ".kml");
    std::ofstream(file) << kmlTourWith(kml[k].element, kml[k].value);
    cases.push_back({"play PYRAMID " + file.string() + " --no-frames --out OUT/k",
                     file.string() + kml[k].expected, 1});
  }
  expectRefused(cases);
}

TEST(NonFiniteInput, QueryNamesEveryNonFiniteLineAndStillAnswersTheGoodOnes) {
  const GlobeRun run =
      runGlobeOnInput("query " + bundledPyramid().string(),
                      "nan,nan\n138.7,35.3\ninf,0\n0,-inf\n1e999,0\n0,-1e999\nnan\n,\n"
                      "-nan,1\n1e-999,0\n");
  EXPECT_TRUE(run.exited) << run.output;
  EXPECT_EQ(run.exitCode, 1) << run.output;
  const std::string expected[] = {
      "line 1: 'nan,nan': longitude is not a finite number",
      "line 3: 'inf,0': longitude is not a finite number",
      "line 4: '0,-inf': latitude is not a finite number",
      "line 5: '1e999,0': longitude is not a finite number",
      "line 6: '0,-1e999': latitude is not a finite number",
      "line 7: 'nan': expected lon,lat in degrees",
      "line 8: ',': expected lon,lat in degrees",
      "line 9: '-nan,1': longitude is not a finite number",
  };
  for (const std::string& line : expected) {
    EXPECT_NE(run.output.find(line), std::string::npos) << line << " in: " << run.output;
  }
  // Two answers: 138.7,35.3 and 1e-999,0 (a number too small for a double reads as 0).
  EXPECT_NE(run.output.find("138.7,35.3,14,"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("\n0,0,"), std::string::npos) << run.output;
}

}  // namespace

namespace {

// Bad overlay files on every command that takes --overlay: the file and the problem are named,
// nothing is drawn (exit 2), never a crash.
TEST(NonFiniteInput, BadOverlayFilesAreNamed) {
  const fs::path dir = freshTempDir("bad-overlays");
  {
    std::ofstream(dir / "nan.kml") << R"(<kml><Placemark><name>Bad</name><Point>
<coordinates>nan,35</coordinates></Point></Placemark></kml>)";
  }
  { std::ofstream(dir / "text.geojson") << "this is not JSON"; }
  { std::ofstream(dir / "zip.kmz") << "PK\x03\x04 truncated"; }
  const std::string snapshot = "snapshot PYRAMID -o OUT/x.png --camera 138,35,1000 --overlay ";
  const std::string play = "play PYRAMID " + std::string(GLOBE_SOURCE_DIR) +
                           "/data/paths/fuji-demo.json --no-frames --out OUT/play --overlay ";
  expectRefused({
      {snapshot + (dir / "nan.kml").string(), "nan.kml", 2},
      {snapshot + (dir / "nan.kml").string(), "Bad", 2},
      {snapshot + (dir / "text.geojson").string(), "text.geojson", 2},
      {snapshot + (dir / "zip.kmz").string(), "zip.kmz", 2},
      {snapshot + (dir / "missing.gpx").string(), "missing.gpx", 2},
      {play + (dir / "nan.kml").string(), "globe play: --overlay", 2},
      {"view PYRAMID --frames 1 --overlay " + (dir / "text.geojson").string(),
       "globe view: --overlay", 2},
  });
}

}  // namespace
