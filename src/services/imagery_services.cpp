#include "services/imagery_services.hpp"

#include <string_view>

#include "services/pmtiles_imagery.hpp"
#include "services/template_imagery.hpp"
#include "services/wmts_imagery.hpp"
#include "streaming/imagery_store.hpp"

namespace globe::services {
namespace {

using Opened = Result<std::unique_ptr<streaming::ImageryTiles>>;

template <class T>
Opened widen(Result<std::unique_ptr<T>> opened) {
  if (!opened) return Error{opened.error()};
  return std::unique_ptr<streaming::ImageryTiles>(std::move(*opened));
}

// The imagery services a layer spec names by its prefix ("wmts:URL"), one row each: the prefix
// and what opens the rest of the spec. Anything else is a layer (a directory or URL).
struct ImageryService {
  std::string_view prefix;
  Opened (*open)(const std::string& url, std::shared_ptr<transport::Network> network);
};
constexpr ImageryService kImageryServices[] = {
    {"xyz:",
     [](const std::string& url, std::shared_ptr<transport::Network> network) {
       return widen(openXyzImagery(url, std::move(network)));
     }},
    {"tms:",
     [](const std::string& url, std::shared_ptr<transport::Network> network) {
       return widen(openTmsImagery(url, std::move(network)));
     }},
    {"wmts:",
     [](const std::string& url, std::shared_ptr<transport::Network> network) {
       return widen(openWmtsImagery(url, std::move(network)));
     }},
    {"pmtiles:",
     [](const std::string& url, std::shared_ptr<transport::Network> network) {
       return widen(openPmtilesImagery(url, std::move(network)));
     }},
};

const ImageryService* serviceOf(const std::string& spec) {
  for (const ImageryService& service : kImageryServices) {
    if (std::string_view(spec).starts_with(service.prefix)) return &service;
  }
  return nullptr;
}

}  // namespace

bool isImageryService(const std::string& spec) { return serviceOf(spec) != nullptr; }

Result<std::unique_ptr<streaming::ImageryTiles>> openImageryTiles(
    const std::string& spec, std::shared_ptr<transport::Network> network) {
  if (const ImageryService* service = serviceOf(spec)) {
    return service->open(spec.substr(service->prefix.size()), std::move(network));
  }
  return widen(streaming::ImageryStore::open(spec, std::move(network)));
}

}  // namespace globe::services
