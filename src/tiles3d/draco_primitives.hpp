// Primitives compressed by Draco (KHR_draco_mesh_compression), decoded here rather than by
// tinygltf: its decoder follows the extension's bufferView, buffer, accessor and attribute ids
// unchecked (an unknown attribute id is a null pointer it calls through). The extension is taken
// out of the JSON before tinygltf reads it; each primitive is decoded, checked, into buffers of
// its own after.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/result.hpp"

namespace tinygltf {
class Model;
}

namespace globe::tiles3d {

struct DracoPrimitive {
  size_t mesh = 0, primitive = 0;
  int64_t bufferView = -1;
  std::vector<std::pair<std::string, int64_t>> attributes;  // glTF attribute → Draco unique id
};

// The Draco primitives of `gltf`, their extension removed from it. Errors name `name`.
Result<std::vector<DracoPrimitive>> takeDracoPrimitives(nlohmann::json& gltf,
                                                        const std::string& name);

// Each primitive's indices (uint32) and named attributes (floats) decoded into new buffers,
// its accessors pointed at them; ids, ranges and sizes checked (8 M triangles, 256 MiB).
Result<void> decodeDracoPrimitives(const std::vector<DracoPrimitive>& primitives,
                                   tinygltf::Model& model, const std::string& name);

}  // namespace globe::tiles3d
