// Camera path files: the JSON format read and written, KML tours, and every bad file refused
// with its file, line and field.
#include "camera/camera_path_file.hpp"
#include "camera/path_checks.hpp"
#include "tests/support/build_paths.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <fstream>
#include <limits>
#include <string>

namespace globe::camera {
namespace {

class PathFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    static std::atomic<int> counter{0};
    dir_ = std::filesystem::temp_directory_path() /
           ("globe_path_files_" + std::to_string(::getpid()) + "_" + std::to_string(++counter));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path write(const std::string& name, const std::string& text) {
    const auto path = dir_ / name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  // The error of reading `text` as `name`, with the directory removed from it.
  std::string errorOf(const std::string& name, const std::string& text) {
    auto result = readCameraPath(write(name, text));
    if (result) return "(no error)";
    std::string message = result.error();
    const std::string prefix = (dir_ / "").string();
    if (message.rfind(prefix, 0) == 0) message.erase(0, prefix.size());
    return message;
  }

  std::filesystem::path dir_;
};

constexpr const char* kGoodJson = R"({
  "description": "two keys",
  "interpolation": "linear",
  "keyframes": [
    {"t": 0, "lon": 138.73, "lat": 35.36, "height": 5000, "heading": 10, "pitch": -20, "roll": 1},
    {"t": 2.5, "lon": -179.5, "lat": -90, "height": 20, "aboveTerrain": true}
  ]
}
)";

TEST_F(PathFiles, ReadsJsonWithDefaults) {
  auto file = readCameraPath(write("good.json", kGoodJson));
  ASSERT_TRUE(file) << file.error();
  EXPECT_EQ(file->interpolation, "linear");
  ASSERT_EQ(file->keyframes.size(), 2u);
  const PathKeyframe& a = file->keyframes[0];
  EXPECT_EQ(a.timeSeconds, 0);
  EXPECT_EQ(a.longitudeDegrees, 138.73);
  EXPECT_EQ(a.latitudeDegrees, 35.36);
  EXPECT_EQ(a.heightMeters, 5000);
  EXPECT_EQ(a.headingDegrees, 10);
  EXPECT_EQ(a.pitchDegrees, -20);
  EXPECT_EQ(a.rollDegrees, 1);
  EXPECT_FALSE(a.heightAboveTerrain);
  const PathKeyframe& b = file->keyframes[1];
  EXPECT_EQ(b.timeSeconds, 2.5);
  EXPECT_EQ(b.headingDegrees, 0);  // default
  EXPECT_EQ(b.pitchDegrees, -90);  // default: straight down
  EXPECT_EQ(b.rollDegrees, 0);     // default
  EXPECT_TRUE(b.heightAboveTerrain);
  // "smooth" when not given.
  auto smooth = readCameraPath(
      write("one.JSON", R"({"keyframes": [{"t": 1, "lon": 0, "lat": 0, "height": 1}]})"));
  ASSERT_TRUE(smooth) << smooth.error();
  EXPECT_EQ(smooth->interpolation, "smooth");
}

TEST_F(PathFiles, WritesJsonThatReadsBackIdentically) {
  CameraPathFile file;
  file.interpolation = "smooth";
  file.keyframes = {{0.1, 138.7275, 35.3606, 3776.123456789, 359.9, -89.99, 0.3, false},
                    {1.0 / 3.0, -180, 90, -11000, -720, 90, -1e-7, true}};
  const auto path = dir_ / "out.json";
  ASSERT_TRUE(writeCameraPathJson(path, file));
  auto back = readCameraPathJson(path);
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->interpolation, "smooth");
  ASSERT_EQ(back->keyframes.size(), 2u);
  for (size_t k = 0; k < 2; ++k) {
    const PathKeyframe &a = file.keyframes[k], &b = back->keyframes[k];
    EXPECT_EQ(a.timeSeconds, b.timeSeconds);
    EXPECT_EQ(a.longitudeDegrees, b.longitudeDegrees);
    EXPECT_EQ(a.latitudeDegrees, b.latitudeDegrees);
    EXPECT_EQ(a.heightMeters, b.heightMeters);
    EXPECT_EQ(a.headingDegrees, b.headingDegrees);
    EXPECT_EQ(a.pitchDegrees, b.pitchDegrees);
    EXPECT_EQ(a.rollDegrees, b.rollDegrees);
    EXPECT_EQ(a.heightAboveTerrain, b.heightAboveTerrain);
  }
  // A path the reader would refuse is not written at all.
  file.keyframes[1].latitudeDegrees = 95;
  const auto refused = writeCameraPathJson(dir_ / "bad.json", file);
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().find("keyframes[1].lat: 95 is outside -90..90"), std::string::npos)
      << refused.error();
  EXPECT_FALSE(std::filesystem::exists(dir_ / "bad.json"));
}

