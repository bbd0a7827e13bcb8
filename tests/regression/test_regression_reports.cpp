// The three reports of a run: report.json (null where a view was not compared, never a made-up
// figure), junit.xml as CI systems parse it (escaped, counted), report.html with each failed view's
// three images.
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "regression/regression_report.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::regression {
namespace {

namespace fs = std::filesystem;

ViewOutcome outcome(const char* name, ViewStatus status, double fraction, int largest,
                    double ssim, double seconds, const char* message) {
  ViewOutcome o;
  o.name = name;
  o.status = status;
  o.hasMetrics = status != ViewStatus::error;
  o.differingFraction = fraction;
  o.largestChannelDifference = largest;
  o.meanSsim = ssim;
  o.lowestWindowSsim = ssim;
  o.seconds = seconds;
  o.message = message;
  o.imagesWritten = status == ViewStatus::fail;
  return o;
}

std::vector<ViewOutcome> outcomes() {
  return {outcome("summit", ViewStatus::pass, 0, 3, 0.9999, 1.25, ""),
          outcome("coast", ViewStatus::fail, 0.02, 200, 0.97, 2, "2% <differ> & \"more\""),
          outcome("gone", ViewStatus::error, 1, 255, 0, 0.1,
                  "globe snapshot exited with 2: no such pyramid")};
}

std::string readText(const fs::path& file) {
  std::stringstream text;
  text << std::ifstream(file).rdbuf();
  return text.str();
}

TEST(RegressionReports, JsonJunitAndHtmlSayTheSame) {
  const fs::path dir = globe::testing::freshTempDir("regression-reports");
  const auto views = outcomes();
  const RunSummary summary = summarize(views, 3.5);
  EXPECT_EQ(summary.passed, 1u);
  EXPECT_EQ(summary.failed, 1u);
  EXPECT_EQ(summary.errors, 1u);
  ASSERT_TRUE(writeJsonReport(dir, views, summary));
  ASSERT_TRUE(writeJunitReport(dir, "my suite", views, summary));
  ASSERT_TRUE(writeHtmlReport(dir, "my suite", views, summary));

  const auto json = nlohmann::json::parse(readText(dir / "report.json"));
  ASSERT_EQ(json["views"].size(), 3u);
  EXPECT_EQ(json["views"][1]["status"], "fail");
  EXPECT_EQ(json["views"][1]["differingFraction"], 0.02);
  EXPECT_EQ(json["views"][1]["images"]["diff"], "coast.diff.png");
  EXPECT_TRUE(json["views"][2]["differingFraction"].is_null()) << "an error has no figures";
  EXPECT_TRUE(json["views"][2]["ssim"].is_null());
  EXPECT_EQ(json["views"][0]["tolerance"]["channel"], Tolerance{}.channelThreshold);

  tinyxml2::XMLDocument junit;
  ASSERT_EQ(junit.LoadFile((dir / "junit.xml").c_str()), tinyxml2::XML_SUCCESS);
  const auto* suite = junit.FirstChildElement("testsuites")->FirstChildElement("testsuite");
  ASSERT_NE(suite, nullptr);
  EXPECT_STREQ(suite->Attribute("tests"), "3");
  EXPECT_STREQ(suite->Attribute("failures"), "1");
  EXPECT_STREQ(suite->Attribute("errors"), "1");
  const auto* first = suite->FirstChildElement("testcase");
  EXPECT_STREQ(first->Attribute("name"), "summit");
  EXPECT_EQ(first->FirstChildElement(), nullptr) << "a pass has no child";
  const auto* failure = first->NextSiblingElement()->FirstChildElement("failure");
  ASSERT_NE(failure, nullptr);
  EXPECT_STREQ(failure->Attribute("message"), "2% <differ> & \"more\"") << "escaped and read back";
  EXPECT_NE(first->NextSiblingElement()->NextSiblingElement()->FirstChildElement("error"), nullptr);

  const std::string html = readText(dir / "report.html");
  for (const char* image : {"coast.expected.png", "coast.actual.png", "coast.diff.png"}) {
    EXPECT_NE(html.find(std::string("src=\"") + image + "\""), std::string::npos) << image;
  }
  EXPECT_EQ(html.find("summit.diff.png"), std::string::npos) << "only failed views' images";
  EXPECT_NE(html.find("2% &lt;differ&gt; &amp; &quot;more&quot;"), std::string::npos);
}

}  // namespace
}  // namespace globe::regression
