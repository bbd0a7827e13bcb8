// Test tilesets made on the spot: a box "building" as a GLB (glTF y-up, base at 0, its roof at
// `heightMeters`), placed east-north-up at a longitude and latitude by a tile transform.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

namespace globe::tiles3d::testing {

// A GLB of a box [-halfEast, halfEast] × [0, height] × [-halfNorth, halfNorth] (x east, y up,
// z south as glTF's y-up becomes 3D Tiles' z-up): 12 triangles, uint16 indices.
std::vector<std::byte> boxGlb(double halfEastMeters, double halfNorthMeters, double heightMeters);

// The east-north-up frame at a place on the WGS84 ellipsoid (column-major, as tileset.json).
glm::dmat4 eastNorthUp(double longitudeDegrees, double latitudeDegrees, double heightMeters);

// tileset.json's 16 numbers for a matrix.
std::string transformJson(const glm::dmat4& m);

void writeFile(const std::filesystem::path& path, const std::string& text);
void writeFile(const std::filesystem::path& path, const std::vector<std::byte>& bytes);

}  // namespace globe::tiles3d::testing
