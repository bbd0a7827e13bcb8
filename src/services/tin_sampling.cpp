#include "services/tin_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace globe::services {
namespace {

constexpr int kN = static_cast<int>(kServiceVerticesPerSide);
constexpr int kW = terrain::kApronWidth;

size_t at(int row, int column) {
  return static_cast<size_t>((row + kW) * static_cast<int>(ServiceSamples::side()) + column + kW);
}

// The grid's coordinates in quantized units: column j at u = j/(N-1) of 32767, row i (from the
// north) at v = (N-1-i)/(N-1) of it.
double gridU(int column) { return column * double{formats::kQuantizedMax} / (kN - 1); }
double gridV(int row) { return (kN - 1 - row) * double{formats::kQuantizedMax} / (kN - 1); }

bool waterAt(const std::vector<uint8_t>& mask, double u, double v) {
  if (mask.empty()) return false;
  if (mask.size() == 1) return mask[0] >= 128;
  const int column = std::clamp(static_cast<int>(u / formats::kQuantizedMax * 255 + 0.5), 0, 255);
  const int row = std::clamp(
      static_cast<int>((formats::kQuantizedMax - v) / formats::kQuantizedMax * 255 + 0.5), 0, 255);
  return mask[static_cast<size_t>(row) * 256 + column] >= 128;
}

}  // namespace

void mirrorApron(ServiceSamples& s) {
  auto mirror = [&](int inside, int edge, int outside, bool rows, int other) {
    const size_t o = rows ? at(outside, other) : at(other, outside);
    const size_t e = rows ? at(edge, other) : at(other, edge);
    const size_t i = rows ? at(inside, other) : at(other, inside);
    s.heightMeters[o] = 2 * s.heightMeters[e] - s.heightMeters[i];
    if (!s.water.empty()) s.water[o] = s.water[e];
  };
  // Rows first over the block's columns, then columns over every row (corners included).
  for (int k = 1; k <= kW; ++k) {
    for (int column = 0; column < kN; ++column) {
      mirror(k, 0, -k, true, column);
      mirror(kN - 1 - k, kN - 1, kN - 1 + k, true, column);
    }
  }
  for (int k = 1; k <= kW; ++k) {
    for (int row = -kW; row < kN + kW; ++row) {
      mirror(k, 0, -k, false, row);
      mirror(kN - 1 - k, kN - 1, kN - 1 + k, false, row);
    }
  }
}

ServiceSamples sampleTin(const formats::QuantizedMesh& mesh) {
  ServiceSamples s;
  s.heightMeters.assign(ServiceSamples::count(), std::numeric_limits<double>::quiet_NaN());
  if (!mesh.waterMask.empty()) s.water.assign(ServiceSamples::count(), 0);
  const bool normals = mesh.normals.size() == mesh.vertexCount();
  if (normals) s.normals.assign(size_t{kServiceVerticesPerSide} * kServiceVerticesPerSide, {});
  const double step = double{formats::kQuantizedMax} / (kN - 1);
  const double epsilon = 1e-9;
  for (size_t t = 0; t + 2 < mesh.triangles.size(); t += 3) {
    const uint32_t a = mesh.triangles[t], b = mesh.triangles[t + 1], c = mesh.triangles[t + 2];
    const double ua = mesh.u[a], va = mesh.v[a], ub = mesh.u[b], vb = mesh.v[b];
    const double uc = mesh.u[c], vc = mesh.v[c];
    const double area = (ub - ua) * (vc - va) - (uc - ua) * (vb - va);
    if (area == 0) continue;  // degenerate
    const int firstColumn = static_cast<int>(std::ceil(std::min({ua, ub, uc}) / step - 1e-9));
    const int lastColumn = static_cast<int>(std::floor(std::max({ua, ub, uc}) / step + 1e-9));
    const int firstRow =
        kN - 1 - static_cast<int>(std::floor(std::max({va, vb, vc}) / step + 1e-9));
    const int lastRow = kN - 1 - static_cast<int>(std::ceil(std::min({va, vb, vc}) / step - 1e-9));
    for (int row = std::max(firstRow, 0); row <= std::min(lastRow, kN - 1); ++row) {
      for (int column = std::max(firstColumn, 0); column <= std::min(lastColumn, kN - 1);
           ++column) {
        const size_t k = at(row, column);
        if (!std::isnan(s.heightMeters[k])) continue;  // on a shared edge: the first triangle's
        const double u = gridU(column), v = gridV(row);
        const double wa = ((ub - u) * (vc - v) - (uc - u) * (vb - v)) / area;
        const double wb = ((uc - u) * (va - v) - (ua - u) * (vc - v)) / area;
        const double wc = 1 - wa - wb;
        if (wa < -epsilon || wb < -epsilon || wc < -epsilon) continue;
        s.heightMeters[k] =
            wa * mesh.heightMeters[a] + wb * mesh.heightMeters[b] + wc * mesh.heightMeters[c];
        if (!s.water.empty()) s.water[k] = waterAt(mesh.waterMask, u, v) ? 1 : 0;
        if (normals) {
          const auto& na = mesh.normals[a];
          const auto& nb = mesh.normals[b];
          const auto& nc = mesh.normals[c];
          const glm::vec3 mixed(static_cast<float>(wa * na[0] + wb * nb[0] + wc * nc[0]),
                                static_cast<float>(wa * na[1] + wb * nb[1] + wc * nc[1]),
                                static_cast<float>(wa * na[2] + wb * nb[2] + wc * nc[2]));
          const float length = glm::length(mixed);
          s.normals[static_cast<size_t>(row) * kN + column] =
              length > 0 ? mixed / length : glm::vec3(0, 0, 1);
        }
      }
    }
  }
  // Points no triangle covers (a mesh with holes): the nearest vertex's height.
  for (int row = 0; row < kN; ++row) {
    for (int column = 0; column < kN; ++column) {
      const size_t k = at(row, column);
      if (!std::isnan(s.heightMeters[k])) continue;
      const double u = gridU(column), v = gridV(row);
      double best = std::numeric_limits<double>::infinity();
      size_t nearest = 0;
      for (size_t m = 0; m < mesh.vertexCount(); ++m) {
        const double d = (mesh.u[m] - u) * (mesh.u[m] - u) + (mesh.v[m] - v) * (mesh.v[m] - v);
        if (d < best) best = d, nearest = m;
      }
      s.heightMeters[k] = mesh.vertexCount() > 0 ? mesh.heightMeters[nearest] : 0.0;
      if (!s.water.empty()) s.water[k] = waterAt(mesh.waterMask, u, v) ? 1 : 0;
      if (normals) {
        const auto& n =
            mesh.normals.empty() ? std::array<float, 3>{0, 0, 1} : mesh.normals[nearest];
        s.normals[static_cast<size_t>(row) * kN + column] = glm::vec3(n[0], n[1], n[2]);
      }
    }
  }
  mirrorApron(s);
  return s;
}

ServiceSamples sampleHeightmap(const formats::HeightmapTile& tile) {
  ServiceSamples s;
  s.heightMeters.assign(ServiceSamples::count(), 0.0);
  if (!tile.waterMask.empty()) s.water.assign(ServiceSamples::count(), 0);
  for (int row = 0; row < kN; ++row) {
    for (int column = 0; column < kN; ++column) {
      s.heightMeters[at(row, column)] = tile.heightMeters[static_cast<size_t>(row) * kN + column];
      if (!s.water.empty()) {
        s.water[at(row, column)] = waterAt(tile.waterMask, gridU(column), gridV(row)) ? 1 : 0;
      }
    }
  }
  mirrorApron(s);
  return s;
}

}  // namespace globe::services
