// Parses globe-tiler's --shard K/N: which of N shards this run tiles.
#pragma once

#include <cstdint>
#include <string>

#include "core/result.hpp"

namespace globe::tiler_app {

struct ShardSpec {
  uint32_t index = 0;  // K of K/N, from 0
  uint32_t count = 1;  // N
};

// "K/N" with 0 <= K < N; errors name the argument and show the form.
Result<ShardSpec> parseShardSpec(const std::string& text);

}  // namespace globe::tiler_app
