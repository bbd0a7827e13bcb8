// The accuracy mode: three real regions at their finest level, a fixed set of camera queries
// near the drawn surface, each method timed per query and its effective terrain height and
// decisions compared with the drawn surface and with the finest source data.
#include "tools/bench/accuracy.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "collision/exact_surface.hpp"
#include "collision/height_service.hpp"
#include "collision/qotcd.hpp"
#include "collision/sphere_tree.hpp"
#include "geo/ecef.hpp"
#include "tests/collision/mesh_ray_cast.hpp"
#include "tools/bench/accuracy_table.hpp"
#include "tools/bench/memory_use.hpp"
#include "tools/bench/query_timer.hpp"
#include "tools/bench/source_reference.hpp"

namespace globe::bench {
namespace {

constexpr double kRadius = kAccuracyRadiusMeters;
// Camera heights: the drawn surface plus a uniform offset in this range.
constexpr double kLowestOffsetMeters = -100.0;
constexpr double kHighestOffsetMeters = 200.0;
// The sphere tree's effective height is searched up to this far above the drawn surface.
constexpr double kSphereSearchMeters = 5000.0;

struct Region {
  std::string name;
  std::string source;
  uint32_t level;
  formats::BoundsDegrees tileBounds;   // the array: every tile of the level meeting these bounds
  formats::BoundsDegrees queryBounds;  // where the queries lie
  bool wholeGlobe;                     // queries uniform by area over the globe, on land, outside
                                       // the finer sources (so that the finest source is ETOPO20)
};

std::vector<Region> regions() {
  return {
      {"fuji", "SRTM 3\" (E138N35_FUJI)", 14, {138, 35, 139, 36}, {138, 35, 139, 36}, false},
      {"england", "GTOPO30 30\" (W002N52)", 11, {-2, 52, 0, 54}, {-2, 52, 0, 54}, false},
      {"world", "ETOPO20 20' (land)", 6, {-180, -90, 180, 90}, {-180, -90, 180, 90}, true},
  };
}
bool inside(const formats::BoundsDegrees& b, double lonDegrees, double latDegrees) {
  return lonDegrees >= b.west && lonDegrees <= b.east && latDegrees >= b.south &&
         latDegrees <= b.north;
}

double squaredDistanceToSegment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 ab = b - a;
  const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
  const glm::dvec3 d = p - (a + t * ab);
  return glm::dot(d, d);
}

// The sphere tree's effective terrain height at the query's longitude/latitude: the highest
// camera height D (along the normal) at which the 50 m sphere still meets a triangle, minus
// 50 m, found by bisection (the camera is on the drawn surface's normal line; at D = E + 50 m
// the triangle under it is within reach).
double sphereEffectiveHeight(const collision::SphereTreeSet& trees,
                             const std::vector<collision::BoundingSphere>& roots,
                             const geo::Ellipsoid& ellipsoid, const AccuracyQuery& q) {
  auto at = [&](double height) {
    return geo::cartographicToEcef(ellipsoid, {q.longitude, q.latitude, height});
  };
  const double bottom = q.drawn - kRadius, top = q.drawn + kRadius + kSphereSearchMeters;
  const glm::dvec3 low = at(bottom), high = at(top);
  std::vector<uint32_t> candidates;
  for (uint32_t t = 0; t < roots.size(); ++t) {
    const double reach = roots[t].radiusMeters + kRadius;
    if (squaredDistanceToSegment(roots[t].centerEcefMeters, low, high) <= reach * reach) {
      candidates.push_back(t);
    }
  }
  auto collides = [&](double height) {
    const glm::dvec3 camera = at(height);
    return std::any_of(candidates.begin(), candidates.end(), [&](uint32_t t) {
      return trees.intersectTile(t, camera, kRadius).collided;
    });
  };
  double lo = q.drawn + kRadius - 1e-3;
  if (!collides(lo)) lo = q.drawn;
  if (!collides(lo)) return q.drawn;  // not expected: the drawn triangle is a tree triangle
  double hi = q.drawn + kRadius + 250.0;
  while (hi < top && collides(hi)) lo = hi, hi = std::min(top, hi + 250.0);
  for (int step = 0; step < 30; ++step) {
    const double mid = 0.5 * (lo + hi);
    (collides(mid) ? lo : hi) = mid;
  }
  return lo - kRadius;
}
}  // namespace

