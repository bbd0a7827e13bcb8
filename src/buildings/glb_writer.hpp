// One tile's buildings as a binary glTF 2.0 (GLB): one mesh of one primitive (POSITION float32,
// NORMAL float32, uint32 indices, triangles) and one material, under a node whose translation
// is the tile's centre. glTF is y-up and 3D Tiles turns it z-up (a rotation of +90° about x), so
// an ECEF offset (x, y, z) is stored as (x, z, -y), the translation too: the offsets stay small
// enough for float32 (millimetres within a few kilometres) and the centre keeps double precision.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

#include "buildings/extrusion.hpp"

namespace globe::buildings {

// The GLB file's bytes; the same mesh and centre always give the same bytes.
std::vector<std::byte> encodeGlb(const BuildingMesh& mesh, const glm::dvec3& centreEcefMeters);

}  // namespace globe::buildings
