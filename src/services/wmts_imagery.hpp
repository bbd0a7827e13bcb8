// A WMTS layer as an imagery layer: wmts:URL?layer=NAME[&tilematrixset=ID&style=S&format=F],
// URL the GetCapabilities document; tiles by its RESTful template, else by KVP GetTile.
#pragma once

#include <memory>
#include <string>

#include "services/service_imagery.hpp"
#include "transport/network_settings.hpp"

namespace globe::services {

Result<std::unique_ptr<ServiceImagery>> openWmtsImagery(
    const std::string& spec, std::shared_ptr<transport::Network> network);

}  // namespace globe::services
