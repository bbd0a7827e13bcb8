#include "buildings/footprint_reader.hpp"

#include <cpl_error.h>
#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <cmath>
#include <memory>
#include <optional>

#include "buildings/building_height.hpp"

namespace globe::buildings {
namespace {

// GDAL prints its errors by default: a library stays quiet and returns them in its own.
struct QuietGdal {
  QuietGdal() { CPLPushErrorHandler(CPLQuietErrorHandler); }
  ~QuietGdal() { CPLPopErrorHandler(); }
  QuietGdal(const QuietGdal&) = delete;
  QuietGdal& operator=(const QuietGdal&) = delete;
};

struct DatasetCloser {
  void operator()(GDALDataset* dataset) const { GDALClose(dataset); }
};

void warn(FootprintSet& set, const FootprintLimits& limits, std::string text) {
  if (set.warnings.size() < limits.maxWarnings) {
    set.warnings.push_back(std::move(text));
  } else {
    ++set.warningsDropped;
  }
}

std::optional<std::string> field(OGRFeature& feature, const std::string& name) {
  if (name.empty()) return std::nullopt;
  const int index = feature.GetFieldIndex(name.c_str());
  if (index < 0 || !feature.IsFieldSetAndNotNull(index)) return std::nullopt;
  std::string text = feature.GetFieldAsString(index);
  if (text.empty()) return std::nullopt;
  return text;
}

// The polygons of a geometry (curves linearised; multi-polygons and collections in parts).
void collectPolygons(const OGRGeometry& geometry, std::vector<std::unique_ptr<OGRPolygon>>& out) {
  const OGRwkbGeometryType type = wkbFlatten(geometry.getGeometryType());
  if (type == wkbPolygon || type == wkbCurvePolygon || type == wkbTriangle) {
    std::unique_ptr<OGRGeometry> linear(geometry.getLinearGeometry());
    if (auto* polygon = dynamic_cast<OGRPolygon*>(linear.get())) {
      linear.release();
      out.emplace_back(polygon);
    }
    return;
  }
  if (const auto* collection = dynamic_cast<const OGRGeometryCollection*>(&geometry)) {
    for (const OGRGeometry* part : *collection) collectPolygons(*part, out);
  }
}

// The polygon's rings in degrees, or why it cannot be a footprint.
Result<std::vector<RingDegrees>> ringsOf(const OGRPolygon& polygon, const FootprintLimits& limits) {
  std::vector<RingDegrees> rings;
  for (const OGRLinearRing* ring : polygon) {
    if (static_cast<size_t>(ring->getNumPoints()) > limits.maxRingVertices) {
      return makeError("a ring of " + std::to_string(ring->getNumPoints()) + " vertices (at most " +
                       std::to_string(limits.maxRingVertices) + ")");
    }
    RingDegrees out;
    for (int i = 0; i < ring->getNumPoints(); ++i) {
      const double x = ring->getX(i), y = ring->getY(i);
      if (!std::isfinite(x) || !std::isfinite(y) || std::abs(x) > 180 || std::abs(y) > 90) {
        return makeError("a vertex that is not a longitude/latitude (" + std::to_string(x) + ", " +
                         std::to_string(y) + ")");
      }
      if (out.empty() || out.back() != glm::dvec2(x, y)) out.emplace_back(x, y);
    }
    if (out.size() >= 2 && out.front() == out.back()) out.pop_back();
    if (out.size() < 3) {
      if (rings.empty()) return makeError("an outer ring of fewer than 3 distinct vertices");
      continue;  // a degenerate hole: nothing to cut out
    }
    rings.push_back(std::move(out));
  }
  if (rings.empty()) return makeError("an empty polygon");
  Footprint probe{rings, 0, ""};
  const ExtentDegrees e = extentOf(probe);
  if (e.east - e.west > limits.maxExtentDegrees || e.north - e.south > limits.maxExtentDegrees) {
    return makeError("a footprint " + std::to_string(e.east - e.west) + "° × " +
                     std::to_string(e.north - e.south) + "° wide (at most " +
                     std::to_string(limits.maxExtentDegrees) + "°): not a building");
  }
  return rings;
}

struct LayerContext {
  const std::string& path;
  const FootprintOptions& options;
  FootprintSet& into;
  size_t vertices = 0;
  size_t polygonFeatures = 0;  // features with a polygon, read or not
};

// One feature's footprints; an error only where a limit for the whole input is passed.
Result<void> readFeature(OGRFeature& feature, const std::string& where, LayerContext& c) {
  const FootprintLimits& limits = c.options.limits;
  OGRGeometry* geometry = feature.GetGeometryRef();
  std::vector<std::unique_ptr<OGRPolygon>> polygons;
  if (geometry != nullptr) collectPolygons(*geometry, polygons);
  if (polygons.empty()) {
    ++c.into.refused;
    warn(c.into, limits, where + ": no polygon (a point, a line or no geometry): skipped");
    return {};
  }
  ++c.polygonFeatures;
  const BuildingHeight height =
      buildingHeight({field(feature, c.options.heightAttribute), field(feature, "height"),
                      field(feature, "building:levels")},
                     c.options.levelHeightMeters);
  if (!height.meters) {
    if (height.problem.empty()) {
      ++c.into.withoutHeight;
    } else {
      ++c.into.refused;
      warn(c.into, limits, where + ": " + height.problem + ": skipped");
    }
    return {};
  }
  for (const auto& polygon : polygons) {
    auto rings = ringsOf(*polygon, limits);
    if (!rings) {
      ++c.into.refused;
      warn(c.into, limits, where + ": " + rings.error() + ": skipped");
      continue;
    }
    for (const RingDegrees& ring : *rings) c.vertices += ring.size();
    if (c.into.footprints.size() >= limits.maxFootprints || c.vertices > limits.maxVertices) {
      return makeError(c.path + ": more than " + std::to_string(limits.maxFootprints) +
                       " footprints or " + std::to_string(limits.maxVertices) +
                       " vertices in all: split the input into regions and run once for each");
    }
    c.into.footprints.push_back({std::move(*rings), *height.meters, where});
  }
  return {};
}

}  // namespace

Result<void> readFootprints(const std::string& path, const FootprintOptions& options,
                            FootprintSet& into) {
  GDALAllRegister();
  QuietGdal quiet;
  std::unique_ptr<GDALDataset, DatasetCloser> dataset(GDALDataset::FromHandle(
      GDALOpenEx(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
  if (!dataset) {
    const std::string why = CPLGetLastErrorMsg();
    return makeError(path + ": not a vector file OGR can open" + (why.empty() ? "" : ": " + why));
  }
  OGRSpatialReference lonLat;
  lonLat.importFromEPSG(4326);
  lonLat.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  LayerContext context{path, options, into};
  for (const Footprint& f : into.footprints) {
    for (const RingDegrees& ring : f.rings) context.vertices += ring.size();
  }
  for (OGRLayer* layer : dataset->GetLayers()) {
    const std::string layerName = layer->GetName();
    const OGRwkbGeometryType type = wkbFlatten(layer->GetGeomType());
    if (type == wkbPoint || type == wkbLineString || type == wkbMultiPoint ||
        type == wkbMultiLineString || type == wkbNone) {
      warn(into, options.limits, path + ": layer " + layerName + " holds no polygons: skipped");
      continue;
    }
    std::unique_ptr<OGRCoordinateTransformation> toLonLat;
    if (const OGRSpatialReference* srs = layer->GetSpatialRef()) {
      OGRSpatialReference source(*srs);
      source.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
      if (!source.IsSame(&lonLat)) {
        toLonLat.reset(OGRCreateCoordinateTransformation(&source, &lonLat));
        if (!toLonLat) {
          return makeError(path + ": layer " + layerName +
                           ": its CRS does not transform to longitude/latitude");
        }
      }
    }
    layer->ResetReading();
    for (auto& feature : *layer) {
      const std::string where =
          path + ": layer " + layerName + ": feature " + std::to_string(feature->GetFID());
      OGRGeometry* geometry = feature->GetGeometryRef();
      if (geometry != nullptr && toLonLat && geometry->transform(toLonLat.get()) != OGRERR_NONE) {
        ++into.refused;
        warn(into, options.limits, where + ": does not transform to longitude/latitude: skipped");
        continue;
      }
      auto read = readFeature(*feature, where, context);
      if (!read) return read;
    }
  }
  if (context.polygonFeatures == 0) {
    return makeError(path + ": holds no polygon features (building footprints expected)");
  }
  return {};
}

}  // namespace globe::buildings
