#include "apps/globe/profile_panel.hpp"

#include <algorithm>
#include <cmath>

#include "geo/ecef.hpp"
#include "measure/elevation_profile.hpp"
#include "measure/profile_chart.hpp"

namespace globe::app {
namespace {

bool samePath(const std::vector<measure::PathPoint>& a, const std::vector<measure::PathPoint>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                    [](const measure::PathPoint& p, const measure::PathPoint& q) {
                      return p.longitudeDegrees == q.longitudeDegrees &&
                             p.latitudeDegrees == q.latitudeDegrees;
                    });
}

}  // namespace

glm::ivec2 profileChartSizePixels(int framebufferWidthPixels, int framebufferHeightPixels) {
  return {std::clamp(framebufferWidthPixels / 2, measure::kMinChartWidthPixels, 900),
          std::clamp(framebufferHeightPixels * 2 / 5, measure::kMinChartHeightPixels, 360)};
}

std::optional<std::vector<measure::PathPoint>> placemarkLine(const overlays::Placemark& placemark) {
  for (const overlays::Geometry& geometry : placemark.geometries) {
    if (geometry.kind != overlays::GeometryKind::LineString || geometry.rings.empty()) continue;
    std::vector<measure::PathPoint> path;
    for (const overlays::Position& p : geometry.rings.front()) {
      // Its own heights are the file's, per its altitude mode: not terrain to compare with.
      measure::PathPoint point;
      point.longitudeDegrees = p.longitudeDegrees;
      point.latitudeDegrees = p.latitudeDegrees;
      path.push_back(point);
    }
    return path;
  }
  return std::nullopt;
}

Result<std::unique_ptr<ProfilePanel>> ProfilePanel::create() {
  auto image = render::ImageOverlay::create({});
  if (!image) return Error{image.error()};
  return std::unique_ptr<ProfilePanel>(new ProfilePanel(std::move(*image)));
}

Result<std::optional<ProfileSummary>> ProfilePanel::update(
    const std::vector<measure::PathPoint>& path, streaming::TerrainSource& source,
    const geo::Ellipsoid& ellipsoid, int framebufferWidthPixels, int framebufferHeightPixels) {
  const glm::ivec2 size = profileChartSizePixels(framebufferWidthPixels, framebufferHeightPixels);
  if (image_->hasImage() && size == sizePixels_ && samePath(path, path_)) {
    return std::optional<ProfileSummary>();
  }
  clear();
  auto rows = measure::elevationProfile(source, path, ellipsoid);
  if (!rows) return Error{rows.error()};
  auto chart = measure::drawProfileChart(*rows, size.x, size.y);
  if (!chart) return Error{chart.error()};
  image_->setImage(*chart);
  path_ = path;
  sizePixels_ = size;
  const size_t stride = rows->size() / kGroundPoints + 1;
  for (size_t i = 0; i < rows->size(); i += stride) {
    const measure::ProfileRow& row = (*rows)[i];
    groundEcef_.push_back(geo::cartographicToEcef(
        ellipsoid, geo::Cartographic::fromDegrees(row.sample.longitudeDegrees,
                                                  row.sample.latitudeDegrees, row.heightMeters)));
  }
  const auto [lowest, highest] = std::minmax_element(
      rows->begin(), rows->end(), [](const measure::ProfileRow& a, const measure::ProfileRow& b) {
        return a.heightMeters < b.heightMeters;
      });
  return std::optional<ProfileSummary>(ProfileSummary{rows->size(),
                                                      rows->back().sample.distanceMeters,
                                                      lowest->heightMeters, highest->heightMeters});
}

void ProfilePanel::clear() {
  image_->setImage({});
  path_.clear();
  sizePixels_ = {0, 0};
  groundEcef_.clear();
}

glm::vec2 profileChartTopLeft(ChartCorner corner, glm::ivec2 chartSizePixels,
                              int framebufferWidthPixels, int framebufferHeightPixels,
                              float bottomMarginPixels) {
  const float top = std::round(static_cast<float>(framebufferHeightPixels - chartSizePixels.y) -
                               bottomMarginPixels);
  const float left = corner == ChartCorner::BottomLeft
                         ? 8.0f
                         : static_cast<float>(framebufferWidthPixels - chartSizePixels.x - 8);
  return {left, top};
}

ChartCorner profileChartCorner(std::span<const glm::dvec2> pathPixels, glm::ivec2 chartSizePixels,
                               int framebufferWidthPixels, int framebufferHeightPixels,
                               float bottomMarginPixels) {
  const auto covered = [&](ChartCorner corner) {
    const glm::dvec2 low(profileChartTopLeft(corner, chartSizePixels, framebufferWidthPixels,
                                             framebufferHeightPixels, bottomMarginPixels));
    const glm::dvec2 high = low + glm::dvec2(chartSizePixels);
    return std::count_if(pathPixels.begin(), pathPixels.end(), [&](const glm::dvec2& p) {
      return p.x >= low.x && p.x < high.x && p.y >= low.y && p.y < high.y;
    });
  };
  return covered(ChartCorner::BottomRight) < covered(ChartCorner::BottomLeft)
             ? ChartCorner::BottomRight
             : ChartCorner::BottomLeft;
}

void ProfilePanel::draw(int framebufferWidthPixels, int framebufferHeightPixels,
                        float bottomMarginPixels, ChartCorner corner) const {
  const glm::vec2 topLeft = profileChartTopLeft(corner, image_->sizePixels(), framebufferWidthPixels,
                                                framebufferHeightPixels, bottomMarginPixels);
  image_->draw(topLeft, framebufferWidthPixels, framebufferHeightPixels, 0.92f);
}

}  // namespace globe::app
