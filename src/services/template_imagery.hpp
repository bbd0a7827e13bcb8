// Imagery services whose tiles are URLs from a template or a tile map: XYZ and TMS.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "services/service_imagery.hpp"
#include "transport/network_settings.hpp"

namespace globe::services {

Result<std::unique_ptr<ServiceImagery>> openXyzImagery(const std::string& spec,
                                                       std::shared_ptr<transport::Network> network);
Result<std::unique_ptr<ServiceImagery>> openTmsImagery(const std::string& url,
                                                       std::shared_ptr<transport::Network> network);

// An imagery layer from URLs: `urlOf(matrix, column, row)` per source tile, read through
// `reader` (404: no tile there).
class UrlReader;
std::unique_ptr<ServiceImagery> makeUrlImagery(
    ImageryServiceDescription description, std::unique_ptr<UrlReader> reader,
    std::function<std::string(size_t, uint64_t, uint64_t)> urlOf);

}  // namespace globe::services
