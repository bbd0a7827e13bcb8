// The elevation profile chart in `globe view`'s bottom-left corner (X, as Google Earth's "Show
// elevation profile"): a path's profile over the pyramid's exact surface, drawn by the chart
// code into an image shown over the frame; remade only when the path or the window's size
// changes.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>

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
  // Over the frame at the bottom left, above the scale bar (bottomMarginPixels).
  void draw(int framebufferWidthPixels, int framebufferHeightPixels,
            float bottomMarginPixels) const;

 private:
  explicit ProfilePanel(std::unique_ptr<render::ImageOverlay> image) : image_(std::move(image)) {}
  std::unique_ptr<render::ImageOverlay> image_;
  std::vector<measure::PathPoint> path_;  // the chart's
  glm::ivec2 sizePixels_{0, 0};
};

}  // namespace globe::app
