// The value checks the camera path readers and writer share: finite numbers in range, strictly
// increasing times, and the messages that name what is wrong.
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include "camera/camera_path_file.hpp"

namespace globe::camera {

// A decimal number as written in a file or on the command line (std::from_chars' general format:
// no leading '+' or spaces; "nan", "inf" and "infinity" are read as such, to be refused by the
// caller's finiteness check). A value too large for a double reads as +-infinity and one too
// small as +-0, as strtod gives them. nullopt when the text is not a number.
std::optional<double> parseDecimal(std::string_view text);

}  // namespace globe::camera

namespace globe::camera::detail {

inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

// nullopt when value is finite and in minimum..maximum; else "95 is outside -90..90" or "1e999 is
// not a finite number", quoting the value as written in the file.
std::optional<std::string> checkNumber(std::string_view written, double value, double minimum,
                                       double maximum);

// "2 is not after the previous keyframe's 5: times must increase strictly" (or "repeats").
std::optional<std::string> checkTimeAfter(std::string_view written, double timeSeconds,
                                          double previousSeconds);

// Text that reads back as the same double: integers in full ("40000000", "-11000"), others
// as short as possible ("0.1", "35.3606", "1e+20").
std::string formatNumber(double value);

// "/x/path.json:7: " — the location prefix of every reader error.
std::string fileLine(const std::filesystem::path& path, int line);

// The first problem of a whole path ("keyframes[2].lat: 95 is outside -90..90"), for writers.
std::optional<std::string> firstProblem(const CameraPathFile& file);

}  // namespace globe::camera::detail
