#include "mask_tiling/land_polygons.hpp"

#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace globe::mask_tiling {
namespace {

struct DatasetCloser {
  void operator()(GDALDataset* dataset) const { GDALClose(dataset); }
};

std::string crsName(const OGRSpatialReference& srs) {
  const char* authority = srs.GetAuthorityName(nullptr);
  const char* code = srs.GetAuthorityCode(nullptr);
  if (authority != nullptr && code != nullptr) return std::string(authority) + ":" + code;
  char* wkt = nullptr;
  srs.exportToWkt(&wkt);
  std::string text = wkt != nullptr ? wkt : "";
  CPLFree(wkt);
  return text.substr(0, 60);
}

// Appends the rings of a polygon (curves linearised), of a multi-polygon or of a collection's
// polygons; false for a geometry with no area (points, lines).
bool appendRings(const OGRGeometry& geometry, std::vector<Ring>& rings) {
  const OGRwkbGeometryType type = wkbFlatten(geometry.getGeometryType());
  if (type == wkbPolygon || type == wkbCurvePolygon || type == wkbTriangle) {
    std::unique_ptr<OGRGeometry> linear;
    const OGRGeometry* surface = &geometry;
    if (type == wkbCurvePolygon) {
      linear.reset(geometry.getLinearGeometry());
      surface = linear.get();
    }
    const auto* polygon = dynamic_cast<const OGRPolygon*>(surface);
    if (polygon == nullptr) return false;
    for (const OGRLinearRing* ring : *polygon) {
      Ring out;
      out.reserve(static_cast<size_t>(ring->getNumPoints()));
      for (int i = 0; i < ring->getNumPoints(); ++i) out.emplace_back(ring->getX(i), ring->getY(i));
      if (out.size() >= 2 && out.front() == out.back()) out.pop_back();
      if (out.size() >= 3) rings.push_back(std::move(out));
    }
    return true;
  }
  if (const auto* collection = dynamic_cast<const OGRGeometryCollection*>(&geometry)) {
    bool any = false;
    for (const OGRGeometry* part : *collection) any = appendRings(*part, rings) || any;
    return any;
  }
  return false;
}

double medianEdge(const std::vector<Ring>& rings) {
  std::vector<double> lengths;
  for (const Ring& ring : rings) {
    for (size_t i = 0; i < ring.size(); ++i) {
      const glm::dvec2 a = ring[i], b = ring[(i + 1) % ring.size()];
      const double cosine = std::cos((a.y + b.y) / 2 * M_PI / 180);
      const double length = std::hypot((b.x - a.x) * cosine, b.y - a.y);
      if (length > 0) lengths.push_back(length);
    }
  }
  if (lengths.empty()) return 0;
  std::nth_element(lengths.begin(), lengths.begin() + static_cast<long>(lengths.size() / 2),
                   lengths.end());
  return lengths[lengths.size() / 2];
}

}  // namespace

Result<std::vector<LandPolygonLayer>> readLandPolygons(const std::string& path) {
  GDALAllRegister();
  std::unique_ptr<GDALDataset, DatasetCloser> dataset(GDALDataset::FromHandle(
      GDALOpenEx(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
  if (!dataset) {
    const std::string why = CPLGetLastErrorMsg();
    return makeError(path + ": not a vector file OGR can open" + (why.empty() ? "" : ": " + why));
  }
  OGRSpatialReference longitudeLatitude;
  longitudeLatitude.importFromEPSG(4326);
  longitudeLatitude.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::vector<LandPolygonLayer> layers;
  for (OGRLayer* layer : dataset->GetLayers()) {
    LandPolygonLayer out;
    out.path = path;
    out.name = layer->GetName();
    out.driver = dataset->GetDriver() != nullptr ? dataset->GetDriver()->GetDescription() : "";
    const OGRSpatialReference* srs = layer->GetSpatialRef();
    std::unique_ptr<OGRCoordinateTransformation> toLongitudeLatitude;
    if (srs != nullptr) {
      out.crs = crsName(*srs);
      OGRSpatialReference source(*srs);
      source.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
      if (!source.IsSame(&longitudeLatitude)) {
        toLongitudeLatitude.reset(OGRCreateCoordinateTransformation(&source, &longitudeLatitude));
        if (!toLongitudeLatitude) {
          return makeError(path + ": layer " + out.name + ": no transformation from " + out.crs +
                           " to longitude/latitude");
        }
      }
    } else {
      out.crs = "EPSG:4326 (assumed: the layer names no CRS)";
    }
    layer->ResetReading();
    for (auto& feature : *layer) {
      OGRGeometry* geometry = feature->GetGeometryRef();
      if (geometry == nullptr) continue;
      if (toLongitudeLatitude && geometry->transform(toLongitudeLatitude.get()) != OGRERR_NONE) {
        return makeError(path + ": layer " + out.name + ": feature " +
                         std::to_string(feature->GetFID()) +
                         " does not transform to longitude/latitude");
      }
      const size_t before = out.rings.size();
      appendRings(*geometry, out.rings);
      for (size_t r = before; r < out.rings.size(); ++r) {
        for (const glm::dvec2& p : out.rings[r]) {
          if (!std::isfinite(p.x) || !std::isfinite(p.y) || std::abs(p.x) > 180.0 + 1e-9 ||
              std::abs(p.y) > 90.0 + 1e-9) {
            return makeError(path + ": layer " + out.name + ": feature " +
                             std::to_string(feature->GetFID()) +
                             " has a vertex outside longitude -180..180, latitude -90..90");
          }
        }
        out.vertices += out.rings[r].size();
      }
    }
    if (out.rings.empty()) continue;  // no polygons: not land
    out.extent = boundsOf(out.rings.front());
    for (const Ring& ring : out.rings) {
      const RectangleDegrees b = boundsOf(ring);
      out.extent = {std::min(out.extent.west, b.west), std::min(out.extent.south, b.south),
                    std::max(out.extent.east, b.east), std::max(out.extent.north, b.north)};
    }
    out.medianEdgeDegrees = medianEdge(out.rings);
    layers.push_back(std::move(out));
  }
  if (layers.empty()) {
    return makeError(path +
                     ": holds no polygons (land polygons expected: areas of land, lakes "
                     "as their holes)");
  }
  return layers;
}

}  // namespace globe::mask_tiling
