// Range checks and number formatting shared by the camera path readers and writer.
#include "camera/path_checks.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace globe::camera {

std::optional<double> parseDecimal(std::string_view text) {
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (end != text.data() + text.size() || text.empty()) return std::nullopt;
  if (error == std::errc::result_out_of_range) {
    // from_chars leaves the value alone on overflow and underflow alike; strtod tells them apart.
    return std::strtod(std::string(text).c_str(), nullptr);
  }
  if (error != std::errc()) return std::nullopt;
  return value;
}

}  // namespace globe::camera

namespace globe::camera::detail {

std::optional<std::string> checkNumber(std::string_view written, double value, double minimum,
                                       double maximum) {
  if (!std::isfinite(value)) return std::string(written) + " is not a finite number";
  if (value < minimum || value > maximum) {
    std::string range = minimum == -kUnbounded ? "at most " + formatNumber(maximum)
                        : maximum == kUnbounded
                            ? "at least " + formatNumber(minimum)
                            : formatNumber(minimum) + ".." + formatNumber(maximum);
    const bool bounded = minimum != -kUnbounded && maximum != kUnbounded;
    return std::string(written) + (bounded ? " is outside " : " is not ") + range;
  }
  return std::nullopt;
}

std::optional<std::string> checkTimeAfter(std::string_view written, double timeSeconds,
                                          double previousSeconds) {
  if (timeSeconds == previousSeconds) {
    return std::string(written) + " repeats the previous keyframe's time: times must increase " +
           "strictly";
  }
  if (timeSeconds < previousSeconds) {
    return std::string(written) + " is before the previous keyframe's " +
           formatNumber(previousSeconds) + ": times must increase strictly";
  }
  return std::nullopt;
}

std::string formatNumber(double value) {
  char text[64];
  if (std::isfinite(value) && std::abs(value) < 1e15 && value == std::trunc(value)) {
    std::snprintf(text, sizeof text, "%.0f", value == 0 ? 0.0 : value);  // 40000000, not 4e+07
    return text;
  }
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

std::string fileLine(const std::filesystem::path& path, int line) {
  return path.string() + ":" + std::to_string(line) + ": ";
}

std::optional<std::string> firstProblem(const CameraPathFile& file) {
  if (file.interpolation != "linear" && file.interpolation != "smooth") {
    return "interpolation: '" + file.interpolation + "' is not linear or smooth";
  }
  if (file.keyframes.empty()) return "keyframes: none (a path needs at least 1 keyframe)";
  for (size_t k = 0; k < file.keyframes.size(); ++k) {
    const PathKeyframe& key = file.keyframes[k];
    const std::string where = "keyframes[" + std::to_string(k) + "].";
    struct Field {
      const char* name;
      double value, minimum, maximum;
    };
    const Field fields[] = {
        {"t", key.timeSeconds, -kUnbounded, kUnbounded},
        {"lon", key.longitudeDegrees, -180, 180},
        {"lat", key.latitudeDegrees, -90, 90},
        {"height", key.heightMeters, kPathMinimumHeightMeters, kPathMaximumHeightMeters},
        {"heading", key.headingDegrees, -kUnbounded, kUnbounded},
        {"pitch", key.pitchDegrees, -90, 90},
        {"roll", key.rollDegrees, -kUnbounded, kUnbounded},
    };
    for (const Field& field : fields) {
      if (auto problem =
              checkNumber(formatNumber(field.value), field.value, field.minimum, field.maximum)) {
        return where + field.name + ": " + *problem;
      }
    }
    if (k > 0) {
      if (auto problem = checkTimeAfter(formatNumber(key.timeSeconds), key.timeSeconds,
                                        file.keyframes[k - 1].timeSeconds)) {
        return where + "t: " + *problem;
      }
    }
  }
  return std::nullopt;
}

}  // namespace globe::camera::detail
