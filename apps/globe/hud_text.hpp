// What the `globe view` HUD says: the always-on status lines (the help overlay is the key table's:
// loop redraws only when the text (frame time aside) changes.
#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "camera/camera_controller.hpp"
#include "camera/camera_pose.hpp"
#include "camera/navigator.hpp"
#include "formats/pyramid_manifest.hpp"
#include "geo/cartographic.hpp"
#include "terrain/relief_shading.hpp"

namespace globe::app {

struct HudState {
  camera::NavigationMode mode = camera::NavigationMode::Orbit;
  camera::CameraPose pose;
  camera::CollisionState collision;  // the controller's last update
  size_t tilesDrawn = 0;
  size_t tilesLoading = 0;             // wanted by the view and not resident yet
  size_t tilesMissing = 0;             // wanted by the view, failed to load: drawn coarser
  double frameMilliseconds = 0;        // the last frame drawn; 0: not known yet
  double flySpeedMetersPerSecond = 0;  // shown in fly mode
  double speedFactor = 1;              // the scroll-wheel factor, shown in fly mode
  bool recording = false;
  size_t keyframes = 0;  // recorded so far
  bool flyingTo = false;
  // The drawn ground under the mouse pointer (nullopt: the sky or no pointer), and the ground
  // distance a pixel spans at the centre of the view (NaN: no ground there; the scale bar).
  std::optional<geo::Cartographic> underCursor;
  double metersPerPixel = std::numeric_limits<double>::quiet_NaN();
  std::optional<std::string> prompt;  // the go-to text (G), or a view's name (V), being typed
  bool promptSavesView = false;
  bool promptOpensFile = false;
  std::vector<std::string> suggestions;  // the gazetteer's best places for it
  std::string message;                   // what the last go-to said (an error)
  std::string warning;                   // the latest warning (a server failing), while recent
  std::string network;                   // failed loads and their retries, when any failed
  std::string ruler;                     // the ruler's length and area, while it is on (M)
  // The imagery controls (L, 1-4, [ ]): said only with layers.
  struct Layer {
    bool shown = true;
    float opacity = 1.0f;
  };
  terrain::ImageryLighting lighting = terrain::ImageryLighting::Auto;
  std::vector<Layer> layers;
  size_t selectedLayer = 0;
  std::optional<double> sunUnixSeconds;  // the Sun's instant (--time, , and .), said when set
  // What the terrain under the camera was made from: "ETOPO20.DEM, 20' (~37 km)" (empty: unknown).
  std::string terrainData;
};

// A source's sample spacing as people say it, with its length along a meridian, in the HUD's
// ASCII: "20' (~37 km)", "3\" (~93 m)", "2 deg (~222 km)".
std::string spacingText(double stepDegrees);
// "ETOPO20.DEM, 20' (~37 km)": the finest source of the pyramid at (lon, lat) and its spacing;
// empty where the manifest names none (a terrain service, or outside every source).
std::string terrainDataText(const formats::PyramidManifest& manifest, double longitudeDegrees,
                            double latitudeDegrees);

// "lighting auto  layers >1 on 100%  2 off 40%" (> marks the layer [ and ] change); empty
// without layers.
std::string imageryStatus(const HudState& state);

// "terrain H m  clearance C m", or "no terrain under the camera" (never a clearance above the
// ellipsoid presented as one above the ground); the HUD and the window title both say this.
std::string terrainStatus(const camera::CollisionState& collision);

// The status lines, e.g. "lon 138.73000  lat 35.36000  height 4123 m". With withFrameTime false
// the frame time is left out: what the loop compares to decide whether the HUD changed.
std::vector<std::string> hudStatusLines(const HudState& state, bool withFrameTime = true);

// The scale bar: the longest round ground length (1, 2 or 5 x 10^k m) at most maximumPixels long
// at this many metres a pixel, e.g. {85.1 px, "2 km"} at 23.5 m/px and 100 px; nullopt where the
// scale is unknown (NaN: no ground at the centre).
struct ScaleBarLength {
  double pixels = 0;
  std::string label;
};
std::optional<ScaleBarLength> scaleBarLength(double metersPerPixel, double maximumPixels);


}  // namespace globe::app
