#include "apps/globe/camera_argument.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <string_view>
#include <vector>

#include "camera/path_checks.hpp"

namespace globe::app {
namespace {

// The fields of `text` split at every separator (an empty text has none; "1,,2" and "1,2," have
// an empty field, which is not a number).
Result<std::vector<double>> parseNumbers(const std::string& text, char separator,
                                         const char* what) {
  std::vector<double> values;
  if (text.empty()) return values;
  for (size_t begin = 0;;) {
    const size_t end = std::min(text.find(separator, begin), text.size());
    const std::string field = text.substr(begin, end - begin);
    const std::optional<double> value = camera::parseDecimal(field);
    if (!value) {
      return makeError(std::string(what) + " '" + text + "': '" + field + "' is not a number");
    }
    if (!std::isfinite(*value)) {
      return makeError(std::string(what) + " '" + text + "': '" + field +
                       "' is not a finite number");
    }
    values.push_back(*value);
    if (end == text.size()) return values;
    begin = end + 1;
  }
}

}  // namespace

Result<camera::CameraPose> parseCameraArgument(const std::string& text) {
  auto values = parseNumbers(text, ',', "--camera");
  if (!values) return Error{values.error()};
  const std::vector<double>& v = *values;
  if (v.size() != 3 && v.size() != 6) {
    return makeError("--camera '" + text + "': expected LON,LAT,HEIGHT[,HEADING,PITCH,ROLL]");
  }
  if (v[1] < -90 || v[1] > 90)
    return makeError("--camera '" + text + "': latitude must be within -90..90");
  if (v[0] < -180 || v[0] > 180) {  // not wrapped: 200 is more likely a slip than 200-360
    return makeError("--camera '" + text + "': longitude out of range (-180..180)");
  }
  if (v[2] < -12000 || v[2] > 1e9) {
    return makeError("--camera '" + text + "': height must be between -12000 m and 1e9 m");
  }
  return v.size() == 3 ? camera::CameraPose::fromDegrees(v[0], v[1], v[2])
                       : camera::CameraPose::fromDegrees(v[0], v[1], v[2], v[3], v[4], v[5]);
}

Result<std::pair<int, int>> parseSizeArgument(const std::string& text) {
  const auto x = text.find('x');
  int w = 0, h = 0;
  if (x == std::string::npos)
    return makeError("--size '" + text + "': expected WxH, e.g. 1280x720");
  const auto [e1, r1] = std::from_chars(text.data(), text.data() + x, w);
  const auto [e2, r2] = std::from_chars(text.data() + x + 1, text.data() + text.size(), h);
  if (r1 != std::errc() || r2 != std::errc() || e1 != text.data() + x ||
      e2 != text.data() + text.size()) {
    return makeError("--size '" + text + "': expected WxH, e.g. 1280x720");
  }
  if (w < 1 || h < 1 || w > 16384 || h > 16384) {
    return makeError("--size '" + text + "': width and height must be 1..16384");
  }
  return std::pair{w, h};
}

Result<double> parseNumberArgument(std::string_view option, const std::string& text, double minimum,
                                   double maximum, bool minimumExcluded) {
  const std::string named = std::string(option) + " '" + text + "': ";
  const std::optional<double> value = camera::parseDecimal(text);
  if (!value) return makeError(named + "not a number");
  if (!std::isfinite(*value)) return makeError(named + "not a finite number");
  if (*value < minimum || (minimumExcluded && *value == minimum) || *value > maximum) {
    return makeError(named + "must be in " + (minimumExcluded ? "(" : "[") +
                     camera::detail::formatNumber(minimum) + ", " +
                     camera::detail::formatNumber(maximum) + "]");
  }
  return *value;
}

}  // namespace globe::app
