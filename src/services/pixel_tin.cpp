#include "services/pixel_tin.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <numeric>
#include <unordered_map>

namespace globe::services {
namespace {

// Lines closer than this (pixels) to a block edge are left out: no sliver triangles.
constexpr double kSliverPixels = 1e-6;
// At most k×k squares a pixel square is cut into.
constexpr uint32_t kMaxCuts = 64;

double latitudeOfRow(double row, double worldPixels) {
  return std::atan(std::sinh(std::numbers::pi * (1 - 2 * (row + 0.5) / worldPixels)));
}

// The vertex lines across one axis (pixel coordinates, ascending): the block's edges and the
// pixel centres' lines strictly between them.
std::vector<double> linesBetween(double first, double last) {
  std::vector<double> lines{first};
  for (double k = std::floor(first) + 1; k < last; ++k) {
    if (k - first > kSliverPixels && last - k > kSliverPixels) lines.push_back(k);
  }
  lines.push_back(last);
  return lines;
}

// The bilinear surface of pixel square (column, row)..(column + 1, row + 1).
struct Square {
  double h00, h10, h01, h11;  // h<dx><dy>, rows downward
  int64_t column, row;
  double at(double x, double y) const {
    const double tx = x - static_cast<double>(column), ty = y - static_cast<double>(row);
    return (1 - ty) * ((1 - tx) * h00 + tx * h10) + ty * ((1 - tx) * h01 + tx * h11);
  }
  double twist() const { return h00 + h11 - h10 - h01; }
};

Square squareAt(const PixelWindow& pixels, double x, double y) {
  const auto c = static_cast<int64_t>(std::floor(x)), r = static_cast<int64_t>(std::floor(y));
  return {pixels.at(c, r), pixels.at(c + 1, r), pixels.at(c, r + 1), pixels.at(c + 1, r + 1), c, r};
}

// The cuts per side a piece of a pixel square needs: two triangles over a square whose
// bilinear twist is t miss the surface by at most |t| / 4 (at its centre).
uint32_t cutsFor(double twistMeters, double widthPixels, double heightPixels,
                 double toleranceMeters) {
  const double cuts =
      std::sqrt(std::fabs(twistMeters) * widthPixels * heightPixels / (4 * toleranceMeters));
  return static_cast<uint32_t>(std::clamp(std::ceil(cuts), 1.0, double{kMaxCuts}));
}

// The cuts each piece needs, row by row; the tolerance widened until the vertices fit.
std::vector<uint32_t> cutsPerPiece(const PixelWindow& pixels, const std::vector<double>& xs,
                                   const std::vector<double>& ys, double toleranceMeters) {
  std::vector<uint32_t> cuts((xs.size() - 1) * (ys.size() - 1));
  for (;; toleranceMeters *= 2) {
    size_t needed = 0;
    for (size_t b = 0, k = 0; b + 1 < ys.size(); ++b) {
      for (size_t a = 0; a + 1 < xs.size(); ++a, ++k) {
        const Square s = squareAt(pixels, (xs[a] + xs[a + 1]) / 2, (ys[b] + ys[b + 1]) / 2);
        cuts[k] = cutsFor(s.twist(), xs[a + 1] - xs[a], ys[b + 1] - ys[b], toleranceMeters);
        needed += size_t{cuts[k] + 1} * (cuts[k] + 1);
      }
    }
    if (needed <= kMaxPixelTinVertices) return cuts;
  }
}

struct PointKey {
  uint64_t x, y;
  bool operator==(const PointKey&) const = default;
};
struct PointHash {
  size_t operator()(const PointKey& k) const { return std::hash<uint64_t>()(k.x * 31 + k.y); }
};

// Vertices by their pixel coordinates, each once.
class VertexSet {
 public:
  VertexSet(const geo::GlobeRectangle& block, const std::vector<double>& xs,
            const std::vector<double>& ys, double worldPixels)
      : block_(block), xs_(xs), ys_(ys), worldPixels_(worldPixels) {}

  uint32_t index(double x, double y, const Square& square) {
    const PointKey key{std::bit_cast<uint64_t>(x), std::bit_cast<uint64_t>(y)};
    auto [it, added] = indices_.try_emplace(key, static_cast<uint32_t>(vertices.size()));
    if (added) vertices.push_back({u(x), v(y), square.at(x, y)});
    return it->second;
  }
  std::vector<terrain::TinVertex> vertices;

