// junit.xml as CI systems read it (GitLab, Jenkins, GitHub's test-report actions): one
// <testsuite>, one <testcase> per view; a failed view is a <failure>, a view that could not be
// rendered an <error>; an updated reference passes (the run wrote it). Valid under the strict
// Apache Ant schema and Jenkins' (tests/data/junit).
#include <cstdio>
#include <ctime>
#include <sstream>

#include "core/xml_escape.hpp"
#include "regression/regression_report.hpp"
#include "transport/atomic_file.hpp"

namespace globe::regression {

namespace {

// "YYYY-MM-DDTHH:MM:SS" in UTC, without a zone: the form the Ant schema's timestamp takes.
std::string utcTimestamp(int64_t secondsSince1970) {
  const std::time_t time = static_cast<std::time_t>(secondsSince1970);
  std::tm utc{};
  ::gmtime_r(&time, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%S", &utc);
  return text;
}

std::string threeDecimals(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", seconds);
  return text;
}

}  // namespace

Result<void> writeJunitReport(const std::filesystem::path& outFolder, const std::string& suiteName,
                              const std::vector<ViewOutcome>& outcomes,
                              const RunSummary& summary) {
  const std::string suite = xmlEscaped(suiteName.empty() ? "suite" : suiteName);
  std::ostringstream xml;
  xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites>\n"
      << "  <testsuite name=\"" << suite << "\" package=\"" << suite << "\" id=\"0\" hostname=\""
      << xmlEscaped(summary.hostname) << "\" timestamp=\"" << utcTimestamp(summary.startedUtcSeconds)
      << "\" tests=\"" << outcomes.size() << "\" failures=\"" << summary.failed << "\" errors=\""
      << summary.errors << "\" skipped=\"0\" time=\"" << threeDecimals(summary.seconds) << "\">\n"
      << "    <properties/>\n";
  for (const ViewOutcome& o : outcomes) {
    xml << "    <testcase classname=\"" << suite << "\" name=\"" << xmlEscaped(o.name)
        << "\" time=\"" << threeDecimals(o.seconds) << "\"";
    // By status (pass, fail, error, updated): the element that says why it did not pass, and its
    // type.
    struct Element {
      const char* name;
      const char* type;
    };
    static constexpr Element kElements[] = {
        {nullptr, nullptr}, {"failure", "differs"}, {"error", "not judged"}, {nullptr, nullptr}};
    const Element element = kElements[static_cast<int>(o.status)];
    if (element.name == nullptr) {
      xml << "/>\n";
      continue;
    }
    xml << ">\n      <" << element.name << " type=\"" << element.type << "\" message=\""
        << xmlEscaped(o.message) << "\">" << xmlEscaped(o.message) << "</" << element.name
        << ">\n    </testcase>\n";
  }
  xml << "    <system-out/>\n    <system-err/>\n  </testsuite>\n</testsuites>\n";
  return transport::writeFileAtomically(outFolder / "junit.xml", xml.str());
}

}  // namespace globe::regression
