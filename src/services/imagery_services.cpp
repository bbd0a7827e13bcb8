#include "services/imagery_services.hpp"

#include "services/pmtiles_imagery.hpp"
#include "services/template_imagery.hpp"
#include "services/wmts_imagery.hpp"
#include "streaming/imagery_store.hpp"

namespace globe::services {
namespace {

bool startsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

template <class T>
Result<std::unique_ptr<streaming::ImageryTiles>> widen(Result<std::unique_ptr<T>> opened) {
  if (!opened) return Error{opened.error()};
  return std::unique_ptr<streaming::ImageryTiles>(std::move(*opened));
}

}  // namespace

bool isImageryService(const std::string& spec) {
  return startsWith(spec, "xyz:") || startsWith(spec, "tms:") || startsWith(spec, "wmts:") ||
         startsWith(spec, "pmtiles:");
}

Result<std::unique_ptr<streaming::ImageryTiles>> openImageryTiles(
    const std::string& spec, std::shared_ptr<transport::Network> network) {
  if (startsWith(spec, "xyz:")) return widen(openXyzImagery(spec.substr(4), std::move(network)));
  if (startsWith(spec, "tms:")) return widen(openTmsImagery(spec.substr(4), std::move(network)));
  if (startsWith(spec, "wmts:")) return widen(openWmtsImagery(spec.substr(5), std::move(network)));
  if (startsWith(spec, "pmtiles:")) {
    return widen(openPmtilesImagery(spec.substr(8), std::move(network)));
  }
  return widen(streaming::ImageryStore::open(spec, std::move(network)));
}

}  // namespace globe::services
