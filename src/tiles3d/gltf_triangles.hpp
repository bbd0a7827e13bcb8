// A glTF 2.0 model (GLB, or glTF JSON with embedded buffers) as triangles: every TRIANGLES,
// TRIANGLE_STRIP and TRIANGLE_FAN primitive of its default scene through its nodes' transforms,
// Draco-compressed ones decoded, turned from glTF's y-up to the z-up 3D Tiles expects. Extensions
// it does not know are read past (EXT_mesh_features, CESIUM_primitive_outline: metadata and
// outlines, no geometry). Normals, the base colour and its texture (decoded) come along for
// drawing.
#pragma once

#include <cstddef>
#include <span>
#include <string>

#include "core/result.hpp"
#include "tiles3d/triangle_mesh.hpp"

namespace globe::tiles3d {

// Errors name `name` (the file or URL) and say what is wrong.
Result<TriangleMesh> readGltfTriangles(std::span<const std::byte> bytes, const std::string& name);

}  // namespace globe::tiles3d
