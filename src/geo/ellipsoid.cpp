// Globe model selection: mapping between GlobeModel, its ellipsoid and its name.
#include "geo/ellipsoid.hpp"

#include <algorithm>
#include <cctype>

namespace globe::geo {

namespace {

bool equalsIgnoringCase(std::string_view text, std::string_view lowerCase) {
  return std::ranges::equal(text, lowerCase, [](char c, char lower) {
    return std::tolower(static_cast<unsigned char>(c)) == lower;
  });
}

}  // namespace

Ellipsoid ellipsoidFor(GlobeModel model) {
  return model == GlobeModel::Sphere ? Ellipsoid::sphere() : Ellipsoid::wgs84();
}

std::optional<GlobeModel> parseGlobeModel(std::string_view text) {
  if (equalsIgnoringCase(text, "wgs84")) return GlobeModel::Wgs84;
  if (equalsIgnoringCase(text, "sphere")) return GlobeModel::Sphere;
  return std::nullopt;
}

std::string_view toString(GlobeModel model) {
  return model == GlobeModel::Sphere ? "sphere" : "wgs84";
}

}  // namespace globe::geo