int runAccuracy(Pyramid& pyramid, const AccuracyOptions& options) {
  const geo::Ellipsoid ellipsoid = pyramid.ellipsoid();
  std::vector<std::filesystem::path> rasterPaths;
  for (const formats::SourceInfo& source : pyramid.manifest().sources) {
    rasterPaths.emplace_back(source.path);
  }
  auto reference = SourceReference::load(rasterPaths);
  if (!reference) {
    std::fprintf(stderr, "globe-bench: %s\n", reference.error().c_str());
    return 1;
  }
  const QueryTimer timer;
  std::printf("per-query timer: %.2f ns per tick, %.1f ns overhead subtracted\n",
              timer.nanosecondsPerTick(), timer.overheadNanoseconds());
  std::mt19937_64 rng(options.seed);
  std::vector<AccuracyRow> rows;
  std::vector<AccuracyQuery> all;  // every region's queries, for the overall rows
  nlohmann::json header;
  header["clearance_m"] = kRadius;
  header["sphere_radius_m"] = kRadius;
  header["camera_offset_range_m"] = {kLowestOffsetMeters, kHighestOffsetMeters};
  header["timer_overhead_ns"] = timer.overheadNanoseconds();
  header["regions"] = nlohmann::json::array();
  std::array<double, kMethodCount> bytesTotals{};
  size_t tileTotal = 0;

  for (const Region& region : regions()) {
    const formats::BoundsDegrees& b = region.tileBounds;
    const std::vector<geo::TileId> ids =
        pyramid.tilesOfLevel(region.level, b.west, b.south, b.east, b.north);
    std::vector<terrain::ArrayTile> tiles;
    for (const geo::TileId& id : ids)
      tiles.push_back(terrain::makeArrayTile(id, pyramid.block(id)));
    terrain::RenderingTileArray array;
    array.assign(std::move(tiles));
    collision::SphereTreeSet trees;
    trees.build(array, ellipsoid);
    std::vector<collision::BoundingSphere> roots;
    for (uint32_t t = 0; t < trees.tileCount(); ++t) roots.push_back(trees.node(t, 0, 0));

    // The fixed queries.
    std::uniform_real_distribution<double> unit(0.0, 1.0),
        offset(kLowestOffsetMeters, kHighestOffsetMeters);
    std::vector<AccuracyQuery> queries;
    queries.reserve(options.queriesPerRegion);
    const formats::BoundsDegrees& qb = region.queryBounds;
    while (queries.size() < options.queriesPerRegion) {
      AccuracyQuery q;
      if (region.wholeGlobe) {
        q.longitude = -std::numbers::pi + 2.0 * std::numbers::pi * unit(rng);
        q.latitude = std::asin(2.0 * unit(rng) - 1.0);
      } else {
        q.longitude = geo::degreesToRadians(qb.west + (qb.east - qb.west) * unit(rng));
        q.latitude = geo::degreesToRadians(qb.south + (qb.north - qb.south) * unit(rng));
      }
      const double lonDeg = geo::radiansToDegrees(q.longitude);
      const double latDeg = geo::radiansToDegrees(q.latitude);
      const auto source = reference->heightMeters(lonDeg, latDeg);
      // Reference (a), the drawn surface, by the tests' brute-force ray caster (every triangle
      // of the tile, written apart from exactSurfaceHeight), so the exact method is measured
      // against it rather than equal to it by construction.
      const terrain::ArrayTile* tile = array.findIndexed(q.longitude, q.latitude);
      const auto drawn = tile == nullptr ? std::nullopt
                                         : collision::testing::castOntoTileMesh(
                                               *tile, ellipsoid, q.longitude, q.latitude);
      const auto exact = collision::exactSurfaceHeight(array, ellipsoid, q.longitude, q.latitude);
      if (!source || !drawn || !exact) continue;
      if (region.wholeGlobe) {
        bool finer = false;
        for (const Region& other : regions()) {
          finer = finer || (!other.wholeGlobe && inside(other.queryBounds, lonDeg, latDeg));
        }
        if (finer || *source <= 0.0) continue;
      }
      q.source = *source;
      q.drawn = drawn->heightMeters;
      q.cameraHeight = q.drawn + offset(rng);
      q.ecef = geo::cartographicToEcef(ellipsoid, {q.longitude, q.latitude, q.cameraHeight});
      const auto qotcd = collision::sampleHeight(array, ellipsoid, q.longitude, q.latitude,
                                                 collision::HeightMode::Qotcd);
      q.effectiveHeight[kQotcdLinear] = q.effectiveHeight[kQotcdIndexed] =
          qotcd ? qotcd->heightMeters : 0.0;
      q.effectiveHeight[kExactSurface] = exact->heightMeters;
      q.effectiveHeight[kSphereTree] = sphereEffectiveHeight(trees, roots, ellipsoid, q);
      queries.push_back(q);
    }

    // Each method over every query, timed one by one (after a short warm-up).
    auto run = [&](size_t method, const glm::dvec3& camera) {
      switch (method) {
        case kSphereTree:
          return trees.intersect(camera, kRadius).collided;
        case kQotcdLinear:
          return collision::qotcdLinear(array, ellipsoid, camera, kRadius).collided;
        case kQotcdIndexed:
          return collision::qotcdIndexed(array, ellipsoid, camera, kRadius).collided;
        default:
          return collision::exactSurfaceTest(array, ellipsoid, camera, kRadius).collided;
      }
    };
    for (size_t method = 0; method < kMethodCount; ++method) {
      bool sink = false;
      for (size_t k = 0; k < std::min<size_t>(1000, queries.size()); ++k) {
        sink = sink != run(method, queries[k].ecef);
      }
      for (AccuracyQuery& q : queries) {
        const uint64_t start = QueryTimer::now();
        const bool collided = run(method, q.ecef);
        const uint64_t end = QueryTimer::now();
        q.collided[method] = collided;
        q.nanoseconds[method] = timer.nanoseconds(start, end);
      }
      if (sink) std::fflush(stdout);  // keeps the warm-up from being optimised away
    }

    const MemoryUse memory = memoryUse(array, trees);
    const std::array<double, kMethodCount> bytes = {
        memory.sphereTreeBytesPerTile, memory.qotcdLinearBytesPerTile,
        memory.qotcdIndexedBytesPerTile, memory.exactSurfaceBytesPerTile};
    std::vector<const AccuracyQuery*> pointers;
    for (const AccuracyQuery& q : queries) pointers.push_back(&q);
    for (size_t method = 0; method < kMethodCount; ++method) {
      rows.push_back(summarise(region.name, method, ids.size(), pointers, bytes[method]));
      bytesTotals[method] += bytes[method] * static_cast<double>(ids.size());
    }
    tileTotal += ids.size();
    header["regions"].push_back({{"name", region.name},
                                 {"source", region.source},
                                 {"level", region.level},
                                 {"tiles", ids.size()},
                                 {"queries", queries.size()}});
    all.insert(all.end(), queries.begin(), queries.end());
  }
  std::vector<const AccuracyQuery*> pointers;
  for (const AccuracyQuery& q : all) pointers.push_back(&q);
  for (size_t method = 0; method < kMethodCount; ++method) {
    rows.push_back(summarise("all", method, tileTotal, pointers,
                             bytesTotals[method] / static_cast<double>(tileTotal)));
  }
  printAccuracyTable(rows);
  if (!options.outputDirectory.empty()) writeAccuracyFiles(options.outputDirectory, rows, header);
  return 0;
}

}  // namespace globe::bench