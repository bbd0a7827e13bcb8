// The HUD's status and help text, formatted from the camera, the collision state and the tiles.
#include "apps/globe/hud_text.hpp"

#include <cmath>
#include <filesystem>
#include <cstdio>

#include "collision/collision_response.hpp"
#include "geo/cartographic.hpp"
#include "sun/utc_time.hpp"

namespace globe::app {
namespace {

std::string format(const char* pattern, auto... values) {
  char text[256];
  std::snprintf(text, sizeof text, pattern, values...);
  return text;
}

// Metres with fewer decimals the larger they are: 1.25 m, 312.4 m, 41236 m.
std::string meters(double value) {
  const double magnitude = std::abs(value);
  return format(magnitude < 100 ? "%.2f m" : magnitude < 10000 ? "%.1f m" : "%.0f m", value);
}

double displayHeadingDegrees(double radians) {
  double degrees = std::fmod(geo::radiansToDegrees(radians), 360.0);
  if (degrees < 0) degrees += 360.0;
  return degrees >= 359.95 ? 0.0 : degrees;
}

}  // namespace

std::string spacingText(double stepDegrees) {
  constexpr double kMetersPerDegree = 6'371'000.0 * 3.141592653589793 / 180;
  const double meters = stepDegrees * kMetersPerDegree;
  const std::string length =
      meters >= 10'000 ? format("%.0f km", meters / 1000)
      : meters >= 1000 ? format("%.1f km", meters / 1000)
                       : format("%.0f m", meters);
  const std::string angle = stepDegrees >= 1        ? format("%g deg", stepDegrees)
                            : stepDegrees * 60 >= 1 ? format("%.3g'", stepDegrees * 60)
                                                    : format("%.3g\"", stepDegrees * 3600);
  return angle + " (~" + length + ")";
}

std::string terrainStatus(const camera::CollisionState& collision) {
  if (!collision.terrainFound) return "no terrain under the camera";
  return "terrain " + meters(collision.terrainHeightMeters) + "  clearance " +
         meters(collision.clearanceMeters);
}

std::string imageryStatus(const HudState& s) {
  if (s.layers.empty()) return {};
  std::string text = "lighting " + std::string(terrain::toString(s.lighting)) + "  layers";
  for (size_t k = 0; k < s.layers.size(); ++k) {
    text += format("%s%s%zu %s %.0f%%", k == 0 ? " " : "  ", k == s.selectedLayer ? ">" : "", k + 1,
                   s.layers[k].shown ? "on" : "off", 100.0 * s.layers[k].opacity);
  }
  return text;
}

std::vector<std::string> hudStatusLines(const HudState& s, bool withFrameTime) {
  std::vector<std::string> lines;
  std::string mode = std::string(camera::toString(s.mode)) + (s.flyingTo ? " (flying to)" : "");
  if (s.mode == camera::NavigationMode::Fly) {
    mode += format("  speed %.1f m/s ", s.flySpeedMetersPerSecond) +
            (s.speedFactor >= 1 ? format("(x%g)", s.speedFactor)
                                : format("(x1/%g)", 1.0 / s.speedFactor));
  }
  lines.push_back(mode);
  lines.push_back(format("lon %.5f  lat %.5f  height ", s.pose.position.longitudeDegrees(),
                         s.pose.position.latitudeDegrees()) +
                  meters(s.pose.position.heightMeters));
  lines.push_back(terrainStatus(s.collision));
  if (!s.terrainData.empty()) lines.push_back("terrain data: " + s.terrainData);
  lines.push_back(format("heading %.1f  pitch %.1f", displayHeadingDegrees(s.pose.headingRadians),
                         geo::radiansToDegrees(s.pose.pitchRadians)));
  lines.push_back(s.collision.collided
                      ? "COLLISION " + std::string(collision::toString(s.collision.response))
                      : std::string("collision none"));
  if (s.underCursor) {
    lines.push_back(format("cursor lon %.5f  lat %.5f  ground ", s.underCursor->longitudeDegrees(),
                           s.underCursor->latitudeDegrees()) +
                    meters(s.underCursor->heightMeters));
  }
  if (s.prompt) {
    lines.push_back(s.promptSavesView
                        ? "save view as: " + *s.prompt + "_   (Enter: save, Esc: cancel)"
                    : s.promptOpensFile ? "open KML/KMZ/GeoJSON/GPX: " + *s.prompt +
                                              "_   (Enter: open, Esc: cancel)"
                                        : "go to: " + *s.prompt + "_   (Enter: go, Esc: cancel)");
    for (const std::string& place : s.suggestions) lines.push_back("       " + place);
  }
  if (!s.message.empty()) lines.push_back(s.message);
  if (!s.network.empty()) lines.push_back("network: " + s.network);
  if (!s.warning.empty()) lines.push_back("! " + s.warning);
  std::string tiles = format("tiles %zu drawn, %zu loading", s.tilesDrawn, s.tilesLoading);
  if (s.tilesMissing > 0) tiles += format(", %zu FAILED (drawn coarser)", s.tilesMissing);
  if (withFrameTime && s.frameMilliseconds > 0) {
    tiles += format("  frame %.1f ms (%.0f fps)", s.frameMilliseconds, 1000 / s.frameMilliseconds);
  }
  lines.push_back(tiles);
  if (std::string imagery = imageryStatus(s); !imagery.empty()) lines.push_back(std::move(imagery));
  if (s.sunUnixSeconds) lines.push_back("sun " + sun::formatUtcTime(*s.sunUnixSeconds));
  if (!s.ruler.empty()) lines.push_back(s.ruler);
  if (s.recording) lines.push_back(format("REC  %zu keyframes  (P stops)", s.keyframes));
  lines.push_back("H: help");
  return lines;
}

std::optional<ScaleBarLength> scaleBarLength(double metersPerPixel, double maximumPixels) {
  if (!std::isfinite(metersPerPixel) || !(metersPerPixel > 0) || !std::isfinite(maximumPixels) ||
      !(maximumPixels >= 1)) {
    return std::nullopt;
  }
  const double most = metersPerPixel * maximumPixels;
  const double decade = std::pow(10.0, std::floor(std::log10(most)));
  double meters = decade;
  for (const double step : {5.0, 2.0}) {
    if (step * decade <= most) {
      meters = step * decade;
      break;
    }
  }
  const std::string label = meters >= 1000 ? format("%.0f km", meters / 1000)
                            : meters >= 1  ? format("%.0f m", meters)
                                           : format("%g m", meters);
  return ScaleBarLength{meters / metersPerPixel, label};
}

std::string terrainDataText(const formats::PyramidManifest& manifest, double longitudeDegrees,
                            double latitudeDegrees) {
  const formats::SourceInfo* source =
      formats::finestSourceAt(manifest, longitudeDegrees, latitudeDegrees);
  if (source == nullptr) return "";
  return std::filesystem::path(source->path).filename().string() + ", " +
         spacingText(source->stepDegrees);
}

}  // namespace globe::app
