// report.html: a page a person opens after a failed run. A table of every view (status, the
// metrics against their tolerances, time, message), then each failed view's expected, actual and
// diff images side by side (files beside the page, so the folder is the report: CI systems keep
// it as one artifact).
#include <cstdio>
#include <sstream>

#include "core/xml_escape.hpp"
#include "regression/regression_report.hpp"
#include "transport/atomic_file.hpp"

namespace globe::regression {
namespace {

constexpr const char* kStyle =
    "body{font:14px sans-serif;margin:1.5em;color:#222}table{border-collapse:collapse}"
    "td,th{border:1px solid #ccc;padding:3px 8px;text-align:left}"
    ".pass{color:#17702b}.fail{color:#b00}.error{color:#b00;font-weight:bold}.updated{color:#05c}"
    ".images{display:flex;gap:8px;flex-wrap:wrap}figure{margin:0}figcaption{font-size:12px}"
    "img{max-width:32vw;border:1px solid #999;image-rendering:pixelated}";

std::string metrics(const ViewOutcome& o) {
  if (!o.hasMetrics) return "<td>-</td><td>-</td>";
  char text[160];
  std::snprintf(text, sizeof text, "<td>%.5f (&le; %.5f)</td><td>%.4f (&ge; %.4f)</td>",
                o.differingFraction, o.tolerance.differingFraction, o.meanSsim,
                o.tolerance.minimumSsim);
  return text;
}

void writeImages(std::ostringstream& html, const ViewOutcome& o) {
  const std::string name = xmlEscaped(o.name);
  html << "<h2 id=\"" << name << "\">" << name << "</h2>\n<p>" << xmlEscaped(o.message)
       << "</p>\n<div class=\"images\">\n";
  static constexpr const char* kImages[][2] = {
      {"expected", "expected (the reference)"}, {"actual", "actual (this run)"},
      {"diff", "diff (red: beyond the channel threshold)"}};
  for (const auto& [suffix, caption] : kImages) {
    html << "<figure><img alt=\"" << name << " " << suffix << "\" src=\"" << name << "."
         << suffix << ".png\"><figcaption>" << caption << "</figcaption></figure>\n";
  }
  html << "</div>\n";
}

}  // namespace

Result<void> writeHtmlReport(const std::filesystem::path& outFolder, const std::string& suiteName,
                             const std::vector<ViewOutcome>& outcomes, const RunSummary& summary) {
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>globe regress: "
       << xmlEscaped(suiteName) << "</title><style>" << kStyle << "</style></head><body>\n"
       << "<h1>globe regress: " << xmlEscaped(suiteName) << "</h1>\n<p>" << outcomes.size()
       << " views: " << summary.passed << " passed, " << summary.failed << " failed, "
       << summary.errors << " errors, " << summary.updated << " references written</p>\n"
       << "<table><tr><th>view</th><th>status</th><th>differing pixels</th><th>SSIM</th>"
       << "<th>seconds</th><th>message</th></tr>\n";
  for (const ViewOutcome& o : outcomes) {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.2f", o.seconds);
    const std::string name = xmlEscaped(o.name);
    html << "<tr><td>"
         << (o.imagesWritten ? "<a href=\"#" + name + "\">" + name + "</a>" : name)
         << "</td><td class=\"" << statusName(o.status) << "\">" << statusName(o.status)
         << "</td>" << metrics(o) << "<td>" << seconds << "</td><td>" << xmlEscaped(o.message)
         << "</td></tr>\n";
  }
  html << "</table>\n";
  for (const ViewOutcome& o : outcomes) {
    if (o.imagesWritten) writeImages(html, o);
  }
  html << "</body></html>\n";
  return transport::writeFileAtomically(outFolder / "report.html", html.str());
}

}  // namespace globe::regression