// Keyframe k of a path whose keyframe 2 (on line 7) is `third`.
std::string withThird(const std::string& third, const std::string& interpolation = "smooth") {
  return "{\n"
         "  \"interpolation\": \"" +
         interpolation +
         "\",\n"
         "  \"keyframes\": [\n"
         "    {\"t\": 0, \"lon\": 1, \"lat\": 2, \"height\": 3},\n"
         "    {\"t\": 2, \"lon\": 1, \"lat\": 2, \"height\": 3},\n"
         "\n"
         "    " +
         third +
         "\n"
         "  ]\n"
         "}\n";
}

// "time": the Sun's instant at a keyframe (ISO-8601 with its zone), read, written back, refused
// naming the line when it is not an instant.
TEST_F(PathFiles, KeyframeTimesReadWriteAndAreChecked) {
  auto file = readCameraPath(write("sun.json", R"({"keyframes": [
    {"t": 0, "lon": 138.7, "lat": 35.3, "height": 9000, "time": "2024-06-21T06:00+09:00"},
    {"t": 10, "lon": 138.8, "lat": 35.3, "height": 9000},
    {"t": 20, "lon": 138.9, "lat": 35.3, "height": 9000, "time": "2024-06-21T09:00:00Z"}]})"));
  ASSERT_TRUE(file) << file.error();
  ASSERT_TRUE(file->keyframes[0].sunUnixSeconds);
  EXPECT_EQ(*file->keyframes[0].sunUnixSeconds, 1718917200.0);  // 2024-06-20T21:00:00Z
  EXPECT_FALSE(file->keyframes[1].sunUnixSeconds);
  EXPECT_EQ(*file->keyframes[2].sunUnixSeconds, 1718960400.0);
  ASSERT_TRUE(writeCameraPathJson(dir_ / "sun-out.json", *file));
  auto back = readCameraPathJson(dir_ / "sun-out.json");
  ASSERT_TRUE(back) << back.error();
  for (size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(back->keyframes[k].sunUnixSeconds, file->keyframes[k].sunUnixSeconds) << k;
  }
  EXPECT_EQ(errorOf("t1.json", withThird(R"({"t": 5, "lon": 1, "lat": 2, "height": 3, "time": 12})")),
            "t1.json:7: keyframes[2].time: expected an ISO-8601 string, got a number");
  const std::string noZone = errorOf(
      "t2.json", withThird(R"({"t": 5, "lon": 1, "lat": 2, "height": 3, "time": "2024-06-21T06:00"})"));
  EXPECT_EQ(noZone.rfind("t2.json:7: keyframes[2].time: time '2024-06-21T06:00': no zone", 0), 0u)
      << noZone;
}

