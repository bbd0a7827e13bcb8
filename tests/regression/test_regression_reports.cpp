// The three reports of a run: report.json (null where a view was not compared, never a made-up
// figure), junit.xml as CI systems parse it (escaped, counted), report.html with each failed view's
// three images.
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "regression/regression_report.hpp"
#include "tests/support/build_paths.hpp"
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

// xmllint's complaints about `file` under tests/data/junit/SCHEMA; "" when it is valid.
std::string schemaErrors(const fs::path& file, const char* schema) {
  const fs::path xsd = fs::path(GLOBE_SOURCE_DIR) / "tests/data/junit" / schema;
  const std::string command =
      "xmllint --noout --schema '" + xsd.string() + "' '" + file.string() + "' 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return "popen failed";
  std::string output;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  const int status = ::pclose(pipe);
  return status == 0 ? "" : "exit status " + std::to_string(status) + ": " + output;
}

// Valid under the strict Ant schema (properties, system-out, system-err, a zoneless timestamp, a
// hostname, typed failures and errors) and Jenkins' xUnit one; a message with terminal colours
// and other control characters (which XML 1.0 forbids) still gives a valid document.
TEST(RegressionReports, JunitIsValidUnderTheAntAndJenkinsSchemas) {
  const fs::path dir = globe::testing::freshTempDir("regression-junit");
  auto views = outcomes();
  views.push_back(outcome("tty", ViewStatus::error, 1, 255, 0, 0.2,
                          "globe snapshot exited with 1: \x1b[31mred\x1b[0m \x01\x7f done"));
  RunSummary summary = summarize(views, 3.5);
  summary.startedUtcSeconds = 1765000000;
  summary.hostname = "ci-runner-7";
  ASSERT_TRUE(writeJunitReport(dir, "my suite", views, summary));
  const fs::path junit = dir / "junit.xml";
  EXPECT_EQ(schemaErrors(junit, "ant-junit.xsd"), "");
  EXPECT_EQ(schemaErrors(junit, "jenkins-junit-10.xsd"), "");
  const std::string xml = readText(junit);
  EXPECT_NE(xml.find("timestamp=\"2025-12-06T05:46:40\" "), std::string::npos) << xml;
  EXPECT_NE(xml.find("hostname=\"ci-runner-7\""), std::string::npos);
  EXPECT_NE(xml.find("red"), std::string::npos) << "the message is kept, its controls replaced";

  // The check can fail: a failure without its type is refused by the Ant schema.
  std::string broken = xml;
  broken.erase(broken.find(" type=\"differs\""), 15);
  std::ofstream(dir / "broken.xml", std::ios::binary) << broken;
  EXPECT_NE(schemaErrors(dir / "broken.xml", "ant-junit.xsd"), "");
}

}  // namespace
}  // namespace globe::regression
