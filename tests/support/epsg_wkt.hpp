// The WKT of an EPSG code, for tests that write georeferenced rasters with GDAL.
#pragma once

#include <cpl_conv.h>
#include <ogr_srs_api.h>

#include <string>

namespace globe::testing {

inline std::string wktOfEpsg(int epsg) {
  OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
  OSRImportFromEPSG(srs, epsg);
  char* wkt = nullptr;
  OSRExportToWkt(srs, &wkt);
  std::string out = wkt != nullptr ? wkt : "";
  CPLFree(wkt);
  OSRDestroySpatialReference(srs);
  return out;
}

}  // namespace globe::testing
