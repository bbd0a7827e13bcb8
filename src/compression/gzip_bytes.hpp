// Tiles a server stores gzip-compressed without saying so (Cesium terrain as ctb writes it): the
// bytes as stored, inflated when they start with gzip's magic.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "core/result.hpp"

namespace globe::compression {

bool isGzip(std::span<const std::byte> bytes);
// The bytes inflated when gzip, else a copy; errors (damaged stream, more than maxBytes inflated)
// name `name`.
Result<std::vector<std::byte>> gunzipIfNeeded(std::span<const std::byte> bytes,
                                              const std::string& name, size_t maxBytes);

}  // namespace globe::compression
