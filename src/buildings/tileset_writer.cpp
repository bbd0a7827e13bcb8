#include "buildings/tileset_writer.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <vector>

namespace globe::buildings {
namespace {

constexpr double kEquatorialRadiusMeters = 6378137.0;

double radians(double degrees) { return degrees * std::numbers::pi / 180; }

CellBounds merged(const CellBounds& a, const CellBounds& b) {
  if (a.empty) return b;
  if (b.empty) return a;
  return {false,
          {std::min(a.extent.west, b.extent.west), std::min(a.extent.south, b.extent.south),
           std::max(a.extent.east, b.extent.east), std::max(a.extent.north, b.extent.north)},
          std::min(a.minHeightMeters, b.minHeightMeters),
          std::max(a.maxHeightMeters, b.maxHeightMeters)};
}

double cellWidthMeters(const QuadtreeCell& cell) {
  const ExtentDegrees& e = cell.extent;
  const double midLatitude = radians((e.south + e.north) / 2);
  const double east = radians(e.east - e.west) * kEquatorialRadiusMeters * std::cos(midLatitude);
  const double north = radians(e.north - e.south) * kEquatorialRadiusMeters;
  return std::max(east, north);
}

double geometricErrorMeters(const QuadtreeCell& cell) {
  return cell.children.empty() ? 0.0 : cellWidthMeters(cell) / 20;
}

nlohmann::json tileJson(std::span<const QuadtreeCell> cells, std::span<const CellBounds> subtree,
                        size_t at) {
  const QuadtreeCell& cell = cells[at];
  const CellBounds& b = subtree[at];
  nlohmann::json tile{{"boundingVolume",
                       {{"region",
                         {radians(b.extent.west), radians(b.extent.south), radians(b.extent.east),
                          radians(b.extent.north), b.minHeightMeters, b.maxHeightMeters}}}},
                      {"geometricError", geometricErrorMeters(cell)}};
  if (at == 0) tile["refine"] = "ADD";
  if (!cell.items.empty()) tile["content"] = {{"uri", contentUri(cell)}};
  if (!cell.children.empty()) {
    nlohmann::json children = nlohmann::json::array();
    for (const size_t child : cell.children) children.push_back(tileJson(cells, subtree, child));
    tile["children"] = std::move(children);
  }
  return tile;
}

}  // namespace

std::string contentUri(const QuadtreeCell& cell) {
  return "tiles/" + std::to_string(cell.level) + "/" + std::to_string(cell.x) + "/" +
         std::to_string(cell.y) + ".glb";
}

std::string tilesetJson(std::span<const QuadtreeCell> cells, std::span<const CellBounds> own) {
  // Children come after their parents: summed from the last cell back.
  std::vector<CellBounds> subtree(own.begin(), own.end());
  for (size_t i = cells.size(); i-- > 0;) {
    for (const size_t child : cells[i].children) subtree[i] = merged(subtree[i], subtree[child]);
  }
  nlohmann::json root = tileJson(cells, subtree, 0);
  const double error =
      std::max(2 * root["geometricError"].get<double>(), cellWidthMeters(cells[0]) / 10);
  const nlohmann::json tileset{
      {"asset", {{"version", "1.1"}, {"generator", "globe-tiler buildings"}}},
      {"geometricError", error},
      {"root", std::move(root)}};
  return tileset.dump(1) + "\n";
}

}  // namespace globe::buildings
