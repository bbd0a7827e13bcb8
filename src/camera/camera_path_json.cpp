// The JSON camera path format: nlohmann parses, JsonLocations gives every error its line.
#include <algorithm>
#include <array>
#include <functional>
#include <tuple>
#include <nlohmann/json.hpp>
#include <string_view>

#include "camera/camera_path_file.hpp"
#include "camera/camera_path_shots.hpp"
#include "camera/json_locations.hpp"
#include "camera/path_checks.hpp"
#include "sun/utc_time.hpp"
#include "transport/atomic_file.hpp"

namespace globe::camera {
namespace {

using detail::kUnbounded;
using nlohmann::json;

struct NumberField {
  const char* name;
  double PathKeyframe::*member;
  bool required;
  double minimum, maximum;
};

constexpr std::array<NumberField, 7> kNumberFields = {{
    {"t", &PathKeyframe::timeSeconds, true, -kUnbounded, kUnbounded},
    {"lon", &PathKeyframe::longitudeDegrees, true, -180, 180},
    {"lat", &PathKeyframe::latitudeDegrees, true, -90, 90},
    {"height", &PathKeyframe::heightMeters, true, kPathMinimumHeightMeters,
     kPathMaximumHeightMeters},
    {"heading", &PathKeyframe::headingDegrees, false, -kUnbounded, kUnbounded},
    {"pitch", &PathKeyframe::pitchDegrees, false, -90, 90},
    {"roll", &PathKeyframe::rollDegrees, false, -kUnbounded, kUnbounded},
}};
constexpr std::string_view kKeyframeFields =
    "t, lon, lat, height, heading, pitch, roll, aboveTerrain, time, ease, target, fov";

std::string_view typeName(const json& value) {
  return value.is_number()    ? "a number"
         : value.is_string()  ? "a string"
         : value.is_boolean() ? "a boolean"
         : value.is_null()    ? "null"
         : value.is_array()   ? "an array"
                              : "an object";
}

using FieldFailure = std::function<Error(const std::string& field, const std::string& what)>;

// "ease": a named curve or [x1, y1, x2, y2] (CSS cubic-bezier, x1 and x2 in 0..1).
Result<CubicBezierEase> readEase(const json& value, const FieldFailure& fail) {
  constexpr std::string_view kExpected = "linear, in, out, inOut or [x1, y1, x2, y2]";
  if (value.is_string()) {
    const std::string name = value.get<std::string>();
    if (auto ease = namedEase(name)) return *ease;
    return fail("ease", "'" + name.substr(0, 40) + "' is not " + std::string(kExpected));
  }
  if (!value.is_array() || value.size() != 4 ||
      !std::all_of(value.begin(), value.end(), [](const json& v) { return v.is_number(); })) {
    return fail("ease", "expected " + std::string(kExpected) + ", got " +
                            std::string(typeName(value)));
  }
  const std::array<double, 4> n{value[0].get<double>(), value[1].get<double>(),
                                value[2].get<double>(), value[3].get<double>()};
  for (size_t i = 0; i < n.size(); ++i) {
    const bool isX = i % 2 == 0;
    if (auto problem = detail::checkNumber(detail::formatNumber(n[i]), n[i],
                                           isX ? 0.0 : -kUnbounded, isX ? 1.0 : kUnbounded)) {
      return fail("ease[" + std::to_string(i) + "]", *problem);
    }
  }
  return CubicBezierEase{n[0], n[1], n[2], n[3]};
}

// "target": {"lon", "lat", "height", "aboveTerrain"?}.
Result<PathTarget> readTarget(const json& value, const FieldFailure& fail) {
  if (!value.is_object()) {
    return fail("target", "expected an object {\"lon\", \"lat\", \"height\"}, got " +
                              std::string(typeName(value)));
  }
  PathTarget target;
  const std::array<std::tuple<const char*, double PathTarget::*, double, double>, 3> fields = {{
      {"lon", &PathTarget::longitudeDegrees, -180, 180},
      {"lat", &PathTarget::latitudeDegrees, -90, 90},
      {"height", &PathTarget::heightMeters, kPathMinimumHeightMeters, kPathMaximumHeightMeters},
  }};
  for (const auto& item : value.items()) {
    const std::string& key = item.key();
    if (key != "lon" && key != "lat" && key != "height" && key != "aboveTerrain") {
      return fail("target." + key, "unknown field (a target has lon, lat, height, aboveTerrain)");
    }
  }
  for (const auto& [name, member, minimum, maximum] : fields) {
    const auto it = value.find(name);
    if (it == value.end()) return fail("target", std::string("missing field '") + name + "'");
    if (!it->is_number()) {
      return fail(std::string("target.") + name,
                  "expected a number, got " + std::string(typeName(*it)));
    }
    const double number = it->get<double>();
    if (auto problem =
            detail::checkNumber(detail::formatNumber(number), number, minimum, maximum)) {
      return fail(std::string("target.") + name, *problem);
    }
    target.*member = number;
  }
  if (const auto it = value.find("aboveTerrain"); it != value.end()) {
    if (!it->is_boolean()) {
      return fail("target.aboveTerrain",
                  "expected true or false, got " + std::string(typeName(*it)));
    }
    target.heightAboveTerrain = it->get<bool>();
  }
  return target;
}

// Reads and checks one keyframe object; `previous` is the keyframe before it, if any.
Result<PathKeyframe> readKeyframe(const json& object, const std::string& where,
                                  const JsonLocations& at, const std::filesystem::path& path,
                                  const PathKeyframe* previous) {
  auto fail = [&](const std::string& field, const std::string& what) -> Error {
    const std::string name = field.empty() ? where : where + "." + field;
    return makeError(detail::fileLine(path, at.line(name)) + name + ": " + what);
  };
  if (!object.is_object()) {
    return fail("", "expected a keyframe object, got " + std::string(typeName(object)));
  }
  for (const auto& item : object.items()) {
    const std::string& key = item.key();  // not a structured binding: clang 14 cannot capture one
    const bool known = key == "aboveTerrain" || key == "time" || key == "ease" || key == "target" ||
                       key == "fov" ||
                       std::any_of(kNumberFields.begin(), kNumberFields.end(),
                                   [&](const NumberField& field) { return key == field.name; });
    if (!known) {
      return fail(key, "unknown field (a keyframe has " + std::string(kKeyframeFields) + ")");
    }
  }
  PathKeyframe keyframe;
  for (const NumberField& field : kNumberFields) {
    const auto it = object.find(field.name);
    if (it == object.end()) {
      if (field.required) return fail("", std::string("missing field '") + field.name + "'");
      continue;
    }
    if (!it->is_number()) {
      return fail(field.name, "expected a number, got " + std::string(typeName(*it)));
    }
    const double value = it->get<double>();
    if (auto problem = detail::checkNumber(at.written(where + "." + field.name), value,
                                           field.minimum, field.maximum)) {
      return fail(field.name, *problem);
    }
    keyframe.*field.member = value;
  }
  if (const auto it = object.find("aboveTerrain"); it != object.end()) {
    if (!it->is_boolean()) {
      return fail("aboveTerrain", "expected true or false, got " + std::string(typeName(*it)));
    }
    keyframe.heightAboveTerrain = it->get<bool>();
  }
  if (const auto it = object.find("time"); it != object.end()) {
    if (!it->is_string()) {
      return fail("time", "expected an ISO-8601 string, got " + std::string(typeName(*it)));
    }
    auto instant = sun::parseUtcTime(it->get<std::string>());
    if (!instant) return fail("time", instant.error());
    keyframe.sunUnixSeconds = *instant;
  }
  if (const auto it = object.find("ease"); it != object.end()) {
    auto ease = readEase(*it, fail);
    if (!ease) return Error{ease.error()};
    keyframe.ease = *ease;
  }
  if (const auto it = object.find("fov"); it != object.end()) {
    if (!it->is_number()) {
      return fail("fov", "expected a number (degrees), got " + std::string(typeName(*it)));
    }
    const double fov = it->get<double>();
    if (auto problem = detail::checkNumber(at.written(where + ".fov"), fov, 1, 170)) {
      return fail("fov", *problem);
    }
    keyframe.fovDegrees = fov;
  }
  if (const auto it = object.find("target"); it != object.end()) {
    auto target = readTarget(*it, fail);
    if (!target) return Error{target.error()};
    keyframe.target = *target;
  }
  if (previous != nullptr) {
    if (auto problem = detail::checkTimeAfter(at.written(where + ".t"), keyframe.timeSeconds,
                                              previous->timeSeconds)) {
      return fail("t", *problem);
    }
  }
  return keyframe;
}

Result<CameraPathFile> parsePath(std::string_view text, const std::filesystem::path& path) {
  json document;
  try {
    document = json::parse(text);
  } catch (const json::parse_error& error) {
    // nlohmann's message is "[json.exception.parse_error.101] parse error at line L, column C:
    // what"; the line comes from its byte position, the text after the position is kept.
    std::string what = error.what();
    if (const size_t colon = what.find(": "); colon != std::string::npos) what.erase(0, colon + 2);
    const size_t offset = error.byte > 0 ? error.byte - 1 : 0;
    return makeError(detail::fileLine(path, lineOfOffset(text, offset)) +
                     "not valid JSON: " + what);
  } catch (const json::exception& error) {
    // A number too large for a double ("number overflow parsing '1e999'", no position): found by
    // its text, it is reported like any other non-finite value.
    const std::string what = error.what();
    const size_t open = what.find('\''), close = what.rfind('\'');
    if (open != std::string::npos && close > open) {
      const std::string token = what.substr(open + 1, close - open - 1);
      const JsonLocations at(text);
      if (const std::string name = at.pathWritten(token); !name.empty()) {
        return makeError(detail::fileLine(path, at.line(name)) + name + ": " + token +
                         " is not a finite number");
      }
    }
    return makeError(detail::fileLine(path, 1) + "not valid JSON: " + what);
  }
  const JsonLocations at(text);
  auto fail = [&](const std::string& name, const std::string& what) -> Error {
    return makeError(detail::fileLine(path, at.line(name)) + name + ": " + what);
  };
  if (!document.is_object()) {
    return makeError(detail::fileLine(path, at.line("")) +
                     "expected an object {\"keyframes\": [...]}, got " +
                     std::string(typeName(document)));
  }
  for (const auto& [key, value] : document.items()) {
    (void)value;
    if (key != "keyframes" && key != "interpolation" && key != "description" &&
        key != "altitude" && key != "orbit" && key != "flyTo") {
      return fail(key,
                  "unknown field (the top level has keyframes, interpolation, altitude, "
                  "description, or a shot: orbit, flyTo)");
    }
  }
  CameraPathFile file;
  if (const auto it = document.find("interpolation"); it != document.end()) {
    if (!it->is_string()) {
      return fail("interpolation",
                  "expected \"linear\" or \"smooth\", got " + std::string(typeName(*it)));
    }
    file.interpolation = it->get<std::string>();
    if (file.interpolation != "linear" && file.interpolation != "smooth") {
      return fail("interpolation",
                  at.written("interpolation") + " is not \"linear\" or \"smooth\"");
    }
  }
  if (const auto it = document.find("altitude"); it != document.end()) {
    if (!it->is_string() || (*it != "linear" && *it != "logarithmic")) {
      return fail("altitude", (it->is_string() ? at.written("altitude") : std::string(typeName(*it))) +
                                  " is not \"linear\" or \"logarithmic\"");
    }
    file.logarithmicAltitude = *it == "logarithmic";
  }
  const int given = static_cast<int>(document.contains("keyframes")) +
                    static_cast<int>(document.contains("orbit")) +
                    static_cast<int>(document.contains("flyTo"));
  if (given > 1) {
    return makeError(detail::fileLine(path, at.line("")) +
                     "give one of keyframes, orbit or flyTo, not several");
  }
  auto shot = detail::readShot(document, fail);
  if (!shot) return Error{shot.error()};
  if (*shot) {
    file.keyframes = std::move(**shot);
    if (!document.contains("interpolation")) file.interpolation = "smooth";
    return file;
  }
  const auto keyframes = document.find("keyframes");
  if (keyframes == document.end()) {
    return makeError(detail::fileLine(path, at.line("")) +
                     "missing field 'keyframes' (or a shot: orbit, flyTo)");
  }
  if (!keyframes->is_array()) {
    return fail("keyframes", "expected an array, got " + std::string(typeName(*keyframes)));
  }
  if (keyframes->empty()) return fail("keyframes", "empty: a path needs at least 1 keyframe");
  for (size_t k = 0; k < keyframes->size(); ++k) {
    auto keyframe = readKeyframe((*keyframes)[k], "keyframes[" + std::to_string(k) + "]", at, path,
                                 file.keyframes.empty() ? nullptr : &file.keyframes.back());
    if (!keyframe) return Error{keyframe.error()};
    file.keyframes.push_back(*keyframe);
  }
  return file;
}

// ", \"ease\": \"inOut\"" or its four numbers; "" without one.
std::string easeText(const std::optional<CubicBezierEase>& ease) {
  if (!ease) return "";
  if (const std::string_view name = easeName(*ease); !name.empty()) {
    return ", \"ease\": \"" + std::string(name) + "\"";
  }
  return ", \"ease\": [" + detail::formatNumber(ease->x1) + ", " + detail::formatNumber(ease->y1) +
         ", " + detail::formatNumber(ease->x2) + ", " + detail::formatNumber(ease->y2) + "]";
}

std::string targetText(const std::optional<PathTarget>& target) {
  if (!target) return "";
  return ", \"target\": {\"lon\": " + detail::formatNumber(target->longitudeDegrees) +
         ", \"lat\": " + detail::formatNumber(target->latitudeDegrees) +
         ", \"height\": " + detail::formatNumber(target->heightMeters) +
         (target->heightAboveTerrain ? ", \"aboveTerrain\": true}" : "}");
}

}  // namespace

Result<CameraPathFile> readCameraPathJson(const std::filesystem::path& path) {
  auto bytes = transport::readWholeFile(path, kPathFileMaximumBytes);
  if (!bytes) return Error{bytes.error()};
  const std::string_view text(reinterpret_cast<const char*>(bytes->data()), bytes->size());
  return parsePath(text, path);
}

Result<void> writeCameraPathJson(const std::filesystem::path& path, const CameraPathFile& file) {
  if (auto problem = detail::firstProblem(file)) {
    return makeError(path.string() + ": not written: " + *problem);
  }
  std::string text = "{\n  \"interpolation\": \"" + file.interpolation + "\",\n" +
                     (file.logarithmicAltitude ? "  \"altitude\": \"logarithmic\",\n" : "") +
                     "  \"keyframes\": [\n";
  for (size_t k = 0; k < file.keyframes.size(); ++k) {
    const PathKeyframe& key = file.keyframes[k];
    text += "    {";
    for (size_t f = 0; f < kNumberFields.size(); ++f) {
      text += std::string(f > 0 ? ", " : "") + "\"" + kNumberFields[f].name +
              "\": " + detail::formatNumber(key.*kNumberFields[f].member);
    }
    if (key.heightAboveTerrain) text += ", \"aboveTerrain\": true";
    if (key.sunUnixSeconds) text += ", \"time\": \"" + sun::formatUtcTime(*key.sunUnixSeconds) + "\"";
    text += easeText(key.ease) + targetText(key.target);
    if (key.fovDegrees) text += ", \"fov\": " + detail::formatNumber(*key.fovDegrees);
    text += k + 1 < file.keyframes.size() ? "},\n" : "}\n";
  }
  text += "  ]\n}\n";
  return transport::writeFileAtomically(path, text);
}

}  // namespace globe::camera
