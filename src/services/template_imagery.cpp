#include "services/template_imagery.hpp"

#include <functional>

#include "services/tms_tilemap.hpp"
#include "services/url_reader.hpp"
#include "services/url_template.hpp"

namespace globe::services {
namespace {

constexpr size_t kMaxImageTileBytes = size_t{16} << 20;
constexpr size_t kMaxTileMapBytes = size_t{4} << 20;

class UrlImagery final : public ServiceImagery {
 public:
  UrlImagery(ImageryServiceDescription d, std::unique_ptr<UrlReader> reader,
             std::function<std::string(size_t, uint64_t, uint64_t)> urlOf)
      : ServiceImagery(std::move(d)), reader_(std::move(reader)), urlOf_(std::move(urlOf)) {}

 protected:
  Result<std::optional<std::vector<std::byte>>> fetchSourceTile(size_t matrix, uint64_t column,
                                                                uint64_t row) override {
    return reader_->read(urlOf_(matrix, column, row), kMaxImageTileBytes);
  }
  std::string sourceTileUrl(size_t matrix, uint64_t column, uint64_t row) const override {
    return urlOf_(matrix, column, row);
  }

 private:
  std::unique_ptr<UrlReader> reader_;
  std::function<std::string(size_t, uint64_t, uint64_t)> urlOf_;
};

Result<formats::BoundsDegrees> parseBounds(const std::string& text) {
  formats::BoundsDegrees b;
  if (std::sscanf(text.c_str(), "%lf,%lf,%lf,%lf", &b.west, &b.south, &b.east, &b.north) != 4 ||
      !(b.west < b.east && b.south < b.north && b.west >= -180 && b.east <= 180 && b.south >= -90 &&
        b.north <= 90)) {
    return makeError("bounds=" + text + ": expected WEST,SOUTH,EAST,NORTH in degrees");
  }
  return b;
}

}  // namespace

std::unique_ptr<ServiceImagery> makeUrlImagery(
    ImageryServiceDescription description, std::unique_ptr<UrlReader> reader,
    std::function<std::string(size_t, uint64_t, uint64_t)> urlOf) {
  return std::make_unique<UrlImagery>(std::move(description), std::move(reader), std::move(urlOf));
}

Result<std::unique_ptr<ServiceImagery>> openXyzImagery(
    const std::string& spec, std::shared_ptr<transport::Network> network) {
  std::string pattern = spec;
  auto options = takeQueryOptions(
      pattern, {"minzoom", "maxzoom", "subdomains", "tilesize", "crs", "bounds", "attribution"});
  auto problem = [&](const std::string& what) { return makeError("xyz:" + spec + ": " + what); };
  auto xyz = xyzTemplateOptions(pattern, options, 18);
  if (!xyz) return problem(xyz.error());
  const std::string crs = options.count("crs") ? options["crs"] : "EPSG:3857";
  if (crs != "EPSG:3857" && crs != "EPSG:4326") {
    return problem("crs=" + crs + ": EPSG:3857 (the default) or EPSG:4326");
  }
  ImageryServiceDescription d;
  d.location = "xyz:" + spec;
  d.driver = "XYZ";
  d.tiling = crs == "EPSG:4326" ? geographicQuad(xyz->minZoom, xyz->maxZoom, xyz->tileSize)
                                : webMercatorQuad(xyz->minZoom, xyz->maxZoom, xyz->tileSize);
  d.bounds = crs == "EPSG:4326" ? formats::BoundsDegrees{-180, -90, 180, 90}
                                : formats::BoundsDegrees{-180, -kWebMercatorMaxLatitudeDegrees, 180,
                                                         kWebMercatorMaxLatitudeDegrees};
  if (options.count("bounds")) {
    auto b = parseBounds(options["bounds"]);
    if (!b) return problem(b.error());
    d.bounds = *b;
  }
  d.attribution = options.count("attribution") ? options["attribution"] : "";
  const std::vector<std::string> subdomains = xyz->subdomains;
  auto reader = std::make_unique<UrlReader>(network, kImageAccept);
  d.remote = reader->remote(pattern);
  const uint32_t firstZoom = xyz->minZoom;
  return makeUrlImagery(std::move(d), std::move(reader),
                        [pattern, subdomains, firstZoom](size_t m, uint64_t x, uint64_t y) {
                          return expandTileUrl(pattern, {static_cast<uint32_t>(firstZoom + m),
                                                         static_cast<uint32_t>(x),
                                                         static_cast<uint32_t>(y), "", subdomains});
                        });
}

Result<std::unique_ptr<ServiceImagery>> openTmsImagery(
    const std::string& spec, std::shared_ptr<transport::Network> network) {
  std::string url = spec;
  auto options = takeQueryOptions(url, {"attribution"});
  std::string xmlUrl = url;
  const std::string path = url.substr(0, url.find('?'));
  if (path.size() < 4 || path.compare(path.size() - 4, 4, ".xml") != 0) {
    std::string folder = path;
    while (!folder.empty() && folder.back() == '/') folder.pop_back();
    xmlUrl = folder + "/tilemapresource.xml";
  }
  auto reader = std::make_unique<UrlReader>(network, kImageAccept);
  auto bytes = reader->read(xmlUrl, kMaxTileMapBytes);
  if (!bytes) return Error{bytes.error()};
  if (!*bytes) return makeError(xmlUrl + ": not found (a TMS tile map publishes it)");
  auto map = parseTmsTileMap(
      std::string_view(reinterpret_cast<const char*>((*bytes)->data()), (*bytes)->size()), xmlUrl);
  if (!map) return Error{map.error()};
  ImageryServiceDescription d;
  d.location = "tms:" + spec;
  d.attribution = options.count("attribution") ? options["attribution"] : "";
  d.driver = "TMS";
  d.tiling = map->tiling;
  d.bounds = map->bounds;
  d.remote = reader->remote(xmlUrl);
  std::vector<std::string> base;
  for (const std::string& href : map->hrefs) base.push_back(resolveUrl(xmlUrl, href));
  const TileMatrixSet tiling = map->tiling;
  const std::string extension = map->extension;
  return makeUrlImagery(std::move(d), std::move(reader),
                        [base, tiling, extension](size_t m, uint64_t x, uint64_t row) {
                          const uint64_t y = tiling.matrices[m].rows - 1 - row;  // from the bottom
                          return base[m] + "/" + std::to_string(x) + "/" + std::to_string(y) + "." +
                                 extension;
                        });
}

}  // namespace globe::services
