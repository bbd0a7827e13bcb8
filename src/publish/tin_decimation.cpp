#include "publish/tin_decimation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace globe::publish::tin {
namespace {

// Half-edge collapses of the inserted vertices (never the border's) onto a neighbour, each kept
// only where every new triangle stays counter-clockwise and every sample it covers within the
// error; repeated while a pass removes any.
class Decimation {
 public:
  Decimation(const Grid& grid, double maxErrorMeters, std::vector<GridPoint> points,
             const std::vector<int>& triangles, int fixedVertices)
      : grid_(grid),
        maxErrorMeters_(maxErrorMeters),
        points_(std::move(points)),
        fixedVertices_(fixedVertices),
        incident_(points_.size()) {
    for (size_t i = 0; i < triangles.size(); i += 3) {
      addTriangle({triangles[i], triangles[i + 1], triangles[i + 2]});
    }
  }

  void run() {
    // A vertex is tried again only when a collapse changed its star since its last try.
    dirty_.assign(points_.size(), true);
    for (int pass = 0; pass < 8; ++pass) {
      bool removedAny = false;
      for (int v = static_cast<int>(points_.size()) - 1; v >= fixedVertices_; --v) {
        if (!dirty_[static_cast<size_t>(v)]) continue;
        dirty_[static_cast<size_t>(v)] = false;
        removedAny = tryRemove(v) || removedAny;
      }
      if (!removedAny) break;
    }
  }

  GridTin result() const {
    GridTin tin;
    std::vector<int> index(points_.size(), -1);
    for (size_t t = 0; t < vertexTriangles.size(); ++t) {
      if (!alive_[t]) continue;
      for (int v : vertexTriangles[t]) {
        auto& i = index[static_cast<size_t>(v)];
        if (i < 0) {
          i = static_cast<int>(tin.samples.size());
          tin.samples.push_back(grid_.sampleOf(points_[static_cast<size_t>(v)]));
        }
        tin.triangles.push_back(static_cast<uint32_t>(i));
      }
    }
    return tin;
  }

 private:
  using Triangle = std::array<int, 3>;

  void addTriangle(const Triangle& t) {
    const int index = static_cast<int>(vertexTriangles.size());
    vertexTriangles.push_back(t);
    alive_.push_back(true);
    for (int v : t) incident_[static_cast<size_t>(v)].push_back(index);
  }

  const Position& positionOf(int v) const {
    const GridPoint p = points_[static_cast<size_t>(v)];
    return grid_.positionAt(p.x, p.y);
  }

  bool tryRemove(int v) {
    std::vector<int> star;
    for (int t : incident_[static_cast<size_t>(v)]) {
      if (alive_[static_cast<size_t>(t)]) star.push_back(t);
    }
    std::vector<int> neighbours;
    for (int t : star) {
      for (int w : vertexTriangles[static_cast<size_t>(t)]) {
        if (w != v && std::find(neighbours.begin(), neighbours.end(), w) == neighbours.end()) {
          neighbours.push_back(w);
        }
      }
    }
    double bestError = INFINITY;
    int best = -1;
    for (int u : neighbours) {
      const double error = collapseError(star, v, u, bestError);
      if (error < bestError) {
        bestError = error;
        best = u;
      }
    }
    if (best < 0 || bestError > maxErrorMeters_) return false;
    for (int t : star) {
      alive_[static_cast<size_t>(t)] = false;
      Triangle moved = vertexTriangles[static_cast<size_t>(t)];
      if (std::find(moved.begin(), moved.end(), best) != moved.end()) continue;
      std::replace(moved.begin(), moved.end(), v, best);
      addTriangle(moved);
      for (int w : moved) dirty_[static_cast<size_t>(w)] = true;
    }
    return true;
  }

  // The largest error of the star's triangles with v moved onto u; INFINITY where one would fold
  // over. Stops once above `enough` (a better neighbour is already known).
  double collapseError(const std::vector<int>& star, int v, int u, double enough) const {
    double worst = 0;
    for (int t : star) {
      Triangle moved = vertexTriangles[static_cast<size_t>(t)];
      if (std::find(moved.begin(), moved.end(), u) != moved.end()) continue;
      std::replace(moved.begin(), moved.end(), v, u);
      const std::array<GridPoint, 3> corners{points_[static_cast<size_t>(moved[0])],
                                             points_[static_cast<size_t>(moved[1])],
                                             points_[static_cast<size_t>(moved[2])]};
      if (orient(corners[0], corners[1], corners[2]) <= 0) return INFINITY;
      const WorstSample sample = worstSampleIn(
          grid_, corners, {positionOf(moved[0]), positionOf(moved[1]), positionOf(moved[2])}, true);
      worst = std::max(worst, sample.errorMeters);
      if (worst > maxErrorMeters_ || worst >= enough) return INFINITY;
    }
    return worst;
  }

  const Grid& grid_;
  double maxErrorMeters_;
  std::vector<GridPoint> points_;
  int fixedVertices_;
  std::vector<Triangle> vertexTriangles;
  std::vector<bool> alive_;
  std::vector<std::vector<int>> incident_;
  std::vector<bool> dirty_;
};

}  // namespace

GridTin decimate(const Grid& grid, double maxErrorMeters, const Insertion& inserted) {
  Decimation decimation(grid, maxErrorMeters, inserted.points, inserted.triangles,
                        inserted.fixedVertices);
  decimation.run();
  return decimation.result();
}

}  // namespace globe::publish::tin
