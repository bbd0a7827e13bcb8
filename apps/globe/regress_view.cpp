#include "apps/globe/regress_view.hpp"

#include <cstdio>
#include <vector>

#include "transport/read_file.hpp"
#include "formats/image_io.hpp"
#include "regression/image_difference.hpp"
#include "regression/structural_similarity.hpp"
#include "transport/atomic_file.hpp"

namespace globe::app {
namespace {

namespace fs = std::filesystem;
using regression::ViewOutcome;
using regression::ViewStatus;

// A snapshot's log, bounded: what it says is a few lines; "" when there is none to read.
constexpr std::uintmax_t kMaxLogBytes = 16u << 20;
// A reference or an actual image copied whole: far above any image globe snapshot writes.
constexpr std::uintmax_t kMaxImageBytes = 1u << 30;

std::string readLog(const fs::path& log) {
  auto text = transport::readFileBounded(log, kMaxLogBytes);
  return text ? std::move(*text) : std::string();
}

// The last lines of the process's output: what it said about why it failed.
std::string logTail(const fs::path& log) {
  const std::string text = readLog(log);
  std::string tail = text.size() > 600 ? "..." + text.substr(text.size() - 600) : text;
  while (!tail.empty() && (tail.back() == '\n' || tail.back() == ' ')) tail.pop_back();
  for (char& c : tail) c = c == '\n' ? ' ' : c;
  return tail;
}

// The error a finished process gives, or "" when it rendered something.
std::string processError(const SnapshotExit& exit, const fs::path& log, double timeoutSeconds) {
  if (!exit.started) return exit.message;
  if (exit.timedOut) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "killed after %.1f s (its limit %.0f s, or the run's budget): ", exit.seconds,
                  timeoutSeconds);
    return text + logTail(log);
  }
  if (exit.signal != 0) return "globe snapshot died of signal " + std::to_string(exit.signal);
  if (exit.exitCode != 0) {
    return "globe snapshot exited with " + std::to_string(exit.exitCode) + ": " + logTail(log);
  }
  // Its summary line: "OUT.png: N tiles drawn, ...".
  const std::string text = readLog(log);
  const size_t drawn = text.find(" tiles drawn");
  if (drawn == std::string::npos) {
    return "globe snapshot did not say what it drew: " + logTail(log);
  }
  const size_t number = text.rfind(' ', drawn - 1);
  if (text.substr(number + 1, drawn - number - 1) == "0") {
    return "the view drew nothing (0 tiles drawn): " + logTail(log);
  }
  return "";
}

Result<void> copyFileAtomically(const fs::path& from, const fs::path& to) {
  std::error_code error;
  fs::create_directories(to.parent_path(), error);
  const auto bytes = transport::readFileBounded(from, kMaxImageBytes);
  if (!bytes) return makeError(bytes.error());
  if (bytes->empty()) return makeError(from.string() + ": empty");
  return transport::writeFileAtomically(to, *bytes);
}

void removeQuietly(const fs::path& file) {
  std::error_code ignored;
  fs::remove(file, ignored);
}

std::string failureMessage(const ViewOutcome& o) {
  char text[240];
  std::snprintf(text, sizeof text,
                "%.4f%% of pixels differ by more than %d (allowed %.4f%%), largest %d; SSIM %.4f "
                "(at least %.4f)",
                100 * o.differingFraction, o.tolerance.channelThreshold,
                100 * o.tolerance.differingFraction, o.largestChannelDifference, o.meanSsim,
                o.tolerance.minimumSsim);
  return text;
}

// The reference compared with the actual image: metrics, pass or fail, the images of a failure.
void compareWithReference(ViewOutcome& o, const formats::ImageRgba& expected,
                          const formats::ImageRgba& actual, const fs::path& out) {
  const auto difference =
      regression::compareImages(expected, actual, o.tolerance.channelThreshold);
  if (!difference.sameSize) {
    o.status = ViewStatus::fail;
    o.message = "the image is " + std::to_string(actual.widthPixels) + "x" +
                std::to_string(actual.heightPixels) + ", its reference " +
                std::to_string(expected.widthPixels) + "x" + std::to_string(expected.heightPixels);
    return;
  }
  const auto similarity = regression::structuralSimilarity(expected, actual);
  o.hasMetrics = true;
  o.differingFraction = difference.differingFraction;
  o.largestChannelDifference = difference.largestChannelDifference;
  o.meanSsim = similarity.meanSsim;
  o.lowestWindowSsim = similarity.lowestWindowSsim;
  const bool pass = o.differingFraction <= o.tolerance.differingFraction &&
                    o.meanSsim >= o.tolerance.minimumSsim;
  o.status = pass ? ViewStatus::pass : ViewStatus::fail;
  if (pass) return;
  o.message = failureMessage(o);
  const auto wroteExpected = formats::writePngAtomically(
      out / (o.name + ".expected.png"), expected.pixels, expected.widthPixels,
      expected.heightPixels);
  const auto wroteDiff = formats::writePngAtomically(
      out / (o.name + ".diff.png"), difference.diffRgba, actual.widthPixels, actual.heightPixels);
  o.imagesWritten = wroteExpected.ok() && wroteDiff.ok();
}

}  // namespace

fs::path actualPath(const fs::path& outFolder, const std::string& name) {
  return outFolder / (name + ".actual.png");
}

ViewOutcome judgeView(const regression::RegressionSuite& suite,
                      const regression::RegressionView& view, const fs::path& out,
                      const SnapshotExit& exit, bool update) {
  ViewOutcome o;
  o.name = view.name;
  o.tolerance = view.tolerance;
  o.seconds = exit.seconds;
  const fs::path log = out / (view.name + ".log");
  const fs::path actualFile = actualPath(out, view.name);
  const fs::path reference = regression::referencePath(suite, view.name);
  o.message = processError(exit, log, suite.timeoutSeconds);
  if (!o.message.empty()) return o;  // an error: the log stays for reading
  auto actual = formats::loadImageRgba(actualFile);
  if (!actual) {
    o.message = actual.error();
    return o;
  }
  std::error_code error;
  const bool known = fs::exists(reference, error);
  if (known) {
    auto expected = formats::loadImageRgba(reference);
    if (!expected) {
      o.message = "the reference: " + expected.error();
      return o;
    }
    compareWithReference(o, *expected, *actual, out);
  }
  if (update && (!known || o.status == ViewStatus::fail)) {
    const auto written = copyFileAtomically(actualFile, reference);
    o.status = written ? ViewStatus::updated : ViewStatus::error;
    o.message = !written ? written.error()
                         : (known ? "reference rewritten: " + o.message : "new reference written");
    o.imagesWritten = false;
    removeQuietly(out / (o.name + ".expected.png"));
    removeQuietly(out / (o.name + ".diff.png"));
  } else if (!known) {
    o.message = "no reference " + reference.string() + " (--update writes it)";
    return o;  // error
  }
  if (o.status != ViewStatus::fail) {
    removeQuietly(actualFile);
    removeQuietly(log);
  }
  return o;
}

}  // namespace globe::app
