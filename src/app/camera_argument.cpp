#include "app/camera_argument.hpp"

#include <charconv>
#include <cmath>
#include <sstream>
#include <vector>

namespace globe::app {
namespace {

Result<std::vector<double>> parseNumbers(const std::string& text, char separator,
                                         const char* what) {
  std::vector<double> values;
  std::stringstream stream(text);
  std::string field;
  while (std::getline(stream, field, separator)) {
    double value = 0;
    const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (error != std::errc() || end != field.data() + field.size()) {
      return makeError(std::string(what) + " '" + text + "': '" + field + "' is not a number");
    }
    if (!std::isfinite(value)) {
      return makeError(std::string(what) + " '" + text + "': '" + field + "' is not finite");
    }
    values.push_back(value);
  }
  return values;
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
  if (v[0] < -540 || v[0] > 540)
    return makeError("--camera '" + text + "': longitude out of range");
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

}  // namespace globe::app
