// Benchmark cases over Fuji-centred arrays: one query per iteration, consecutive frames of one
// flight path (or independent random positions), cycling through a precomputed query list.
#include "tools/bench/timing_benchmarks.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "camera/camera_controller.hpp"
#include "collision/exact_surface.hpp"
#include "collision/lateral_clearance.hpp"
#include "collision/qotcd.hpp"
#include "collision/sphere_tree.hpp"
#include "collision/sphere_tree_bvh.hpp"
#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "tools/bench/bench_terrain.hpp"

namespace globe::bench {
namespace {

constexpr size_t kFlightFrames = 4096;  // 68 s of flight at 60 Hz
constexpr size_t kRandomQueries = 65536;
constexpr uint64_t kFlightSeed = 20240607;
constexpr uint64_t kRandomSeed = 7;
constexpr double kClearanceMeters = collision::kCameraSphereRadiusMeters;
const std::vector<int64_t> kTileCounts = {10, 100, 1000, 10000, 100000};

// Everything the cases share, built on first use and kept (the sphere trees: one size at a
// time, they are large).
struct Shared {
  std::filesystem::path pyramidDirectory;
  std::unique_ptr<Pyramid> pyramid;
  std::string error;
  std::map<uint32_t, std::unique_ptr<BenchArray>> arrays;
  std::map<uint32_t, std::vector<CameraQuery>> randomQueries;
  std::vector<CameraQuery> flight;
  std::vector<CameraQuery> flightOnSphere;  // the same longitude, latitude, height on a sphere
  uint32_t treeTiles = 0;
  std::unique_ptr<collision::SphereTreeSet> trees;
  double treeBuildSeconds = 0;
  std::unique_ptr<collision::SphereTreeBvh> bvh;  // over `trees`
  double bvhBuildSeconds = 0;

