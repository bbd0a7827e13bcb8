// The accuracy mode's per-query records and their summary: time percentiles, height
// overestimates, false negatives and positives; printed as a table, written as CSV and JSON.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "collision/sphere_tree.hpp"

namespace globe::bench {

// The camera sphere's radius and QOTCD's and the exact test's clearance.
inline constexpr double kAccuracyRadiusMeters = collision::kCameraSphereRadiusMeters;

enum Method : size_t { kSphereTree, kQotcdLinear, kQotcdIndexed, kExactSurface, kMethodCount };
inline constexpr std::array<const char*, kMethodCount> kMethodNames = {
    "sphere_tree", "qotcd_linear", "qotcd_indexed", "exact_surface"};

struct AccuracyQuery {
  double longitude = 0, latitude = 0;  // radians
  double cameraHeight = 0;             // D
  double drawn = 0;                    // E: the exact drawn surface
  double source = 0;                   // B: the finest source data, bilinear
  glm::dvec3 ecef{0.0};
  std::array<double, kMethodCount> effectiveHeight{};  // collided iff D <= h + 50 m
  std::array<double, kMethodCount> nanoseconds{};
  std::array<bool, kMethodCount> collided{};
};

struct ErrorStats {
  double mean = 0, p99 = 0, max = 0, min = 0;
  uint64_t penetrations = 0;                // queries with D <= S
  uint64_t falseNegatives = 0;              // a penetration (D <= S) not reported
  uint64_t falseNegativesWithinRadius = 0;  // of those, with S - D <= 50 m
  uint64_t falsePositives = 0;              // reported with D > S + 50 m
};

struct AccuracyRow {
  std::string region;
  std::string method;
  size_t tiles = 0, queries = 0;
  double medianNs = 0, p99Ns = 0, maxNs = 0, meanNs = 0;
  ErrorStats drawn, source;
  double bytesPerTile = 0;
};
// One row: the method's times and errors over the queries (against (a) the drawn surface E,
// (b) the source B).
AccuracyRow summarise(const std::string& region, size_t method, size_t tiles,
                      const std::vector<const AccuracyQuery*>& queries, double bytesPerTile);
void printAccuracyTable(const std::vector<AccuracyRow>& rows);
// accuracy.csv and accuracy.json (the header's fields plus "rows").
void writeAccuracyFiles(const std::filesystem::path& directory,
                        const std::vector<AccuracyRow>& rows, const nlohmann::json& header);

}  // namespace globe::bench
