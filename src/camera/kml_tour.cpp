// Google Earth KML tours (gx:Tour → gx:Playlist → gx:FlyTo + Camera or LookAt, gx:Wait) as path keyframes,
// parsed with tinyxml2; namespace prefixes are ignored (elements match by local name).
#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <string_view>
#include <vector>

#include "camera/camera_path_file.hpp"
#include "camera/look_at.hpp"
#include "camera/path_generators.hpp"
#include "geo/cartographic.hpp"
#include "camera/path_checks.hpp"
#include "transport/atomic_file.hpp"

namespace globe::camera {
namespace {

using detail::kUnbounded;
using tinyxml2::XMLElement;

// "gx:FlyTo" → "FlyTo".
std::string_view localName(const XMLElement& element) {
  const std::string_view name = element.Name();
  const size_t colon = name.find(':');
  return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

const XMLElement* child(const XMLElement& parent, std::string_view name) {
  for (const XMLElement* e = parent.FirstChildElement(); e; e = e->NextSiblingElement()) {
    if (localName(*e) == name) return e;
  }
  return nullptr;
}

// The first element named `name` in document order (iteratively: no recursion on the tree).
const XMLElement* findFirst(const tinyxml2::XMLDocument& document, std::string_view name) {
  std::vector<const XMLElement*> stack;
  if (const XMLElement* root = document.FirstChildElement()) stack.push_back(root);
  while (!stack.empty()) {
    const XMLElement* e = stack.back();
    stack.pop_back();
    if (localName(*e) == name) return e;
    std::vector<const XMLElement*> children;
    for (const XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
      children.push_back(c);
    }
    stack.insert(stack.end(), children.rbegin(), children.rend());
  }
  return nullptr;
}

std::string_view trimmed(const char* text) {
  std::string_view s = text != nullptr ? text : "";
  const size_t first = s.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
}

class TourReader {
 public:
  explicit TourReader(const std::filesystem::path& path) : path_(path) {}

  Error fail(const XMLElement& at, const std::string& what) const {
    return makeError(detail::fileLine(path_, at.GetLineNum()) + what);
  }

  // The number in a child element, checked; `fallback` when the element is absent.
  Result<double> number(const XMLElement& parent, std::string_view name, std::string_view label,
                        std::optional<double> fallback, double minimum, double maximum) const {
    const XMLElement* e = child(parent, name);
    if (e == nullptr) {
      if (fallback) return *fallback;
      return fail(parent, std::string(label) + ": missing <" + std::string(name) + ">");
    }
    const std::string_view text = trimmed(e->GetText());
    const std::optional<double> value = parseDecimal(text);
    if (!value) {
      return fail(
          *e, std::string(label) + ": '" + std::string(text.substr(0, 40)) + "' is not a number");
    }
    if (auto problem = detail::checkNumber(text.substr(0, 40), *value, minimum, maximum)) {
      return fail(*e, std::string(label) + ": " + *problem);
    }
    return *value;
  }

  // Each duration is finite, but their sum may not be: the tour's time must stay a number.
  std::optional<Error> timeOverflow(const XMLElement& step, double timeSeconds) const {
    if (std::isfinite(timeSeconds)) return std::nullopt;
    const XMLElement* at = child(step, "duration");
    return fail(at ? *at : step, "gx:" + std::string(localName(step)) +
                                     ".duration: the tour's time passes " +
                                     detail::formatNumber(std::numeric_limits<double>::max()) +
                                     " s (not a finite number)");
  }

  // An element's altitudeMode (or gx:altitudeMode): absolute, relativeToGround or clampToGround
  // (KML's default); the sea-floor modes are refused.
  Result<std::string_view> mode(const XMLElement& view, const std::string& label) const {
    std::string_view mode = "clampToGround";
    const XMLElement* modeElement = child(view, "altitudeMode");
    if (modeElement != nullptr) mode = trimmed(modeElement->GetText());
    if (mode == "relativeToSeaFloor" || mode == "clampToSeaFloor") {
      return fail(*modeElement, label + ".altitudeMode: " + std::string(mode) +
                                    " is not supported (use absolute or relativeToGround)");
    }
    if (mode != "absolute" && mode != "relativeToGround" && mode != "clampToGround") {
      return fail(*modeElement, label + ".altitudeMode: '" + std::string(mode.substr(0, 40)) +
                                    "' is not absolute, relativeToGround or clampToGround");
    }
    return mode;
  }

  // A LookAt: the camera `range` back from the point along heading and tilt (0 straight down,
  // 90 level), looking at it; the point is the keyframe's target. With a mode above the ground
  // the camera's height is taken above the terrain too, as if the ground under it were the
  // target's (the target itself is exact).
  Result<PathKeyframe> lookAt(const XMLElement& lookAt) const {
    auto altitudeMode = mode(lookAt, "LookAt");
    if (!altitudeMode) return Error{altitudeMode.error()};
    const bool clamped = *altitudeMode == "clampToGround";
    auto lon = number(lookAt, "longitude", "LookAt.longitude", std::nullopt, -180, 180);
    if (!lon) return Error{lon.error()};
    auto lat = number(lookAt, "latitude", "LookAt.latitude", std::nullopt, -90, 90);
    if (!lat) return Error{lat.error()};
    auto altitude = number(lookAt, "altitude", "LookAt.altitude", 0.0, kPathMinimumHeightMeters,
                           kPathMaximumHeightMeters);
    if (!altitude) return Error{altitude.error()};
    auto heading = number(lookAt, "heading", "LookAt.heading", 0.0, -kUnbounded, kUnbounded);
    if (!heading) return Error{heading.error()};
    auto tilt = number(lookAt, "tilt", "LookAt.tilt", 0.0, 0, 90);
    if (!tilt) return Error{tilt.error()};
    auto range = number(lookAt, "range", "LookAt.range", std::nullopt, 0, kPathMaximumHeightMeters);
    if (!range) return Error{range.error()};
    const PathTarget target{*lon, *lat, clamped ? 0.0 : *altitude, *altitudeMode != "absolute"};
    const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
    const CameraPose pose = cameraOfLookAt(
        wgs84, geo::Cartographic::fromDegrees(*lon, *lat, target.heightMeters), *heading, *tilt,
        *range);
    PathKeyframe key;
    key.longitudeDegrees = geo::radiansToDegrees(pose.position.longitudeRadians);
    key.latitudeDegrees = geo::radiansToDegrees(pose.position.latitudeRadians);
    key.heightMeters = std::min(pose.position.heightMeters, kPathMaximumHeightMeters);
    key.heightAboveTerrain = target.heightAboveTerrain;
    key.headingDegrees = geo::radiansToDegrees(pose.headingRadians);
    key.pitchDegrees = geo::radiansToDegrees(pose.pitchRadians);
    key.target = target;
    return key;
  }

  Result<PathKeyframe> camera(const XMLElement& camera) const {
    PathKeyframe key;
    auto altitudeMode = mode(camera, "Camera");
    if (!altitudeMode) return Error{altitudeMode.error()};
    const std::string_view mode = *altitudeMode;
    auto lon = number(camera, "longitude", "Camera.longitude", std::nullopt, -180, 180);
    if (!lon) return Error{lon.error()};
    auto lat = number(camera, "latitude", "Camera.latitude", std::nullopt, -90, 90);
    if (!lat) return Error{lat.error()};
    const bool clamped = mode == "clampToGround";
    auto altitude = number(camera, "altitude", "Camera.altitude",
                           clamped ? std::optional<double>(0.0) : std::nullopt,
                           kPathMinimumHeightMeters, kPathMaximumHeightMeters);
    if (!altitude) return Error{altitude.error()};
    auto heading = number(camera, "heading", "Camera.heading", 0.0, -kUnbounded, kUnbounded);
    if (!heading) return Error{heading.error()};
    auto tilt = number(camera, "tilt", "Camera.tilt", 0.0, 0, 180);
    if (!tilt) return Error{tilt.error()};
    auto roll = number(camera, "roll", "Camera.roll", 0.0, -kUnbounded, kUnbounded);
    if (!roll) return Error{roll.error()};
    key.longitudeDegrees = *lon;
    key.latitudeDegrees = *lat;
    key.heightMeters = clamped ? 0.0 : *altitude;
    key.heightAboveTerrain = mode != "absolute";
    key.headingDegrees = *heading;
    key.pitchDegrees = *tilt - 90.0;
    key.rollDegrees = *roll;
    return key;
  }

  Result<CameraPathFile> tour(const tinyxml2::XMLDocument& document) const {
    const XMLElement* tour = findFirst(document, "Tour");
    if (tour == nullptr) {
      return makeError(detail::fileLine(path_, 1) + "no <gx:Tour> in the file");
    }
    const XMLElement* playlist = child(*tour, "Playlist");
    if (playlist == nullptr) return fail(*tour, "gx:Tour has no <gx:Playlist>");
    CameraPathFile file;
    std::vector<bool> bounceInto;  // per keyframe: reached by a bounce FlyTo
    double pendingSeconds = 0;  // durations since the last keyframe
    for (const XMLElement* e = playlist->FirstChildElement(); e; e = e->NextSiblingElement()) {
      const std::string_view name = localName(*e);
      if (name != "FlyTo" && name != "Wait") continue;  // sound cues, updates, tour controls
      auto duration = number(*e, "duration", std::string("gx:") + std::string(name) + ".duration",
                             0.0, 0, kUnbounded);
      if (!duration) return Error{duration.error()};
      if (name == "Wait") {
        if (!file.keyframes.empty() && *duration > 0) {
          PathKeyframe hold = file.keyframes.back();
          hold.timeSeconds += pendingSeconds + *duration;
          if (auto overflow = timeOverflow(*e, hold.timeSeconds)) return *overflow;
          file.keyframes.push_back(hold);
          pendingSeconds = 0;
        }
        continue;
      }
      const XMLElement* cameraElement = child(*e, "Camera");
      const XMLElement* lookAtElement = child(*e, "LookAt");
      if (cameraElement == nullptr && lookAtElement == nullptr) {
        return fail(*e, "gx:FlyTo has no <Camera> or <LookAt>");
      }
      auto key = cameraElement != nullptr ? camera(*cameraElement) : lookAt(*lookAtElement);
      if (!key) return Error{key.error()};
      bool bounce = true;  // KML's default
      if (const XMLElement* mode = child(*e, "flyToMode")) {
        const std::string_view text = trimmed(mode->GetText());
        if (text != "smooth" && text != "bounce") {
          return fail(*mode, "gx:flyToMode: '" + std::string(text.substr(0, 40)) +
                                 "' is not smooth or bounce");
        }
        bounce = text == "bounce";
      }
      if (file.keyframes.empty()) {
        key->timeSeconds = 0;  // the first FlyTo's duration is Google Earth's approach to it
      } else {
        key->timeSeconds = file.keyframes.back().timeSeconds + pendingSeconds + *duration;
        if (auto overflow = timeOverflow(*e, key->timeSeconds)) return *overflow;
        if (!(key->timeSeconds > file.keyframes.back().timeSeconds)) {
          const XMLElement* at = child(*e, "duration");
          return fail(at ? *at : *e,
                      "gx:FlyTo.duration: " + detail::formatNumber(*duration) +
                          " s after the previous keyframe: times must increase strictly "
                          "(an instant jump is not supported)");
        }
      }
      pendingSeconds = 0;
      file.keyframes.push_back(*key);
      bounceInto.resize(file.keyframes.size(), false);
      bounceInto.back() = bounce;
    }
    if (file.keyframes.empty()) {
      return fail(*playlist,
                  "gx:Playlist has no gx:FlyTo with a Camera or LookAt (a path needs at least "
                  "1 keyframe)");
    }
    // Smooth FlyTos run through their views without stopping (one spline); bounce ones stop at
    // each view and arc over long ways (path_generators.hpp).
    file.interpolation = "smooth";
    file.keyframes = withBounceArcs(file.keyframes, bounceInto);
    return file;
  }

 private:
  std::filesystem::path path_;
};

}  // namespace

Result<CameraPathFile> readKmlTour(const std::filesystem::path& path) {
  auto bytes = transport::readWholeFile(path, kPathFileMaximumBytes);
  if (!bytes) return Error{bytes.error()};
  tinyxml2::XMLDocument document;
  const auto* text = reinterpret_cast<const char*>(bytes->data());
  if (document.Parse(text, bytes->size()) != tinyxml2::XML_SUCCESS) {
    // tinyxml2 reports the line where the innermost element holding the error starts, and
    // names it after "Line number=N: " in ErrorStr.
    std::string what = tinyxml2::XMLDocument::ErrorIDToName(document.ErrorID());
    const std::string detail = document.ErrorStr() != nullptr ? document.ErrorStr() : "";
    if (const size_t at = detail.find("Line number="); at != std::string::npos) {
      if (const size_t colon = detail.find(": ", at); colon != std::string::npos) {
        what += " (" + detail.substr(colon + 2, 80) + ")";
      }
    }
    return makeError(detail::fileLine(path, std::max(document.ErrorLineNum(), 1)) +
                     "not valid XML: " + what);
  }
  return TourReader(path).tour(document);
}

}  // namespace globe::camera