TEST_F(PathFiles, BadJsonNamesFileLineAndField) {
  EXPECT_EQ(errorOf("path.json", withThird(R"({"t": 5, "lon": 1, "lat": 95, "height": 3})")),
            "path.json:7: keyframes[2].lat: 95 is outside -90..90");
  EXPECT_EQ(errorOf("path.json", withThird(R"({"t": 5, "lon": -180.5, "lat": 0, "height": 3})")),
            "path.json:7: keyframes[2].lon: -180.5 is outside -180..180");
  EXPECT_EQ(
      errorOf("path.json", withThird(R"({"t": 5, "lon": 1, "lat": 0, "height": 3, "pitch": -91})")),
      "path.json:7: keyframes[2].pitch: -91 is outside -90..90");
  EXPECT_EQ(errorOf("path.json", withThird(R"({"t": 5, "lon": 1, "lat": 0, "height": 1e999})")),
            "path.json:7: keyframes[2].height: 1e999 is not a finite number");
  EXPECT_EQ(errorOf("path.json", withThird(R"({"t": 5, "lon": 1, "lat": 0, "height": 5e7})")),
            "path.json:7: keyframes[2].height: 5e7 is outside -11000..40000000");
  EXPECT_EQ(errorOf("path.json", withThird(R"({"t": 5, "lon": 1, "lat": 0})")),
            "path.json:7: keyframes[2]: missing field 'height'");
  EXPECT_EQ(errorOf("path.json", withThird(R"({"t": 1, "lon": 1, "lat": 0, "height": 3})")),
            "path.json:7: keyframes[2].t: 1 is before the previous keyframe's 2: times must "
            "increase strictly");
  EXPECT_EQ(errorOf("path.json", withThird(R"({"t": 2, "lon": 1, "lat": 0, "height": 3})")),
            "path.json:7: keyframes[2].t: 2 repeats the previous keyframe's time: times must "
            "increase strictly");
  EXPECT_EQ(errorOf("path.json", withThird(R"({"t": 5, "lon": "1", "lat": 0, "height": 3})")),
            "path.json:7: keyframes[2].lon: expected a number, got a string");
  EXPECT_EQ(errorOf("path.json", withThird(R"({"t": 5, "lon": 1, "lat": 0, "heigth": 3})")),
            "path.json:7: keyframes[2].heigth: unknown field (a keyframe has t, lon, lat, "
            "height, heading, pitch, roll, aboveTerrain, time, ease, target, fov)");
  EXPECT_EQ(errorOf("path.json", withThird("[1, 2]")),
            "path.json:7: keyframes[2]: expected a keyframe object, got an array");
  EXPECT_EQ(
      errorOf("path.json", withThird(R"({"t": 5, "lon": 1, "lat": 0, "height": 3})", "cubic")),
      "path.json:2: interpolation: \"cubic\" is not \"linear\" or \"smooth\"");
  // Not JSON at all: NaN is no JSON number; a missing comma; an unterminated document.
  EXPECT_EQ(errorOf("path.json", withThird(R"({"t": 5, "lon": NaN, "lat": 0, "height": 3})"))
                .rfind("path.json:7: not valid JSON: syntax error", 0),
            0u);
  EXPECT_EQ(errorOf("path.json", withThird(R"({"t": 5 "lon": 1, "lat": 0, "height": 3})"))
                .rfind("path.json:7: not valid JSON: ", 0),
            0u);
  EXPECT_EQ(errorOf("cut.json", "{\n  \"keyframes\": [\n    {\"t\": 0,\n")
                .rfind("cut.json:4: not valid JSON: ", 0),
            0u);
  // Fewer than one keyframe, none at all, the wrong shapes.
  EXPECT_EQ(errorOf("empty.json", "{\n  \"keyframes\": []\n}\n"),
            "empty.json:2: keyframes: empty: a path needs at least 1 keyframe");
  EXPECT_EQ(errorOf("none.json", "{\"interpolation\": \"linear\"}"),
            "none.json:1: missing field 'keyframes' (or a shot: orbit, flyTo)");
  EXPECT_EQ(errorOf("array.json", "[]"),
            "array.json:1: expected an object {\"keyframes\": [...]}, got an array");
  EXPECT_EQ(errorOf("top.json", "{\"keyframes\": [], \n\"speed\": 3}"),
            "top.json:2: speed: unknown field (the top level has keyframes, interpolation, "
            "altitude, description, or a shot: orbit, flyTo)");
  EXPECT_EQ(errorOf("path.txt", "{}"),
            "path.txt: unknown camera path format '.txt' (expected a .json path or a .kml tour)");
  EXPECT_NE(errorOf("missing.json", "").find("(no error)"), 0u);
  auto missing = readCameraPath(dir_ / "nowhere.json");
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find("nowhere.json: cannot open"), std::string::npos);
}

TEST_F(PathFiles, AnOverflowingNumberBeforeASyntaxErrorIsStillNamed) {
  // nlohmann stops at the overflow, before the broken rest; the scanner must cope with it.
  EXPECT_EQ(errorOf("o.json", "{\"keyframes\": [\n{\"t\": 1e999 ]]]}}} ,,, ["),
            "o.json:2: keyframes[0].t: 1e999 is not a finite number");
  EXPECT_EQ(errorOf("p.json", "{\"keyframes\": [1e999 }").rfind("p.json:1: ", 0), 0u);
}

TEST_F(PathFiles, DeepNestingIsRefusedWithoutCrashing) {
  const std::string deep =
      "{\"keyframes\": " + std::string(100000, '[') + std::string(100000, ']') + "}";
  const std::string error = errorOf("deep.json", deep);
  EXPECT_EQ(error.rfind("deep.json:1: ", 0), 0u) << error;
}

