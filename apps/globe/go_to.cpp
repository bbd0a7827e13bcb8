#include "apps/globe/go_to.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "apps/globe/places_file.hpp"
#include "places/coordinates.hpp"
#include "places/name_fold.hpp"

namespace globe::app {
namespace {

std::string placeLabel(const places::Place& p) {
  return p.countryCode.empty() || p.kind == "country" ? p.name : p.name + ", " + p.countryCode;
}

}  // namespace

Result<GoToTarget> parseGoTo(std::string_view text) {
  if (places::foldName(text).empty() && !places::parseCoordinates(text)) {
    return makeError(
        "go to: type a place or a position (e.g. Mount Fuji, Zurich, Paris, US, or "
        "\"35.36, 138.73\")");
  }
  if (auto position = places::parseCoordinates(text)) {
    if (!*position) return makeError("go to: " + position->error());
    char name[64];
    std::snprintf(name, sizeof name, "%.5f, %.5f", (*position)->latitudeDegrees,
                  (*position)->longitudeDegrees);
    return GoToTarget{name, (*position)->latitudeDegrees, (*position)->longitudeDegrees};
  }
  auto gazetteer = loadPlaces();
  if (!gazetteer) return makeError("go to: " + gazetteer.error());
  const auto found = (*gazetteer)->search(text, 1);
  if (found.empty()) {
    return makeError("go to: no place named \"" + std::string(text) +
                     "\" (a place, \"NAME, COUNTRY\", or \"lat, lon\")");
  }
  return GoToTarget{placeLabel(*found[0]), found[0]->latitudeDegrees, found[0]->longitudeDegrees};
}

camera::CameraPose goToPose(const GoToTarget& target) {
  constexpr double kDistanceMeters = 15000;
  constexpr double kPitchDegrees = -35;
  constexpr double kMetresPerDegreeOfLatitude = 111132;
  const double pitch = kPitchDegrees * 3.14159265358979323846 / 180;
  const double back = kDistanceMeters * std::cos(pitch) / kMetresPerDegreeOfLatitude;
  return camera::CameraPose::fromDegrees(target.longitudeDegrees,
                                         std::max(-89.9, target.latitudeDegrees - back),
                                         -kDistanceMeters * std::sin(pitch), 0, kPitchDegrees, 0);
}

Result<camera::SavedView> savedViewNamed(const std::string& name) {
  const auto file = camera::userViewsFile();
  auto views = camera::readSavedViews(file);
  if (!views) return Error{views.error()};
  if (const camera::SavedView* view = camera::findSavedView(*views, name)) return *view;
  std::string names;
  for (const camera::SavedView& v : *views) names += (names.empty() ? "" : ", ") + v.name;
  return makeError(
      "no view named \"" + name + "\" in " + file.string() +
      (names.empty() ? " (none saved: V in the window saves one)" : " (" + names + ")"));
}

std::vector<std::string> goToSuggestions(std::string_view text, size_t count) {
  std::vector<std::string> suggestions;
  if (places::foldName(text).size() < 2 || places::parseCoordinates(text)) return suggestions;
  auto gazetteer = loadPlaces();
  if (!gazetteer) return suggestions;
  for (const places::Place* p : (*gazetteer)->search(text, count)) {
    suggestions.push_back(places::asciiForDisplay(placeLabel(*p)));  // the HUD draws ASCII
  }
  return suggestions;
}

}  // namespace globe::app
