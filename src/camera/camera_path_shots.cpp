// The JSON path format's shots ("orbit", "flyTo": camera/path_generators.hpp) read into keyframes.
#include "camera/camera_path_shots.hpp"

#include <algorithm>
#include <array>
#include <utility>

#include "camera/path_checks.hpp"
#include "camera/path_generators.hpp"

namespace globe::camera::detail {
namespace {

using nlohmann::json;

struct Field {
  const char* name;
  double minimum, maximum;
  std::optional<double> fallback;  // none: required
};

// The object's numbers by the table, in order; unknown fields refused.
Result<std::vector<double>> readNumbers(const json& object, const std::string& where,
                                        std::span<const Field> fields,
                                        std::span<const char* const> others,
                                        const ShotFailure& fail) {
  if (!object.is_object()) return fail(where, "expected an object");
  for (const auto& item : object.items()) {
    const std::string& key = item.key();
    bool known = std::any_of(others.begin(), others.end(), [&](const char* o) { return key == o; });
    for (const Field& field : fields) known = known || key == field.name;
    if (!known) return fail(where + "." + key, "unknown field");
  }
  std::vector<double> values;
  for (const Field& field : fields) {
    const auto it = object.find(field.name);
    if (it == object.end()) {
      if (!field.fallback) return fail(where, std::string("missing field '") + field.name + "'");
      values.push_back(*field.fallback);
      continue;
    }
    const std::string name = where + "." + field.name;
    if (!it->is_number()) return fail(name, "expected a number");
    const double value = it->get<double>();
    if (auto problem = checkNumber(formatNumber(value), value, field.minimum, field.maximum)) {
      return fail(name, *problem);
    }
    values.push_back(value);
  }
  return values;
}

Result<std::vector<PathKeyframe>> readOrbit(const json& object, const ShotFailure& fail) {
  constexpr std::array<Field, 9> kFields = {{
      {"lon", -180, 180, std::nullopt},
      {"lat", -90, 90, std::nullopt},
      {"height", kPathMinimumHeightMeters, kPathMaximumHeightMeters, 0.0},
      {"radius", 1, 1e7, std::nullopt},
      {"altitude", -1e4, kPathMaximumHeightMeters, std::nullopt},
      {"degrees", -3600, 3600, 360.0},
      {"duration", 0.001, 1e6, std::nullopt},
      {"startBearing", -kUnbounded, kUnbounded, 180.0},
      {"fov", 1, 170, 0.0},
  }};
  constexpr std::array<const char*, 1> kOthers = {"aboveTerrain"};
  auto n = readNumbers(object, "orbit", kFields, kOthers, fail);
  if (!n) return Error{n.error()};
  OrbitShot shot;
  shot.centre = {(*n)[0], (*n)[1], (*n)[2], false};
  if (const auto it = object.find("aboveTerrain"); it != object.end()) {
    if (!it->is_boolean()) return fail("orbit.aboveTerrain", "expected true or false");
    shot.centre.heightAboveTerrain = it->get<bool>();
  }
  shot.radiusMeters = (*n)[3];
  shot.altitudeMeters = (*n)[4];
  shot.degrees = (*n)[5];
  shot.durationSeconds = (*n)[6];
  shot.startBearingDegrees = (*n)[7];
  std::vector<PathKeyframe> keys = orbitKeyframes(shot);
  if ((*n)[8] > 0) {
    for (PathKeyframe& key : keys) key.fovDegrees = (*n)[8];
  }
  return keys;
}

Result<CameraPose> readPose(const json& object, const std::string& where, const ShotFailure& fail) {
  constexpr std::array<Field, 5> kFields = {{
      {"lon", -180, 180, std::nullopt},
      {"lat", -90, 90, std::nullopt},
      {"height", kPathMinimumHeightMeters, kPathMaximumHeightMeters, std::nullopt},
      {"heading", -kUnbounded, kUnbounded, 0.0},
      {"pitch", -90, 90, -90.0},
  }};
  auto n = readNumbers(object, where, kFields, {}, fail);
  if (!n) return Error{n.error()};
  return CameraPose::fromDegrees((*n)[0], (*n)[1], (*n)[2], (*n)[3], (*n)[4], 0);
}

Result<std::vector<PathKeyframe>> readFlyTo(const json& object, const ShotFailure& fail) {
  constexpr std::array<Field, 1> kFields = {{{"duration", 0.001, 1e3, std::nullopt}}};
  constexpr std::array<const char*, 2> kOthers = {"from", "to"};
  auto n = readNumbers(object, "flyTo", kFields, kOthers, fail);
  if (!n) return Error{n.error()};
  FlyToShot shot;
  shot.durationSeconds = (*n)[0];
  for (const auto& [name, pose] : {std::pair{"from", &shot.from}, std::pair{"to", &shot.to}}) {
    const auto it = object.find(name);
    if (it == object.end()) return fail("flyTo", std::string("missing field '") + name + "'");
    auto read = readPose(*it, std::string("flyTo.") + name, fail);
    if (!read) return Error{read.error()};
    *pose = *read;
  }
  return flyToKeyframes(shot);
}

}  // namespace

Result<std::optional<std::vector<PathKeyframe>>> readShot(const json& document,
                                                          const ShotFailure& fail) {
  if (const auto it = document.find("orbit"); it != document.end()) {
    auto keys = readOrbit(*it, fail);
    if (!keys) return Error{keys.error()};
    return std::optional(std::move(*keys));
  }
  if (const auto it = document.find("flyTo"); it != document.end()) {
    auto keys = readFlyTo(*it, fail);
    if (!keys) return Error{keys.error()};
    return std::optional(std::move(*keys));
  }
  return std::optional<std::vector<PathKeyframe>>();
}

}  // namespace globe::camera::detail
