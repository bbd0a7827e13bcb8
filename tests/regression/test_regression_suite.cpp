// The suite file: what it accepts, and each mistake refused with the file, the view and the field.
#include <gtest/gtest.h>

#include "regression/regression_suite.hpp"

namespace globe::regression {
namespace {

Result<RegressionSuite> parse(const std::string& text) {
  return parseRegressionSuite(text, "suites/my-suite.json");
}

TEST(RegressionSuite, ReadsViewsToleranceAndTheFolder) {
  auto suite = parse(R"({"tolerance": {"channel": 24, "fraction": 0.005}, "timeoutSeconds": 30,
    "views": [{"name": "summit", "snapshot": ["pyramid", "--camera", "138.7,35.3,6000"]},
              {"name": "coast.2", "snapshot": ["pyramid", "--size", "480x270"],
               "tolerance": {"ssim": 0.95}}]})");
  ASSERT_TRUE(suite) << suite.error();
  EXPECT_EQ(suite->folder, "suites");
  EXPECT_EQ(suite->timeoutSeconds, 30);
  ASSERT_EQ(suite->views.size(), 2u);
  EXPECT_EQ(suite->views[0].snapshotArguments,
            (std::vector<std::string>{"pyramid", "--camera", "138.7,35.3,6000"}));
  EXPECT_EQ(suite->views[0].tolerance.channelThreshold, 24);
  EXPECT_EQ(suite->views[0].tolerance.minimumSsim, Tolerance{}.minimumSsim);
  EXPECT_EQ(suite->views[1].tolerance.differingFraction, 0.005) << "the suite's, inherited";
  EXPECT_EQ(suite->views[1].tolerance.minimumSsim, 0.95) << "the view's own";
  EXPECT_EQ(referencePath(*suite, "summit"), "suites/references/summit.png");
}

TEST(RegressionSuite, EachMistakeIsNamed) {
  const std::pair<const char*, const char*> cases[] = {
      {"[1, 2]", "must be a JSON object"},
      {"{\"views\": [", "not valid JSON"},
      {R"({"views": []})", "\"views\" must be a list of 1 to"},
      {R"({"view": []})", "unknown field \"view\""},
      {R"({"views": [{"name": "a", "snapshot": ["p"], "tolerence": {}}]})",
       "view 1 (a): unknown field \"tolerence\""},
      {R"({"views": [{"name": "../../etc/x", "snapshot": ["p"]}]})", "\"name\" must be"},
      {R"({"views": [{"name": ".hidden", "snapshot": ["p"]}]})", "\"name\" must be"},
      {R"({"views": [{"name": "a", "snapshot": []}]})", "non-empty list"},
      {R"({"views": [{"name": "a", "snapshot": ["p", 3]}]})", "non-string"},
      {R"({"views": [{"name": "a", "snapshot": ["p", "-o", "x.png"]}]})", "must not give -o"},
      {R"({"views": [{"name": "a", "snapshot": ["p", "--output=x.png"]}]})", "must not give -o"},
      {R"({"views": [{"name": "a", "snapshot": ["p"]}, {"name": "a", "snapshot": ["q"]}]})",
       "two views are named \"a\""},
      {R"({"tolerance": {"channel": 300}, "views": [{"name": "a", "snapshot": ["p"]}]})",
       "\"channel\" must be a number from 0 to 255"},
      {R"({"views": [{"name": "a", "snapshot": ["p"], "tolerance": {"fraction": "1%"}}]})",
       "\"fraction\" must be a number from 0 to 1"},
      {R"({"timeoutSeconds": 0, "views": [{"name": "a", "snapshot": ["p"]}]})",
       "\"timeoutSeconds\" must be a number from 1 to 86400"},
  };
  for (const auto& [text, expected] : cases) {
    auto suite = parse(text);
    ASSERT_FALSE(suite) << text;
    EXPECT_NE(suite.error().find("suites/my-suite.json"), std::string::npos) << suite.error();
    EXPECT_NE(suite.error().find(expected), std::string::npos) << text << " -> " << suite.error();
  }
}

TEST(RegressionSuite, AMissingFileIsNamed) {
  auto suite = loadRegressionSuite("/nonexistent/suite.json");
  ASSERT_FALSE(suite);
  EXPECT_EQ(suite.error(), "/nonexistent/suite.json: no such file (a regression suite)");
}

}  // namespace
}  // namespace globe::regression
