// Formatting of `globe play`'s per-frame log, timing log and summary.
#include "apps/globe/play_log.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "geo/cartographic.hpp"

namespace globe::app {
namespace {

// Degrees in (-180, 180]; "-0.000" never printed.
double signedAngleDegrees(double radians) {
  double degrees = geo::radiansToDegrees(radians);
  degrees = std::fmod(degrees, 360.0);
  if (degrees > 180.0) degrees -= 360.0;
  if (degrees <= -180.0) degrees += 360.0;
  return degrees;
}

// Rounds to the printed precision first so -0.0004 prints as 0.000, not -0.000.
double printable(double value, double scale) {
  const double rounded = std::round(value * scale) / scale;
  return rounded == 0.0 ? 0.0 : rounded;
}

template <class F>
double medianOf(const std::vector<FrameRecord>& frames, F field) {
  std::vector<double> values;
  for (const FrameRecord& r : frames) values.push_back(field(r));
  return quantile(std::move(values), 0.5);
}

}  // namespace

std::string_view toString(TerrainSource source) {
  switch (source) {
    case TerrainSource::Drawn:
      return "drawn";
    case TerrainSource::Nadir:
      return "nadir";
    default:
      return "finest";
  }
}

double quantile(std::vector<double> values, double q) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<size_t>(std::ceil(q * static_cast<double>(values.size())));
  return values[std::clamp<size_t>(rank, 1, values.size()) - 1];
}

std::string formatPlayLog(const std::vector<FrameRecord>& frames) {
  std::string text =
      "frame,time_s,lon_deg,lat_deg,height_m,terrain_height_m,clearance_m,collided,response,"
      "tiles_drawn,terrain_source,heading_deg,pitch_deg,roll_deg,scripted_height_m,near_clearance_"
      "m\n";
  char line[512];
  for (const FrameRecord& r : frames) {
    std::snprintf(line, sizeof line,
                  "%d,%.4f,%.7f,%.7f,%.3f,%.3f,%.3f,%d,%s,%zu,%s,%.3f,%.3f,%.3f,%.3f,%.3f\n",
                  r.frame, printable(r.timeSeconds, 1e4),
                  printable(r.pose.position.longitudeDegrees(), 1e7),
                  printable(r.pose.position.latitudeDegrees(), 1e7),
                  printable(r.pose.position.heightMeters, 1e3),
                  printable(r.terrainHeightMeters, 1e3), printable(r.clearanceMeters, 1e3),
                  r.collided ? 1 : 0, std::string(collision::toString(r.response)).c_str(),
                  r.tilesDrawn, std::string(toString(r.terrainSource)).c_str(),
                  printable(signedAngleDegrees(r.pose.headingRadians), 1e3),
                  printable(geo::radiansToDegrees(r.pose.pitchRadians), 1e3),
                  printable(signedAngleDegrees(r.pose.rollRadians), 1e3),
                  printable(r.scriptedHeightMeters, 1e3), printable(r.nearClearanceMeters, 1e3));
    text += line;
  }
  return text;
}

std::string formatTimingLog(const std::vector<FrameRecord>& frames) {
  std::string text = "frame,select_ms,load_ms,collision_ms,draw_ms,write_ms,total_ms\n";
  char line[256];
  for (const FrameRecord& r : frames) {
    const FrameTimings& t = r.timings;
    std::snprintf(line, sizeof line, "%d,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f\n", r.frame, t.selectMs,
                  t.loadMs, t.collisionMs, t.drawMs, t.writeMs, t.totalMs);
    text += line;
  }
  return text;
}

PlaySummary summarize(const std::vector<FrameRecord>& frames) {
  PlaySummary s;
  s.frames = static_cast<int>(frames.size());
  std::vector<double> totals;
  for (const FrameRecord& r : frames) {
    if (r.collided) {
      ++s.collisionFrames;
      if (s.firstCollisionFrame < 0) s.firstCollisionFrame = r.frame;
    }
    if (s.minimumClearanceFrame < 0 || r.clearanceMeters < s.minimumClearanceMeters) {
      s.minimumClearanceMeters = r.clearanceMeters;
      s.minimumClearanceFrame = r.frame;
    }
    totals.push_back(r.timings.totalMs);
    s.peakImageryTextureBytes = std::max(s.peakImageryTextureBytes, r.imageryTextureBytes);
  }
  s.medianFrameMs = quantile(totals, 0.5);
  s.p90FrameMs = quantile(totals, 0.9);
  s.maximumFrameMs = quantile(totals, 1.0);
  s.medianSelectMs = medianOf(frames, [](const FrameRecord& r) { return r.timings.selectMs; });
  s.medianLoadMs = medianOf(frames, [](const FrameRecord& r) { return r.timings.loadMs; });
  s.medianDrawMs = medianOf(frames, [](const FrameRecord& r) { return r.timings.drawMs; });
  return s;
}

std::string formatSummary(const PlaySummary& s, const std::vector<FrameRecord>& frames) {
  std::map<std::string, int> responses;
  for (const FrameRecord& r : frames) {
    if (r.collided) ++responses[std::string(collision::toString(r.response))];
  }
  std::string counts;
  for (const auto& [name, count] : responses) {
    counts += (counts.empty() ? "" : ", ") + name + " " + std::to_string(count);
  }
  char text[1024];
  const double seconds =
      frames.empty() ? 0 : frames.back().timeSeconds - frames.front().timeSeconds;
  int n = std::snprintf(text, sizeof text, "frames: %d (%.2f s of path)\n", s.frames, seconds);
  if (s.firstCollisionFrame >= 0) {
    n += std::snprintf(text + n, sizeof text - static_cast<size_t>(n),
                       "collisions: %d frames, first at frame %d (%s)\n", s.collisionFrames,
                       s.firstCollisionFrame, counts.c_str());
  } else {
    n += std::snprintf(text + n, sizeof text - static_cast<size_t>(n), "collisions: none\n");
  }
  if (s.minimumClearanceFrame >= 0) {
    const FrameRecord& low = frames[static_cast<size_t>(s.minimumClearanceFrame)];
    n += std::snprintf(text + n, sizeof text - static_cast<size_t>(n),
                       "min clearance: %.3f m at frame %d (t %.2f s, %.5f, %.5f, terrain %.1f m)\n",
                       s.minimumClearanceMeters, s.minimumClearanceFrame, low.timeSeconds,
                       low.pose.position.longitudeDegrees(), low.pose.position.latitudeDegrees(),
                       low.terrainHeightMeters);
  }
  n += std::snprintf(text + n, sizeof text - static_cast<size_t>(n),
                     "time per frame: median %.1f ms, p90 %.1f ms, max %.1f ms (median select "
                     "%.1f, load %.1f, draw %.1f ms)\n",
                     s.medianFrameMs, s.p90FrameMs, s.maximumFrameMs, s.medianSelectMs,
                     s.medianLoadMs, s.medianDrawMs);
  if (s.imageryTextureBudgetBytes > 0) {
    std::snprintf(text + n, sizeof text - static_cast<size_t>(n),
                  "imagery textures: peak %.1f MiB of a %.1f MiB budget\n",
                  static_cast<double>(s.peakImageryTextureBytes) / (1 << 20),
                  static_cast<double>(s.imageryTextureBudgetBytes) / (1 << 20));
  }
  return text;
}

}  // namespace globe::app
