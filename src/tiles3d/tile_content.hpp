// A 3D tile's content as triangles in ECEF: b3dm (a glTF and RTC_CENTER), i3dm (a glTF placed
// at each instance: position, orientation from NORMAL_UP/NORMAL_RIGHT, their oct-encoded forms or
// east-north-up, scale), cmpt (its inner tiles), GLB/glTF (3D Tiles 1.1), pnts (points: no
// surface, nothing kept). The tile's transform applies after the content's own placement.
#pragma once

#include <cstddef>
#include <span>
#include <string>

#include <glm/mat4x4.hpp>

#include "core/result.hpp"
#include "geo/ellipsoid.hpp"
#include "tiles3d/triangle_mesh.hpp"

namespace globe::tiles3d {

// Errors name `name` (the file or URL) and say what is wrong: a header past the bytes, an
// unknown magic, a glTF that will not read.
Result<TriangleMesh> readTileContent(std::span<const std::byte> bytes,
                                     const glm::dmat4& tileTransform,
                                     const geo::Ellipsoid& ellipsoid, const std::string& name);

}  // namespace globe::tiles3d