constexpr const char* kTour = R"(<?xml version="1.0" encoding="UTF-8"?>
<kml xmlns="http://www.opengis.net/kml/2.2" xmlns:gx="http://www.google.com/kml/ext/2.2">
<Document>
  <name>Fuji</name>
  <gx:Tour>
    <name>Around the summit</name>
    <gx:Playlist>
      <gx:FlyTo>
        <gx:duration>4.0</gx:duration>
        <gx:flyToMode>smooth</gx:flyToMode>
        <Camera>
          <longitude>138.70</longitude>
          <latitude>35.30</latitude>
          <altitude>6000</altitude>
          <heading>20</heading>
          <tilt>60</tilt>
          <roll>0</roll>
          <altitudeMode>absolute</altitudeMode>
        </Camera>
      </gx:FlyTo>
      <gx:Wait><gx:duration>1.5</gx:duration></gx:Wait>
      <gx:SoundCue><href>ignored.mp3</href></gx:SoundCue>
      <gx:FlyTo>
        <gx:duration>3</gx:duration>
        <gx:flyToMode>smooth</gx:flyToMode>
        <Camera>
          <longitude>138.75</longitude>
          <latitude>35.37</latitude>
          <altitude>300</altitude>
          <heading>-40</heading>
          <tilt>85</tilt>
          <roll>2</roll>
          <gx:altitudeMode>relativeToGround</gx:altitudeMode>
        </Camera>
      </gx:FlyTo>
      <gx:FlyTo>
        <gx:duration>2</gx:duration>
        <Camera>
          <longitude>138.80</longitude>
          <latitude>35.40</latitude>
        </Camera>
      </gx:FlyTo>
    </gx:Playlist>
  </gx:Tour>
</Document>
</kml>
)";

TEST_F(PathFiles, ReadsKmlTours) {
  auto file = readCameraPath(write("tour.kml", kTour));
  ASSERT_TRUE(file) << file.error();
  // Three FlyTos, the Wait's hold and the last FlyTo's bounce: 5.5 km of ground from 300 m, so
  // it arcs (a keyframe at the hop between them).
  ASSERT_EQ(file->keyframes.size(), 5u);
  const auto& k = file->keyframes;
  EXPECT_EQ(k[0].timeSeconds, 0);  // the first FlyTo's duration is Google Earth's approach
  EXPECT_EQ(k[0].longitudeDegrees, 138.70);
  EXPECT_EQ(k[0].heightMeters, 6000);
  EXPECT_FALSE(k[0].heightAboveTerrain);
  EXPECT_EQ(k[0].headingDegrees, 20);
  EXPECT_EQ(k[0].pitchDegrees, -30);  // tilt 60: 30° below the horizon
  EXPECT_EQ(k[1].timeSeconds, 1.5);   // the hold
  EXPECT_EQ(k[1].longitudeDegrees, 138.70);
  EXPECT_EQ(k[2].timeSeconds, 4.5);
  EXPECT_EQ(k[2].heightMeters, 300);
  EXPECT_TRUE(k[2].heightAboveTerrain);
  EXPECT_EQ(k[2].headingDegrees, -40);
  EXPECT_EQ(k[2].pitchDegrees, -5);
  EXPECT_EQ(k[2].rollDegrees, 2);
  EXPECT_EQ(k[3].timeSeconds, 5.5);  // the bounce's apex, eased in before and out after
  EXPECT_GT(k[3].heightMeters, 2000);
  EXPECT_TRUE(k[3].heightAboveTerrain);
  EXPECT_EQ(k[2].ease, kEaseIn);
  EXPECT_EQ(k[3].ease, kEaseOut);
  EXPECT_FALSE(k[1].ease.has_value()) << "the smooth FlyTo does not stop";
  EXPECT_EQ(k[4].timeSeconds, 6.5);
  EXPECT_EQ(k[4].heightMeters, 0);  // clampToGround, KML's default: on the terrain
  EXPECT_TRUE(k[4].heightAboveTerrain);
  EXPECT_EQ(k[4].pitchDegrees, -90);  // tilt 0
  EXPECT_EQ(file->interpolation, "smooth");
  std::string smooth = kTour;
  smooth.replace(smooth.find("<gx:duration>2</gx:duration>"), 28,
                 "<gx:duration>2</gx:duration><gx:flyToMode>smooth</gx:flyToMode>");
  auto allSmooth = readKmlTour(write("smooth.kml", smooth));
  ASSERT_TRUE(allSmooth) << allSmooth.error();
  EXPECT_EQ(allSmooth->interpolation, "smooth");
  ASSERT_EQ(allSmooth->keyframes.size(), 4u) << "smooth: through the views, no arc";
  for (const PathKeyframe& key : allSmooth->keyframes) EXPECT_FALSE(key.ease.has_value());
}

