// junit.xml as CI systems read it (GitLab, Jenkins, GitHub's test-report actions): one
// <testsuite>, one <testcase> per view; a failed view is a <failure>, a view that could not be
// rendered an <error>; an updated reference passes (the run wrote it).
#include <cstdio>
#include <sstream>

#include "core/xml_escape.hpp"
#include "regression/regression_report.hpp"
#include "transport/atomic_file.hpp"

namespace globe::regression {

Result<void> writeJunitReport(const std::filesystem::path& outFolder, const std::string& suiteName,
                              const std::vector<ViewOutcome>& outcomes,
                              const RunSummary& summary) {
  std::ostringstream xml;
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.3f", summary.seconds);
  xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<testsuites name=\"globe regress\" tests=\"" << outcomes.size() << "\" failures=\""
      << summary.failed << "\" errors=\"" << summary.errors << "\" time=\"" << seconds << "\">\n"
      << "  <testsuite name=\"" << xmlEscaped(suiteName) << "\" tests=\"" << outcomes.size()
      << "\" failures=\"" << summary.failed << "\" errors=\"" << summary.errors
      << "\" skipped=\"0\" time=\"" << seconds << "\">\n";
  for (const ViewOutcome& o : outcomes) {
    std::snprintf(seconds, sizeof seconds, "%.3f", o.seconds);
    xml << "    <testcase classname=\"" << xmlEscaped(suiteName) << "\" name=\""
        << xmlEscaped(o.name) << "\" time=\"" << seconds << "\"";
    // By status (pass, fail, error, updated): the element that says why it did not pass.
    static constexpr const char* kElements[] = {nullptr, "failure", "error", nullptr};
    const char* element = kElements[static_cast<int>(o.status)];
    if (element == nullptr) {
      xml << "/>\n";
      continue;
    }
    xml << ">\n      <" << element << " message=\"" << xmlEscaped(o.message) << "\">"
        << xmlEscaped(o.message) << "</" << element << ">\n    </testcase>\n";
  }
  xml << "  </testsuite>\n</testsuites>\n";
  return transport::writeFileAtomically(outFolder / "junit.xml", xml.str());
}

}  // namespace globe::regression
