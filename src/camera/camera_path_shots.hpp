// The JSON path format's shots: {"orbit": {"lon", "lat", "height" (0), "aboveTerrain" (false),
// "radius", "altitude" (the camera above the point), "degrees" (360), "duration",
// "startBearing" (180), "fov"}} or {"flyTo": {"from": {"lon", "lat", "height", "heading",
// "pitch"}, "to": {...}, "duration"}}, instead of "keyframes" (path_generators.hpp).
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "camera/camera_path_file.hpp"
#include "core/result.hpp"

namespace globe::camera::detail {

// An error naming the field ("orbit.radius") and what is wrong with it.
using ShotFailure = std::function<Error(const std::string& field, const std::string& what)>;

// The shot's keyframes, or nullopt when the document names none.
Result<std::optional<std::vector<PathKeyframe>>> readShot(const nlohmann::json& document,
                                                          const ShotFailure& fail);

}  // namespace globe::camera::detail
