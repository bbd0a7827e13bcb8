// What the manifest needs from one finished pack.
#pragma once

#include <cstdint>

#include "formats/pack_format.hpp"
#include "formats/pyramid_manifest.hpp"
#include "terrain/height_block.hpp"

namespace globe::tiling {

struct PackSummary {
  uint64_t tiles = 0;
  formats::BoundsDegrees bounds{180, 90, -180, -90};
  terrain::HeightRange range{INT16_MAX, INT16_MIN};
  uint32_t indexBytes = 0;  // the pack's stored index (version 5), for the manifest
};

PackSummary summarise(const formats::Pack& pack);

}  // namespace globe::tiling
