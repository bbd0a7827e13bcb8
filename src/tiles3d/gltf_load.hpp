// tinygltf's load of a GLB or glTF JSON, with what it does not do done around it: buffer views
// compressed by meshoptimizer decoded (tiles3d/meshopt_buffers.hpp), Draco primitives decoded
// with their ids checked (tiles3d/draco_primitives.hpp) instead of by tinygltf.
#pragma once

#include <cstddef>
#include <span>
#include <string>

#include "core/result.hpp"

namespace tinygltf {
class Model;
class TinyGLTF;
}  // namespace tinygltf

namespace globe::tiles3d {

// `bytes` loaded by `loader` (its callbacks set) into `model`; errors name `name`.
Result<void> loadGltfModel(tinygltf::TinyGLTF& loader, std::span<const std::byte> bytes,
                           const std::string& name, tinygltf::Model& model);

}  // namespace globe::tiles3d
