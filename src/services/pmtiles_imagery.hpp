// A PMTiles v3 archive of PNG, JPEG, WebP or AVIF tiles (Web Mercator) as an imagery layer, read by
// range requests through the program's Network (and its disk cache), or from a local file.
#pragma once

#include <memory>
#include <string>

#include "services/service_imagery.hpp"
#include "transport/network_settings.hpp"

namespace globe::services {

Result<std::unique_ptr<ServiceImagery>> openPmtilesImagery(
    const std::string& url, std::shared_ptr<transport::Network> network);

}  // namespace globe::services