 private:
  // The block's edges at exactly 0 and 1, as the mesh and collision expect them.
  double u(double x) const {
    if (x == xs_.front()) return 0;
    if (x == xs_.back()) return 1;
    return std::clamp((x - xs_.front()) / (xs_.back() - xs_.front()), 0.0, 1.0);
  }
  double v(double y) const {
    if (y == ys_.front()) return 1;
    if (y == ys_.back()) return 0;
    const double lat = latitudeOfRow(y, worldPixels_);
    return std::clamp((lat - block_.southRadians) / block_.heightRadians(), 0.0, 1.0);
  }

  geo::GlobeRectangle block_;
  const std::vector<double>& xs_;
  const std::vector<double>& ys_;
  double worldPixels_;
  std::unordered_map<PointKey, uint32_t, PointHash> indices_;
};

// Cut k of `cuts` between first and last, from the reduced fraction: a neighbour cutting the
// same side into another number of parts finds the positions they share bit for bit.
double cutAt(double first, double last, uint32_t k, uint32_t cuts) {
  if (k == 0) return first;
  if (k == cuts) return last;
  const uint32_t g = std::gcd(k, cuts);
  return first + (last - first) * (k / g) / (cuts / g);
}

// A piece side's cut positions: its own cuts and its neighbour's (0: none), merged.
std::vector<double> sideCuts(double first, double last, uint32_t own, uint32_t neighbour) {
  std::vector<double> at;
  for (const uint32_t cuts : {own, neighbour}) {
    for (uint32_t k = 0; cuts > 0 && k <= cuts; ++k) at.push_back(cutAt(first, last, k, cuts));
  }
  std::sort(at.begin(), at.end());
  at.erase(std::unique(at.begin(), at.end()), at.end());
  return at;
}

// One piece: [x0, x1] × [y0, y1] of a pixel square, its cuts, its neighbours' cuts across each
// side (0 at the block's edge) and the vertex positions along each side.
struct Piece {
  double x0, x1, y0, y1;
  uint32_t cuts;
  std::vector<double> north, south, west, east;
};

// The positions strictly between a and b (ascending) on a side, in the order from a to b.
void between(const std::vector<double>& side, double a, double b, std::vector<double>& out) {
  out.clear();
  for (const double t : side) {
    if (t > std::min(a, b) && t < std::max(a, b)) out.push_back(t);
  }
  if (a > b) std::reverse(out.begin(), out.end());
}

// A sub-square of a piece: two triangles, or where a neighbour cut the piece's side finer, a
// fan from its centre through every vertex on its sides (no T-junctions: no cracks),
// counter-clockwise seen from above (x east, y south).
void addSquare(double west, double east, double north, double south, const Piece& piece,
               const Square& square, VertexSet& vertices, std::vector<uint32_t>& triangles) {
  std::vector<uint32_t> ring;
  std::vector<double> inner;
  auto corner = [&](double x, double y) { ring.push_back(vertices.index(x, y, square)); };
  corner(west, south);
  if (south == piece.y1)
    between(piece.south, west, east, inner);
  else
    inner.clear();
  for (const double x : inner) corner(x, south);
  corner(east, south);
  if (east == piece.x1)
    between(piece.east, south, north, inner);
  else
    inner.clear();
  for (const double y : inner) corner(east, y);
  corner(east, north);
  if (north == piece.y0)
    between(piece.north, east, west, inner);
  else
    inner.clear();
  for (const double x : inner) corner(x, north);
  corner(west, north);
  if (west == piece.x0)
    between(piece.west, north, south, inner);
  else
    inner.clear();
  for (const double y : inner) corner(west, y);
  if (ring.size() == 4) {
    triangles.insert(triangles.end(), {ring[0], ring[1], ring[2], ring[0], ring[2], ring[3]});
    return;
  }
  const uint32_t centre = vertices.index((west + east) / 2, (north + south) / 2, square);
  for (size_t k = 0; k < ring.size(); ++k) {
    triangles.insert(triangles.end(), {centre, ring[k], ring[(k + 1) % ring.size()]});
  }
}

void addPiece(const Piece& piece, const Square& square, VertexSet& vertices,
              std::vector<uint32_t>& triangles) {
  for (uint32_t q = 0; q < piece.cuts; ++q) {
    const double north = cutAt(piece.y0, piece.y1, q, piece.cuts);
    const double south = cutAt(piece.y0, piece.y1, q + 1, piece.cuts);
    for (uint32_t p = 0; p < piece.cuts; ++p) {
      addSquare(cutAt(piece.x0, piece.x1, p, piece.cuts),
                cutAt(piece.x0, piece.x1, p + 1, piece.cuts), north, south, piece, square, vertices,
                triangles);
    }
  }
}

}  // namespace

double pixelColumnOf(double longitudeRadians, double worldPixels) {
  return (longitudeRadians / (2 * std::numbers::pi) + 0.5) * worldPixels - 0.5;
}

double pixelRowOf(double latitudeRadians, double worldPixels) {
  const double mercator = std::log(std::tan(std::numbers::pi / 4 + latitudeRadians / 2));
  return (0.5 - mercator / (2 * std::numbers::pi)) * worldPixels - 0.5;
}

PixelRange pixelRangeOf(const geo::GlobeRectangle& block, double worldPixels) {
  const auto floorOf = [](double p) { return static_cast<int64_t>(std::floor(p)); };
  return {floorOf(pixelColumnOf(block.westRadians, worldPixels)),
          floorOf(pixelColumnOf(block.eastRadians, worldPixels)) + 1,
          floorOf(pixelRowOf(block.northRadians, worldPixels)),
          floorOf(pixelRowOf(block.southRadians, worldPixels)) + 1};
}

Result<std::shared_ptr<const terrain::TinTile>> buildPixelTin(const geo::GlobeRectangle& block,
                                                              const PixelWindow& pixels,
                                                              double toleranceMeters,
                                                              const std::string& name) {
  const std::vector<double> xs = linesBetween(pixelColumnOf(block.westRadians, pixels.worldPixels),
                                              pixelColumnOf(block.eastRadians, pixels.worldPixels));
  const std::vector<double> ys = linesBetween(pixelRowOf(block.northRadians, pixels.worldPixels),
                                              pixelRowOf(block.southRadians, pixels.worldPixels));
  if (!std::all_of(pixels.heightMeters.begin(), pixels.heightMeters.end(),
                   [](double h) { return std::isfinite(h); })) {
    return makeError(name + ": a pixel without a height under a TIN block");
  }
  if ((xs.size() - 1) * (ys.size() - 1) * 4 > kMaxPixelTinVertices) {
    return makeError(name + ": too many pixels for one TIN block");
  }
  const std::vector<uint32_t> cuts = cutsPerPiece(pixels, xs, ys, toleranceMeters);
  VertexSet vertices(block, xs, ys, pixels.worldPixels);
  std::vector<uint32_t> triangles;
  const size_t across = xs.size() - 1, down = ys.size() - 1;
  auto cutsOf = [&](size_t a, size_t b) { return cuts[b * across + a]; };
  for (size_t b = 0; b < down; ++b) {
    for (size_t a = 0; a < across; ++a) {
      const uint32_t own = cutsOf(a, b);
      const Piece piece{xs[a],
                        xs[a + 1],
                        ys[b],
                        ys[b + 1],
                        own,
                        sideCuts(xs[a], xs[a + 1], own, b > 0 ? cutsOf(a, b - 1) : 0),
                        sideCuts(xs[a], xs[a + 1], own, b + 1 < down ? cutsOf(a, b + 1) : 0),
                        sideCuts(ys[b], ys[b + 1], own, a > 0 ? cutsOf(a - 1, b) : 0),
                        sideCuts(ys[b], ys[b + 1], own, a + 1 < across ? cutsOf(a + 1, b) : 0)};
      addPiece(piece, squareAt(pixels, (xs[a] + xs[a + 1]) / 2, (ys[b] + ys[b + 1]) / 2), vertices,
               triangles);
    }
  }
  auto tin =
      terrain::TinTile::build(block, std::move(vertices.vertices), std::move(triangles), name);
  if (!tin) return Error{tin.error()};
  return std::shared_ptr<const terrain::TinTile>(
      std::make_shared<terrain::TinTile>(std::move(*tin)));
}

}  // namespace globe::services
