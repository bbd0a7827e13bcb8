// glTF buffer views compressed by meshoptimizer (EXT_meshopt_compression and its ratified form
// KHR_meshopt_compression, the same JSON): read from the glTF's JSON before tinygltf loads it,
// decoded (meshoptimizer's decoders and filters) into buffers of their own after it has.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/result.hpp"

namespace tinygltf {
class Model;
}

namespace globe::tiles3d {

// What one glTF may decode into, all its compressed views together.
constexpr uint64_t kMaxMeshoptDecodedBytes = uint64_t{256} << 20;

enum class MeshoptMode { Attributes, Triangles, Indices };
enum class MeshoptFilter { None, Octahedral, Quaternion, Exponential };

// A buffer view's extension, checked against the spec's rules and the size limit.
struct MeshoptView {
  size_t view = 0;    // the bufferView it fills
  size_t buffer = 0;  // where its compressed bytes are
  uint64_t byteOffset = 0, byteLength = 0;
  uint64_t byteStride = 0, count = 0;
  MeshoptMode mode = MeshoptMode::Attributes;
  MeshoptFilter filter = MeshoptFilter::None;
};

// The compressed views of `gltf` (its JSON; `glb` when it came with a GLB's binary chunk), and
// its fallback buffers replaced by a one-byte placeholder that tinygltf will load (it refuses a
// buffer with no data, and a placeholder may declare gigabytes). Errors name `name`.
Result<std::vector<MeshoptView>> takeMeshoptViews(nlohmann::json& gltf, bool glb,
                                                  const std::string& name);

// Each view decoded from its compressed range (inside its buffer, or an error) into a buffer
// appended to the model, the view pointed at it.
Result<void> decodeMeshoptViews(const std::vector<MeshoptView>& views, tinygltf::Model& model,
                                const std::string& name);

}  // namespace globe::tiles3d
