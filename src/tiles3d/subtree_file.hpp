// A 3D Tiles 1.1 implicit-tiling subtree file (binary ".subtree" or JSON) read into its three
// availabilities: tiles, each content, child subtrees; every length checked before it is read.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/result.hpp"

namespace globe::tiles3d {

// Reads a file named relative to the tileset's folder (after template substitution, e.g.
// "subtrees/0.0.0.subtree"); nullopt when there is no such file; an error for other failures.
using ReadRelativeFile =
    std::function<Result<std::optional<std::vector<std::byte>>>(const std::string& uri)>;

// One availability: a constant, or a bitstream (bit i of byte i / 8, least significant first).
struct Availability {
  bool constant = false;
  std::vector<uint8_t> bits;  // empty: the constant stands
  bool at(uint64_t index) const {
    if (bits.empty()) return constant;
    return index / 8 < bits.size() && ((bits[index / 8] >> (index % 8)) & 1u) != 0;
  }
};

struct Subtree {
  Availability tiles;
  std::vector<Availability> contents;  // one per content of the implicit tile
  Availability childSubtrees;
};

// What the subtree must hold: the bit counts its bitstreams need.
struct SubtreeShape {
  uint64_t tileCount = 0;          // tiles in a subtree of subtreeLevels levels
  uint64_t childSubtreeCount = 0;  // subtrees below its bottom level
  size_t contentCount = 0;
};

// `uri`: the subtree file's name relative to the tileset's folder (its external buffers are
// named relative to its folder). Errors name `name` and `uri`.
Result<Subtree> readSubtree(std::span<const std::byte> bytes, const std::string& uri,
                            const SubtreeShape& shape, const ReadRelativeFile& read,
                            const std::string& name);

}  // namespace globe::tiles3d
