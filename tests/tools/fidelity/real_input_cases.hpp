// Real inputs made awkward on purpose, from the DEMs in the repository, with GDAL's own
// utilities (the library calls behind gdal_translate and gdalwarp): a crop that puts a summit
// at an edge, a half blanked to no data, a DEM warped to UTM.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace globe::fidelity::testing {

// gdal_translate -projwin WEST NORTH EAST SOUTH: a GeoTIFF crop.
void cropRaster(const std::string& input, const std::filesystem::path& output, double west,
                double south, double east, double north);
// A GeoTIFF copy (int16, no data -32768) with every sample where blank(lon, lat) set to no data.
void blankRaster(const std::string& input, const std::filesystem::path& output,
                 const std::function<bool(double longitudeDegrees, double latitudeDegrees)>& blank);
// gdalwarp -t_srs CRS -tr METRES METRES -r bilinear: a GeoTIFF in a projected CRS.
void warpRaster(const std::string& input, const std::filesystem::path& output,
                const std::string& crs, double metres);

}  // namespace globe::fidelity::testing
