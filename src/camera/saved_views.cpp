#include "camera/saved_views.hpp"

#include <tinyxml2.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string_view>

#include <glm/geometric.hpp>

#include "geo/ecef.hpp"
#include "transport/atomic_file.hpp"
#include "core/xml_escape.hpp"

namespace globe::camera {
namespace {

constexpr uint64_t kMaxSavedViewsFileBytes = uint64_t{64} << 20;
constexpr double kViewsPi = 3.14159265358979323846;

std::string lowerAscii(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string_view viewElementName(const tinyxml2::XMLElement& e) {
  std::string_view name = e.Name();
  const size_t colon = name.find(':');
  return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

const tinyxml2::XMLElement* viewChild(const tinyxml2::XMLElement& parent, std::string_view name) {
  for (const auto* e = parent.FirstChildElement(); e; e = e->NextSiblingElement()) {
    if (viewElementName(*e) == name) return e;
  }
  return nullptr;
}


}  // namespace

std::filesystem::path userViewsFile() {
  if (const char* config = std::getenv("XDG_CONFIG_HOME"); config != nullptr && *config != '\0') {
    return std::filesystem::path(config) / "globe/views.json";
  }
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') {
    return std::filesystem::path(home) / ".config/globe/views.json";
  }
  return ".globe-views.json";
}

Result<std::vector<SavedView>> readSavedViews(const std::filesystem::path& file) {
  std::error_code missing;
  if (!std::filesystem::exists(file, missing)) return std::vector<SavedView>();
  auto bytes = transport::readWholeFile(file, kMaxSavedViewsFileBytes);
  if (!bytes) return Error{bytes.error()};
  const auto json = nlohmann::json::parse(
      std::string(reinterpret_cast<const char*>(bytes->data()), bytes->size()), nullptr, false);
  if (json.is_discarded() || !json.is_object() || !json.contains("views") ||
      !json["views"].is_array()) {
    return makeError(file.string() + ": not a views file ({\"views\": [...]})");
  }
  std::vector<SavedView> views;
  for (const auto& v : json["views"]) {
    const bool good = v.is_object() && v.contains("name") && v["name"].is_string() &&
                      v.contains("camera") && v["camera"].is_array() && v["camera"].size() == 6 &&
                      std::all_of(v["camera"].begin(), v["camera"].end(),
                                  [](const auto& n) { return n.is_number(); });
    if (!good) {
      return makeError(file.string() + ": view " + std::to_string(views.size() + 1) +
                       ": needs \"name\" and \"camera\": [lon, lat, height, heading, pitch, roll]");
    }
    const auto& c = v["camera"];
    SavedView view{
        v["name"].get<std::string>(),
        CameraPose::fromDegrees(c[0].get<double>(), c[1].get<double>(), c[2].get<double>(),
                                c[3].get<double>(), c[4].get<double>(), c[5].get<double>()),
        v.value("aboveTerrain", false)};
    if (!view.pose.isFinite() || std::fabs(c[1].get<double>()) > 90) {
      return makeError(file.string() + ": view \"" + view.name + "\": a camera off the globe");
    }
    views.push_back(std::move(view));
  }
  return views;
}

Result<void> writeSavedViews(const std::filesystem::path& file,
                             const std::vector<SavedView>& views) {
  nlohmann::json list = nlohmann::json::array();
  const double deg = 180 / kViewsPi;
  for (const SavedView& v : views) {
    list.push_back({{"name", v.name},
                    {"camera",
                     {v.pose.position.longitudeRadians * deg, v.pose.position.latitudeRadians * deg,
                      v.pose.position.heightMeters, v.pose.headingRadians * deg,
                      v.pose.pitchRadians * deg, v.pose.rollRadians * deg}},
                    {"aboveTerrain", v.heightAboveTerrain}});
  }
  std::error_code error;
  std::filesystem::create_directories(file.parent_path(), error);
  return transport::writeFileAtomically(file, nlohmann::json{{"views", list}}.dump(1) + "\n");
}

void putSavedView(std::vector<SavedView>& views, const SavedView& view) {
  for (SavedView& v : views) {
    if (lowerAscii(v.name) == lowerAscii(view.name)) {
      v = view;
      return;
    }
  }
  views.push_back(view);
}

const SavedView* findSavedView(const std::vector<SavedView>& views, const std::string& name) {
  for (const SavedView& v : views) {
    if (lowerAscii(v.name) == lowerAscii(name)) return &v;
  }
  return nullptr;
}

std::string savedViewsToKml(const std::vector<SavedView>& views) {
  std::string kml =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<kml xmlns=\"http://www.opengis.net/kml/2.2\">\n<Document>\n<name>globe views</name>\n";
  const double deg = 180 / kViewsPi;
  char camera[512];
  for (const SavedView& v : views) {
    // KML's tilt: 0 looking straight down, 90 at the horizon (our pitch + 90).
    std::snprintf(camera, sizeof camera,
                  "  <Camera><longitude>%.9f</longitude><latitude>%.9f</latitude>"
                  "<altitude>%.3f</altitude><heading>%.6f</heading><tilt>%.6f</tilt>"
                  "<roll>%.6f</roll><altitudeMode>%s</altitudeMode></Camera>\n",
                  v.pose.position.longitudeRadians * deg, v.pose.position.latitudeRadians * deg,
                  v.pose.position.heightMeters, v.pose.headingRadians * deg,
                  v.pose.pitchRadians * deg + 90, v.pose.rollRadians * deg,
                  v.heightAboveTerrain ? "relativeToGround" : "absolute");
    kml += "<Placemark>\n  <name>" + xmlEscaped(v.name) + "</name>\n" + camera + "</Placemark>\n";
  }
  return kml + "</Document>\n</kml>\n";
}

CameraPose lookAtPose(double longitudeDegrees, double latitudeDegrees, double altitudeMeters,
                      double headingDegrees, double tiltDegrees, double rangeMeters,
                      const geo::Ellipsoid& ellipsoid) {
  const double rad = kViewsPi / 180;
  const geo::Cartographic target{longitudeDegrees * rad, latitudeDegrees * rad, altitudeMeters};
  const glm::dvec3 point = geo::cartographicToEcef(ellipsoid, target);
  // The local east, north and up at the point; the view along heading, tilted from down.
  const glm::dvec3 up = geo::geodeticSurfaceNormal(ellipsoid, target);
  const glm::dvec3 east = glm::normalize(
      glm::dvec3(-std::sin(target.longitudeRadians), std::cos(target.longitudeRadians), 0));
  const glm::dvec3 north = glm::cross(up, east);
  const double h = headingDegrees * rad, t = tiltDegrees * rad;
  const glm::dvec3 view =
      std::sin(t) * (std::sin(h) * east + std::cos(h) * north) - std::cos(t) * up;
  const glm::dvec3 eye = point - rangeMeters * view;
  const auto at = geo::ecefToCartographic(ellipsoid, eye);
  if (!at) return CameraPose::fromDegrees(longitudeDegrees, latitudeDegrees, rangeMeters);
  // Seen from the eye, the point lies along `view`: the same heading; the pitch measured in the
  // eye's own frame (its up differs from the point's by the arc between them).
  const glm::dvec3 eyeUp = geo::geodeticSurfaceNormal(ellipsoid, *at);
  const double pitch = std::asin(std::clamp(glm::dot(view, eyeUp), -1.0, 1.0));
  const glm::dvec3 eyeEast = glm::normalize(
      glm::dvec3(-std::sin(at->longitudeRadians), std::cos(at->longitudeRadians), 0));
  const glm::dvec3 eyeNorth = glm::cross(eyeUp, eyeEast);
  const double heading = std::atan2(glm::dot(view, eyeEast), glm::dot(view, eyeNorth));
  CameraPose pose;
  pose.position = *at;
  pose.headingRadians = std::fabs(pitch) > kViewsPi / 2 - 1e-9 ? h : heading;
  pose.pitchRadians = pitch;
  return pose;
}

Result<std::vector<SavedView>> savedViewsFromKml(const std::filesystem::path& file,
                                                 const geo::Ellipsoid& ellipsoid) {
  auto bytes = transport::readWholeFile(file, kMaxSavedViewsFileBytes);
  if (!bytes) return Error{bytes.error()};
  tinyxml2::XMLDocument document;
  if (document.Parse(reinterpret_cast<const char*>(bytes->data()), bytes->size()) !=
          tinyxml2::XML_SUCCESS ||
      document.RootElement() == nullptr) {
    return makeError(file.string() + ": not XML (" + std::string(document.ErrorStr()) + ")");
  }
  std::vector<SavedView> views;
  std::vector<const tinyxml2::XMLElement*> stack{document.RootElement()};
  const auto number = [&](const tinyxml2::XMLElement& parent, const char* name, double fallback,
                          double* out) -> Result<void> {
    const tinyxml2::XMLElement* e = viewChild(parent, name);
    if (e == nullptr) {
      *out = fallback;
      return {};
    }
    char* end = nullptr;
    const char* text = e->GetText() != nullptr ? e->GetText() : "";
    *out = std::strtod(text, &end);
    while (end != nullptr && std::isspace(static_cast<unsigned char>(*end)) != 0) ++end;
    if (end == text || (end != nullptr && *end != '\0') || !std::isfinite(*out)) {
      return makeError(file.string() + ":" + std::to_string(e->GetLineNum()) + ": <" + name +
                       "> is not a number");
    }
    return {};
  };
  while (!stack.empty()) {
    const tinyxml2::XMLElement* e = stack.back();
    stack.pop_back();
    for (const auto* c = e->LastChildElement(); c; c = c->PreviousSiblingElement()) {
      stack.push_back(c);
    }
    const std::string_view kind = viewElementName(*e);
    if (kind != "Camera" && kind != "LookAt") continue;
    const tinyxml2::XMLElement* owner = e->Parent() ? e->Parent()->ToElement() : nullptr;
    const tinyxml2::XMLElement* nameElement = owner ? viewChild(*owner, "name") : nullptr;
    SavedView view;
    view.name = nameElement && nameElement->GetText() ? nameElement->GetText()
                                                      : "view " + std::to_string(views.size() + 1);
    double lon = 0, lat = 0, alt = 0, heading = 0, tilt = 0, roll = 0, range = 1000;
    for (auto read : {number(*e, "longitude", NAN, &lon), number(*e, "latitude", NAN, &lat),
                      number(*e, "altitude", 0, &alt), number(*e, "heading", 0, &heading),
                      number(*e, "tilt", 0, &tilt), number(*e, "roll", 0, &roll),
                      number(*e, "range", 1000, &range)}) {
      if (!read) return Error{read.error()};
    }
    if (!(std::fabs(lon) <= 180) || !(std::fabs(lat) <= 90) || !(tilt >= 0 && tilt <= 180) ||
        !(range >= 0)) {
      return makeError(file.string() + ":" + std::to_string(e->GetLineNum()) + ": <" +
                       std::string(kind) + "> needs longitude -180..180, latitude -90..90" +
                       (kind == "LookAt" ? ", tilt 0..180 and a range" : ""));
    }
    const tinyxml2::XMLElement* mode = viewChild(*e, "altitudeMode");
    const std::string altitudeMode = mode && mode->GetText() ? mode->GetText() : "clampToGround";
    view.heightAboveTerrain = altitudeMode != "absolute";
    if (altitudeMode == "clampToGround") alt = 0;
    if (kind == "Camera") {
      view.pose = CameraPose::fromDegrees(lon, lat, alt, heading, tilt - 90, roll);
    } else {
      // The point is on the ground (or above it); the eye's height relative to the same.
      view.pose = lookAtPose(lon, lat, alt, heading, tilt, range, ellipsoid);
    }
    views.push_back(view);
  }
  return views;
}

}  // namespace globe::camera
