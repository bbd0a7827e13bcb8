// The elevation profile chart in a bottom corner of `globe view` (X, as Google Earth's "Show
// elevation profile"): a path's profile over the pyramid's exact surface, drawn by the chart
// code into an image shown over the frame; remade only when the path or the window's size
// changes.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/result.hpp"
#include "geo/ellipsoid.hpp"
#include "measure/path_files.hpp"
#include "overlays/overlay_model.hpp"
#include "render/image_overlay.hpp"
#include "streaming/terrain_source.hpp"

namespace globe::app {

struct ProfileSummary {
  size_t samples = 0;
  double lengthMeters = 0;
  double lowestMeters = 0, highestMeters = 0;
};

// The chart's size for a framebuffer: half its width and two fifths of its height, within the
// chart code's limits.
glm::ivec2 profileChartSizePixels(int framebufferWidthPixels, int framebufferHeightPixels);

// A placemark's first line (a LineString's vertices), or nullopt when it has none.
std::optional<std::vector<measure::PathPoint>> placemarkLine(const overlays::Placemark& placemark);

// Where the chart goes: the bottom-left corner above the scale bar, or the bottom-right one when
// fewer of the profiled path's on-screen points (framebuffer pixels, sampled densely along it)
// fall under it there, so the chart does not hide the path it profiles where a corner is free.
enum class ChartCorner { BottomLeft, BottomRight };
ChartCorner profileChartCorner(std::span<const glm::dvec2> pathPixels, glm::ivec2 chartSizePixels,
                               int framebufferWidthPixels, int framebufferHeightPixels,
                               float bottomMarginPixels);
// The chart's top-left corner in framebuffer pixels.
glm::vec2 profileChartTopLeft(ChartCorner corner, glm::ivec2 chartSizePixels,
                              int framebufferWidthPixels, int framebufferHeightPixels,
                              float bottomMarginPixels);

class ProfilePanel {
 public:
  // Needs the GL context current.
  static Result<std::unique_ptr<ProfilePanel>> create();

  // The chart of `path` (two points or more) for this framebuffer size: computed and drawn when
  // either differs from the last call's, else kept. Returns the new chart's summary, or nullopt
  // when nothing changed.
  Result<std::optional<ProfileSummary>> update(const std::vector<measure::PathPoint>& path,
                                               streaming::TerrainSource& source,
                                               const geo::Ellipsoid& ellipsoid,
                                               int framebufferWidthPixels,
                                               int framebufferHeightPixels);
  // Forgets the chart (the next update() makes it again).
  void clear();
  // Over the frame in `corner`, above the scale bar's margin (bottomMarginPixels).
  void draw(int framebufferWidthPixels, int framebufferHeightPixels, float bottomMarginPixels,
            ChartCorner corner) const;
  glm::ivec2 sizePixels() const { return sizePixels_; }  // {0, 0} with no chart
  // The profiled path on the ground (ECEF, at most kGroundPoints of the chart's samples): where
  // it is on screen decides the chart's corner.
  static constexpr size_t kGroundPoints = 512;
  const std::vector<glm::dvec3>& groundPointsEcef() const { return groundEcef_; }

 private:
  explicit ProfilePanel(std::unique_ptr<render::ImageOverlay> image) : image_(std::move(image)) {}
  std::unique_ptr<render::ImageOverlay> image_;
  std::vector<measure::PathPoint> path_;  // the chart's
  glm::ivec2 sizePixels_{0, 0};
  std::vector<glm::dvec3> groundEcef_;
};

}  // namespace globe::app