  Pyramid* openPyramid() {
    if (!pyramid && error.empty()) {
      auto opened = Pyramid::open(pyramidDirectory);
      if (opened) {
        pyramid = std::move(*opened);
      } else {
        error = opened.error();
      }
    }
    return pyramid.get();
  }
  const BenchArray* array(uint32_t tiles) {
    auto it = arrays.find(tiles);
    if (it != arrays.end()) return it->second.get();
    if (openPyramid() == nullptr) return nullptr;
    auto made = makeBenchArray(*pyramid, tiles);
    if (!made) {
      error = made.error();
      return nullptr;
    }
    return arrays.emplace(tiles, std::move(*made)).first->second.get();
  }
  const std::vector<CameraQuery>* flightPath() {
    if (flight.empty()) {
      const BenchArray* area = array(10);
      if (area == nullptr) return nullptr;
      flight = bench::flightPath(area->array, flightArea(), pyramid->ellipsoid(), kFlightFrames,
                                 kFlightSeed);
    }
    return &flight;
  }
  const std::vector<CameraQuery>* sphereFlightPath() {
    if (flightOnSphere.empty() && flightPath() != nullptr) {
      flightOnSphere = flight;
      for (CameraQuery& q : flightOnSphere) {
        q.ecefMeters = geo::cartographicToEcef(
            geo::Ellipsoid::sphere(), {q.longitudeRadians, q.latitudeRadians, q.heightMeters});
      }
    }
    return flightOnSphere.empty() ? nullptr : &flightOnSphere;
  }
  const std::vector<CameraQuery>* random(uint32_t tiles) {
    auto it = randomQueries.find(tiles);
    if (it != randomQueries.end()) return &it->second;
    const BenchArray* a = array(tiles);
    if (a == nullptr) return nullptr;
    auto queries = bench::randomQueries(a->array, a->bounds, pyramid->ellipsoid(), kRandomQueries,
                                        kRandomSeed);
    return &randomQueries.emplace(tiles, std::move(queries)).first->second;
  }
  const collision::SphereTreeSet* sphereTrees(uint32_t tiles) {
    if (trees && treeTiles == tiles) return trees.get();
    const BenchArray* a = array(tiles);
    if (a == nullptr) return nullptr;
    bvh.reset();
    trees.reset();
    auto built = std::make_unique<collision::SphereTreeSet>();
    const auto start = std::chrono::steady_clock::now();
    built->build(a->array, pyramid->ellipsoid());
    treeBuildSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    trees = std::move(built);
    treeTiles = tiles;
    return trees.get();
  }
  const collision::SphereTreeBvh* sphereTreeBvh(uint32_t tiles) {
    const collision::SphereTreeSet* set = sphereTrees(tiles);
    if (set == nullptr) return nullptr;
    if (!bvh) {
      const auto start = std::chrono::steady_clock::now();
      bvh = std::make_unique<collision::SphereTreeBvh>(*set);
      bvhBuildSeconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    return bvh.get();
  }
};

Shared& shared() {
  static Shared instance;
  return instance;
}

// Runs `query(camera)` once per iteration over the whole list, a whole number of times (so
// every size sees the same frames); counts collisions.
template <class Query>
void runQueries(benchmark::State& state, const std::vector<CameraQuery>& queries, Query&& query) {
  int64_t collisions = 0;
  while (state.KeepRunningBatch(static_cast<benchmark::IterationCount>(queries.size()))) {
    for (const CameraQuery& camera : queries) {
      const bool collided = query(camera);
      benchmark::DoNotOptimize(collided);
      collisions += collided ? 1 : 0;
    }
  }
  state.counters["collided"] =
      benchmark::Counter(static_cast<double>(collisions), benchmark::Counter::kAvgIterations);
}

bool prepare(benchmark::State& state, const BenchArray*& array,
             const std::vector<CameraQuery>*& queries, bool randomPositions) {
  const auto tiles = static_cast<uint32_t>(state.range(0));
  array = shared().array(tiles);
  queries = array == nullptr ? nullptr
                             : (randomPositions ? shared().random(tiles) : shared().flightPath());
  if (array == nullptr || queries == nullptr) {
    state.SkipWithError(shared().error.c_str());
    return false;
  }
  state.counters["tiles"] = static_cast<double>(array->array.tiles().size());
  return true;
}

void BM_SphereTree(benchmark::State& state) {
  const BenchArray* array = nullptr;
  const std::vector<CameraQuery>* queries = nullptr;
  if (!prepare(state, array, queries, false)) return;
  const collision::SphereTreeSet* trees =
      shared().sphereTrees(static_cast<uint32_t>(state.range(0)));
  int64_t sphereTests = 0, triangleTests = 0;
  runQueries(state, *queries, [&](const CameraQuery& camera) {
    const collision::SphereTreeResult result =
        trees->intersect(camera.ecefMeters, collision::kCameraSphereRadiusMeters);
    sphereTests += result.sphereTests;
    triangleTests += result.triangleTests;
    return result.collided;
  });
  const double tiles = static_cast<double>(trees->tileCount());
  state.counters["Nv"] =
      benchmark::Counter(static_cast<double>(sphereTests), benchmark::Counter::kAvgIterations);
  state.counters["Np"] =
      benchmark::Counter(static_cast<double>(triangleTests), benchmark::Counter::kAvgIterations);
  state.counters["build_ns_per_tile"] = shared().treeBuildSeconds * 1e9 / tiles;
  state.counters["bytes_per_tile"] = static_cast<double>(trees->memoryBytes()) / tiles;
}

// The fair baseline: the same sphere trees found through a BVH over their root spheres.
void BM_SphereTreeBvh(benchmark::State& state) {
  const BenchArray* array = nullptr;
  const std::vector<CameraQuery>* queries = nullptr;
  if (!prepare(state, array, queries, false)) return;
  const collision::SphereTreeBvh* bvh =
      shared().sphereTreeBvh(static_cast<uint32_t>(state.range(0)));
  int64_t sphereTests = 0, triangleTests = 0;
  runQueries(state, *queries, [&](const CameraQuery& camera) {
    const collision::SphereTreeResult result =
        bvh->intersect(camera.ecefMeters, collision::kCameraSphereRadiusMeters);
    sphereTests += result.sphereTests;
    triangleTests += result.triangleTests;
    return result.collided;
  });
  const double tiles = static_cast<double>(shared().trees->tileCount());
  state.counters["Nv"] =
      benchmark::Counter(static_cast<double>(sphereTests), benchmark::Counter::kAvgIterations);
  state.counters["Np"] =
      benchmark::Counter(static_cast<double>(triangleTests), benchmark::Counter::kAvgIterations);
  state.counters["build_ns_per_tile"] =
      (shared().treeBuildSeconds + shared().bvhBuildSeconds) * 1e9 / tiles;
  state.counters["bytes_per_tile"] =
      static_cast<double>(shared().trees->memoryBytes() + bvh->memoryBytes()) / tiles;
}

void BM_QotcdLinear(benchmark::State& state) {
  const BenchArray* array = nullptr;
  const std::vector<CameraQuery>* queries = nullptr;
  if (!prepare(state, array, queries, false)) return;
  const geo::Ellipsoid ellipsoid = shared().pyramid->ellipsoid();
  runQueries(state, *queries, [&](const CameraQuery& camera) {
    return collision::qotcdLinear(array->array, ellipsoid, camera.ecefMeters, kClearanceMeters)
        .collided;
  });
}

void BM_QotcdIndexed(benchmark::State& state) {
  const BenchArray* array = nullptr;
  const std::vector<CameraQuery>* queries = nullptr;
  if (!prepare(state, array, queries, false)) return;
  const geo::Ellipsoid ellipsoid = shared().pyramid->ellipsoid();
  runQueries(state, *queries, [&](const CameraQuery& camera) {
    return collision::qotcdIndexed(array->array, ellipsoid, camera.ecefMeters, kClearanceMeters)
        .collided;
  });
}

// The floor any vertical test pays, as plain as it can be written: the same geodetic
// conversion, the tile at the array's one level (positionToTile) and one hash probe (find), the
// quad's four heights, one compare with their highest. No edge rules, no other levels, no
// no-data or sea handling: QOTCD indexed divided by this is what its own bookkeeping costs.
void BM_FloorKernel(benchmark::State& state) {
  const BenchArray* array = nullptr;
  const std::vector<CameraQuery>* queries = nullptr;
  if (!prepare(state, array, queries, false)) return;
  const geo::Ellipsoid ellipsoid = shared().pyramid->ellipsoid();
  const uint32_t level = array->array.levelsFinestFirst().front();
  runQueries(state, *queries, [&](const CameraQuery& camera) {
    const auto at = geo::ecefToCartographic(ellipsoid, camera.ecefMeters);
    if (!at) return false;
    const auto id = geo::GeographicTilingScheme::positionToTile(at->longitudeRadians,
                                                                at->latitudeRadians, level);
    if (!id) return false;
    const terrain::ArrayTile* tile = array->array.find(*id);
    if (tile == nullptr) return false;
    const terrain::HeightBlock& block = *tile->block;
    const uint32_t cells = block.verticesPerSide - 1;
    const double u = (at->longitudeRadians - tile->westRadians) /
                     (tile->eastRadians - tile->westRadians) * cells;
    const double v = (tile->northRadians - at->latitudeRadians) /
                     (tile->northRadians - tile->southRadians) * cells;
    const auto column = std::min(static_cast<uint32_t>(u), cells - 1);
    const auto row = std::min(static_cast<uint32_t>(v), cells - 1);
    const int16_t* h = &block.heights[size_t{row} * block.verticesPerSide + column];
    const int16_t highest = std::max(
        std::max(h[0], h[1]), std::max(h[block.verticesPerSide], h[block.verticesPerSide + 1]));
    return at->heightMeters <= highest + kClearanceMeters;
  });
}

void BM_ExactSurface(benchmark::State& state) {
  const BenchArray* array = nullptr;
  const std::vector<CameraQuery>* queries = nullptr;
  if (!prepare(state, array, queries, false)) return;
  const geo::Ellipsoid ellipsoid = shared().pyramid->ellipsoid();
  runQueries(state, *queries, [&](const CameraQuery& camera) {
    return collision::exactSurfaceTest(array->array, ellipsoid, camera.ecefMeters, kClearanceMeters)
        .collided;
  });
}

void BM_QotcdIndexedRandom(benchmark::State& state) {
  const BenchArray* array = nullptr;
  const std::vector<CameraQuery>* queries = nullptr;
  if (!prepare(state, array, queries, true)) return;
  const geo::Ellipsoid ellipsoid = shared().pyramid->ellipsoid();
  runQueries(state, *queries, [&](const CameraQuery& camera) {
    return collision::qotcdIndexed(array->array, ellipsoid, camera.ecefMeters, kClearanceMeters)
        .collided;
  });
}

// Diagnostics: QOTCD and the exact surface split into the camera's conversion to geodetic
// coordinates (geo::ecefToCartographic on WGS84) and the rest; the conversion on the paper's
// sphere, and on WGS84 with sqrt in place of hypot.
void BM_EcefToCartographic(benchmark::State& state) {
  const BenchArray* array = nullptr;
  const std::vector<CameraQuery>* queries = nullptr;
  if (!prepare(state, array, queries, false)) return;
  const geo::Ellipsoid ellipsoid = shared().pyramid->ellipsoid();
  runQueries(state, *queries, [&](const CameraQuery& camera) {
    const auto geodetic = geo::ecefToCartographic(ellipsoid, camera.ecefMeters);
    return geodetic && geodetic->heightMeters <= kClearanceMeters;
  });
}

void BM_EcefToCartographicSphere(benchmark::State& state) {
  const BenchArray* array = nullptr;
  const std::vector<CameraQuery>* queries = nullptr;
  if (!prepare(state, array, queries, false)) return;
  const geo::Ellipsoid sphere = geo::Ellipsoid::sphere();
  runQueries(state, *queries, [&](const CameraQuery& camera) {
    const auto geodetic = geo::ecefToCartographic(sphere, camera.ecefMeters);
    return geodetic && geodetic->heightMeters <= kClearanceMeters;
  });
}

void BM_QotcdIndexedGeodetic(benchmark::State& state) {
  const BenchArray* array = nullptr;
  const std::vector<CameraQuery>* queries = nullptr;
  if (!prepare(state, array, queries, false)) return;
  runQueries(state, *queries, [&](const CameraQuery& camera) {
    const geo::Cartographic geodetic{camera.longitudeRadians, camera.latitudeRadians,
                                     camera.heightMeters};
    return collision::qotcdIndexed(array->array, geodetic, kClearanceMeters).collided;
  });
}

// QOTCD indexed on the paper's spherical globe: the same array and camera longitudes,
// latitudes and heights, the camera's ECEF position and its conversion on a sphere.
void BM_QotcdIndexedOnSphere(benchmark::State& state) {
  const BenchArray* array = nullptr;
  const std::vector<CameraQuery>* queries = nullptr;
  if (!prepare(state, array, queries, false)) return;
  queries = shared().sphereFlightPath();
  const geo::Ellipsoid sphere = geo::Ellipsoid::sphere();
  runQueries(state, *queries, [&](const CameraQuery& camera) {
    return collision::qotcdIndexed(array->array, sphere, camera.ecefMeters, kClearanceMeters)
        .collided;
  });
}

void BM_ExactSurfaceGeodetic(benchmark::State& state) {
  const BenchArray* array = nullptr;
  const std::vector<CameraQuery>* queries = nullptr;
  if (!prepare(state, array, queries, false)) return;
  const geo::Ellipsoid ellipsoid = shared().pyramid->ellipsoid();
  runQueries(state, *queries, [&](const CameraQuery& camera) {
    const auto surface = collision::exactSurfaceHeight(
        array->array, ellipsoid, camera.longitudeRadians, camera.latitudeRadians);
    return camera.heightMeters <= (surface ? surface->heightMeters : 0.0) + kClearanceMeters;
  });
}

// The lateral clearance (collision/lateral_clearance.hpp) as the controller runs it each frame:
// the flight path's eyes brought down to 0.5 m above the drawn surface (every query has
// triangles within the ball: the worst case), radius 0.75 m (a 0.5 m near plane, 45 deg, 16:9,
// + 0.1 m). Compare with BM_ExactSurfaceGeodetic, the vertical test of the same frame.
void BM_LateralClearance(benchmark::State& state) {
  const BenchArray* array = nullptr;
  const std::vector<CameraQuery>* queries = nullptr;
  if (!prepare(state, array, queries, false)) return;
  const geo::Ellipsoid ellipsoid = shared().pyramid->ellipsoid();
  std::vector<CameraQuery> low = *queries;
  for (CameraQuery& camera : low) {
    camera.heightMeters -= camera.aboveSurfaceMeters - 0.5;
    camera.ecefMeters = geo::cartographicToEcef(
        ellipsoid, {camera.longitudeRadians, camera.latitudeRadians, camera.heightMeters});
  }
  runQueries(state, low, [&](const CameraQuery& camera) {
    return collision::nearestDrawnTriangle(array->array, ellipsoid, camera.ecefMeters, 0.75)
        .has_value();
  });
}

// One frame of the camera controller as globe play runs it: the eye proposed at the next point
// of the 60 Hz flight path (a Linear move, 50 m/s), QOTCD, the swept response, the near plane
// and the lateral ball, with or without the glide (camera/terrain_glide.hpp: 25 readings of the
// ground over the next 3 s along the velocity, and the spring). Their ratio is the glide's cost.
void controllerFrames(benchmark::State& state, bool glide) {
  const BenchArray* array = nullptr;
  const std::vector<CameraQuery>* queries = nullptr;
  if (!prepare(state, array, queries, false)) return;
  const geo::Ellipsoid ellipsoid = shared().pyramid->ellipsoid();
  camera::ControllerSettings settings;
  settings.glide.enabled = glide;
  auto poseOf = [](const CameraQuery& q) {
    return camera::CameraPose{
        {q.longitudeRadians, q.latitudeRadians, q.heightMeters}, 0.0, -0.2, 0.0};
  };
  camera::CameraController controller(poseOf(queries->front()), settings);
  size_t next = 1;
  runQueries(state, *queries, [&](const CameraQuery&) {
    const CameraQuery& to = (*queries)[next];
    next = next + 1 < queries->size() ? next + 1 : 0;
    controller.propose(poseOf(to),
                       next == 0 ? camera::MotionKind::Jump : camera::MotionKind::Linear);
    return controller.update(1.0 / 60, array->array, ellipsoid).collided;
  });
}
void BM_ControllerFrame(benchmark::State& state) { controllerFrames(state, false); }
void BM_ControllerFrameGlide(benchmark::State& state) { controllerFrames(state, true); }

double minimum(const std::vector<double>& values) {
  return values.empty() ? 0.0 : *std::min_element(values.begin(), values.end());
}
double maximum(const std::vector<double>& values) {
  return values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
}

// Per-size registration with min and max over the repetitions besides the default statistics.
void registerSizes(const char* name, void (*function)(benchmark::State&),
                   const std::vector<int64_t>& sizes) {
  benchmark::internal::Benchmark* bench = benchmark::RegisterBenchmark(name, function);
  for (const int64_t tiles : sizes) bench->Arg(tiles);
  bench->Unit(benchmark::kNanosecond);
  bench->ComputeStatistics("min", &minimum);
  bench->ComputeStatistics("max", &maximum);
}

}  // namespace

void registerTimingBenchmarks(const std::filesystem::path& pyramidDirectory) {
  shared().pyramidDirectory = pyramidDirectory;
  registerSizes("BM_SphereTree", &BM_SphereTree, kTileCounts);
  registerSizes("BM_SphereTreeBvh", &BM_SphereTreeBvh, kTileCounts);
  registerSizes("BM_QotcdLinear", &BM_QotcdLinear, kTileCounts);
  registerSizes("BM_QotcdIndexed", &BM_QotcdIndexed, kTileCounts);
  registerSizes("BM_FloorKernel", &BM_FloorKernel, kTileCounts);
  registerSizes("BM_ExactSurface", &BM_ExactSurface, kTileCounts);
  registerSizes("BM_QotcdIndexedRandom", &BM_QotcdIndexedRandom, kTileCounts);
  // Diagnostics (the conversion does not depend on the array: one size).
  registerSizes("BM_EcefToCartographic", &BM_EcefToCartographic, {10});
  registerSizes("BM_EcefToCartographicSphere", &BM_EcefToCartographicSphere, {10});
  registerSizes("BM_QotcdIndexedGeodetic", &BM_QotcdIndexedGeodetic, kTileCounts);
  registerSizes("BM_ExactSurfaceGeodetic", &BM_ExactSurfaceGeodetic, kTileCounts);
  registerSizes("BM_LateralClearance", &BM_LateralClearance, kTileCounts);
  registerSizes("BM_ControllerFrame", &BM_ControllerFrame, kTileCounts);
  registerSizes("BM_ControllerFrameGlide", &BM_ControllerFrameGlide, kTileCounts);
  registerSizes("BM_QotcdIndexedOnSphere", &BM_QotcdIndexedOnSphere, kTileCounts);
}

}  // namespace globe::bench