// kTour with `from` (first occurrence) replaced by `to`.
std::string tourWith(const std::string& from, const std::string& to) {
  std::string text = kTour;
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST_F(PathFiles, BadKmlNamesFileLineAndField) {
  EXPECT_EQ(errorOf("tour.kml", tourWith("<latitude>35.30</latitude>", "<latitude>95</latitude>")),
            "tour.kml:13: Camera.latitude: 95 is outside -90..90");
  EXPECT_EQ(
      errorOf("tour.kml", tourWith("<longitude>138.75</longitude>", "<longitude>nan</longitude>")),
      "tour.kml:27: Camera.longitude: nan is not a finite number");
  EXPECT_EQ(errorOf("tour.kml", tourWith("<altitude>300</altitude>", "<altitude>3OO</altitude>")),
            "tour.kml:29: Camera.altitude: '3OO' is not a number");
  EXPECT_EQ(errorOf("tour.kml", tourWith("<tilt>85</tilt>", "<tilt>190</tilt>")),
            "tour.kml:31: Camera.tilt: 190 is outside 0..180");
  EXPECT_EQ(errorOf("tour.kml", tourWith("<altitude>6000</altitude>", "")),
            "tour.kml:11: Camera.altitude: missing <altitude>");
  EXPECT_EQ(errorOf("tour.kml", tourWith("<longitude>138.80</longitude>", "")),
            "tour.kml:38: Camera.longitude: missing <longitude>");
  EXPECT_EQ(
      errorOf("tour.kml", tourWith("<gx:duration>3</gx:duration>", "<gx:duration>0</gx:duration>")),
      "tour.kml:24: gx:FlyTo.duration: 0 s after the previous keyframe: times must "
      "increase strictly (an instant jump is not supported)");
  EXPECT_EQ(errorOf("tour.kml",
                    tourWith("<gx:duration>3</gx:duration>", "<gx:duration>-3</gx:duration>")),
            "tour.kml:24: gx:FlyTo.duration: -3 is not at least 0");
  EXPECT_EQ(errorOf("tour.kml", tourWith("<gx:flyToMode>smooth</gx:flyToMode>",
                                         "<gx:flyToMode>warp</gx:flyToMode>")),
            "tour.kml:10: gx:flyToMode: 'warp' is not smooth or bounce");
  EXPECT_EQ(errorOf("tour.kml", tourWith("<altitudeMode>absolute</altitudeMode>",
                                         "<altitudeMode>relativeToSeaFloor</altitudeMode>")),
            "tour.kml:18: Camera.altitudeMode: relativeToSeaFloor is not supported (use absolute "
            "or relativeToGround)");
  std::string lookAt = kTour;  // the last FlyTo looks at a point instead, without a range
  lookAt.replace(lookAt.rfind("<Camera>"), 8, "<LookAt>");
  lookAt.replace(lookAt.rfind("</Camera>"), 9, "</LookAt>");
  EXPECT_EQ(errorOf("tour.kml", lookAt),
            "tour.kml:38: LookAt.range: missing <range>");
  // tinyxml2 names the line where the element holding the stray end tag starts.
  EXPECT_EQ(errorOf("tour.kml", tourWith("</Camera>", "</Camera></gx:FlyTo>")),
            "tour.kml:7: not valid XML: XML_ERROR_MISMATCHED_ELEMENT (XMLElement "
            "name=gx:Playlist)");
  EXPECT_EQ(errorOf("tour.kml", tourWith("<tilt>85</tilt>", "<tilt a='1>85</tilt>")),
            "tour.kml:31: not valid XML: XML_ERROR_PARSING_ATTRIBUTE (XMLElement name=tilt)");
  EXPECT_EQ(errorOf("none.kml", "<kml><Document/></kml>"), "none.kml:1: no <gx:Tour> in the file");
  EXPECT_EQ(errorOf("empty.kml", "<kml>\n<gx:Tour>\n<gx:Playlist>\n</gx:Playlist></gx:Tour></kml>"),
            "empty.kml:3: gx:Playlist has no gx:FlyTo with a Camera or LookAt (a path needs at "
            "least 1 keyframe)");
  EXPECT_EQ(errorOf("deep.kml", std::string(2000, '<')).rfind("deep.kml:1: not valid XML", 0), 0u);
  const std::string nested = "<kml>" + [] {
    std::string s;
    for (int i = 0; i < 5000; ++i) s += "<a>";
    for (int i = 0; i < 5000; ++i) s += "</a>";
    return s;
  }() + "</kml>";
  EXPECT_EQ(errorOf("nested.kml", nested).rfind("nested.kml:1: not valid XML", 0), 0u);
}

TEST(ParseDecimal, OverflowIsInfinityUnderflowIsZeroAndNonNumbersAreRefused) {
  const double inf = std::numeric_limits<double>::infinity();
  const std::pair<const char*, double> numbers[] = {
      {"0", 0.0},       {"-2.5", -2.5},    {"1e308", 1e308},       {"1e999", inf},
      {"-1e999", -inf}, {"1E400", inf},    {"inf", inf},           {"-infinity", -inf},
      {"1e-999", 0.0},  {"-1e-400", -0.0}, {"4.9e-324", 4.9e-324}, {"1e+400", inf},
  };
  for (const auto& [text, value] : numbers) {
    const auto parsed = parseDecimal(text);
    ASSERT_TRUE(parsed) << text;
    EXPECT_EQ(*parsed, value) << text;
    EXPECT_EQ(std::signbit(*parsed), std::signbit(value)) << text;
  }
  // 400 digits with no exponent overflow too, and 400 zeros after the point underflow.
  EXPECT_EQ(parseDecimal(std::string(400, '9')), inf);
  EXPECT_EQ(parseDecimal("0." + std::string(400, '0') + "1"), 0.0);
  for (const char* text : {"nan", "-nan", "NaN", "nan(1)"}) {
    const auto parsed = parseDecimal(text);
    ASSERT_TRUE(parsed) << text;
    EXPECT_TRUE(std::isnan(*parsed)) << text;
  }
  for (const char* text : {"", " 1", "1 ", "+1", "1,5", "0x10", "1e", "--1", "n", "e5", "1..2"}) {
    EXPECT_FALSE(parseDecimal(text)) << "'" << text << "'";
  }
}

TEST_F(PathFiles, KmlDurationsWhoseSumOverflowsAreRefused) {
  // Each duration is finite, the tour's time is not: 1e308 + 1e308.
  const std::string big = "<gx:duration>1e308</gx:duration>";
  std::string flyTos = tourWith("<gx:duration>3</gx:duration>", big);
  flyTos = flyTos.replace(flyTos.find("<gx:duration>2</gx:duration>"), 28, big);
  EXPECT_EQ(errorOf("sum.kml", flyTos),
            "sum.kml:37: gx:FlyTo.duration: the tour's time passes 1.7976931348623157e+308 s "
            "(not a finite number)");
  // A number too small for a double is 0: accepted where 0 is in range.
  auto tiny = readCameraPath(write("tiny.kml", tourWith("<roll>2</roll>", "<roll>1e-999</roll>")));
  ASSERT_TRUE(tiny) << tiny.error();
  EXPECT_EQ(tiny->keyframes[2].rollDegrees, 0.0);
}

TEST_F(PathFiles, TheBundledExamplesRead) {
  const std::string dir = std::string(GLOBE_SOURCE_DIR) + "/data/paths/";
  auto demo = readCameraPath(dir + "fuji-demo.json");
  ASSERT_TRUE(demo) << demo.error();
  EXPECT_GE(demo->keyframes.back().timeSeconds, 20);
  EXPECT_EQ(demo->keyframes.front().heightMeters, 20000);
  auto tour = readCameraPath(dir + "fuji-tour.kml");
  ASSERT_TRUE(tour) << tour.error();
  EXPECT_EQ(tour->keyframes.size(), 5u);
  EXPECT_EQ(tour->interpolation, "smooth");
  EXPECT_EQ(tour->keyframes.back().timeSeconds, 17.5);
}

}  // namespace
}  // namespace globe::camera
