// Formatting of `globe play`'s per-frame log, timing log and summary.
#include "apps/globe/play_log.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "geo/cartographic.hpp"

namespace globe::app {
namespace {

// A compass heading in [0, 360), as --camera takes it (330, not -30).
double compassDegrees(double radians) {
  double degrees = std::fmod(geo::radiansToDegrees(radians), 360.0);
  if (degrees < 0) degrees += 360.0;
  return std::round(degrees * 1e3) >= 360e3 ? 0.0 : degrees;  // 359.9999 would print as 360
}

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
      "m,lift_m,vertical_jolt_m,new_ground_lift_m,fov_deg\n";
  const std::vector<double> jolts = verticalJoltMeters(frames);
  char line[512];
  for (size_t i = 0; i < frames.size(); ++i) {
    const FrameRecord& r = frames[i];
    std::snprintf(
        line, sizeof line,
        "%d,%.4f,%.7f,%.7f,%.3f,%.3f,%.3f,%d,%s,%zu,%s,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,"
        "%.4f\n",
        r.frame, printable(r.timeSeconds, 1e4), printable(r.pose.position.longitudeDegrees(), 1e7),
        printable(r.pose.position.latitudeDegrees(), 1e7),
        printable(r.pose.position.heightMeters, 1e3), printable(r.terrainHeightMeters, 1e3),
        printable(r.clearanceMeters, 1e3), r.collided ? 1 : 0,
        std::string(collision::toString(r.response)).c_str(), r.tilesDrawn,
        std::string(toString(r.terrainSource)).c_str(),
        printable(compassDegrees(r.pose.headingRadians), 1e3),
        printable(geo::radiansToDegrees(r.pose.pitchRadians), 1e3),
        printable(signedAngleDegrees(r.pose.rollRadians), 1e3),
        printable(r.scriptedHeightMeters, 1e3), printable(r.nearClearanceMeters, 1e3),
        printable(r.pose.position.heightMeters - r.scriptedHeightMeters, 1e3),
        printable(jolts[i], 1e3), printable(r.newGroundLiftMeters, 1e3),
        printable(r.fovYDegrees, 1e4));
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

std::vector<double> verticalJoltMeters(const std::vector<FrameRecord>& frames) {
  std::vector<double> jolts(frames.size(), 0.0);
  for (size_t i = 1; i + 1 < frames.size(); ++i) {
    jolts[i] = frames[i + 1].pose.position.heightMeters - 2 * frames[i].pose.position.heightMeters +
               frames[i - 1].pose.position.heightMeters;
  }
  return jolts;
}

MotionQuality motionQuality(const std::vector<FrameRecord>& frames) {
  constexpr double kOffScriptMeters = 0.01;
  const size_t n = frames.size();
  std::vector<bool> acting(n, false);
  for (size_t i = 0; i < n; ++i) {
    const FrameRecord& r = frames[i];
    if (!r.collided &&
        std::abs(r.pose.position.heightMeters - r.scriptedHeightMeters) <= kOffScriptMeters) {
      continue;
    }
    for (size_t k = i > 0 ? i - 1 : 0; k <= std::min(i + 1, n - 1); ++k) acting[k] = true;
  }
  const std::vector<double> jolts = verticalJoltMeters(frames);
  std::vector<double> response, ground, free;
  MotionQuality q;
  for (size_t i = 0; i < n; ++i) {
    q.minimumNearClearanceMeters =
        i == 0 ? frames[i].nearClearanceMeters
               : std::min(q.minimumNearClearanceMeters, frames[i].nearClearanceMeters);
    q.largestNewGroundLiftMeters =
        std::max(q.largestNewGroundLiftMeters, frames[i].newGroundLiftMeters);
    if (i == 0 || i + 1 == n) continue;
    if (!acting[i]) {
      free.push_back(std::abs(jolts[i]));
      continue;
    }
    response.push_back(std::abs(jolts[i]));
    ground.push_back(std::abs(frames[i + 1].terrainHeightMeters -
                              2 * frames[i].terrainHeightMeters +
                              frames[i - 1].terrainHeightMeters));
  }
  q.responseFrames = static_cast<int>(response.size());
  q.p95JoltResponseMeters = quantile(response, 0.95);
  q.p95GroundJoltMeters = quantile(ground, 0.95);
  q.p95JoltFreeMeters = quantile(free, 0.95);
  return q;
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
  const MotionQuality motion = motionQuality(frames);
  n +=
      std::snprintf(text + n, sizeof text - static_cast<size_t>(n),
                    "motion: p95 vertical jolt %.3f m/frame^2 over %d frames the response acts "
                    "on (the ground's own there %.3f), %.3f in free flight; lowest near-plane "
                    "corner %.3f m; largest lift by new ground in one frame %.3f m\n",
                    motion.p95JoltResponseMeters, motion.responseFrames, motion.p95GroundJoltMeters,
                    motion.p95JoltFreeMeters, motion.minimumNearClearanceMeters,
                    motion.largestNewGroundLiftMeters);
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
