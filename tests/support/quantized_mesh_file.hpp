// A quantized-mesh tile read from a file for the TIN tests and benchmarks: gunzipped where it
// is, decoded (formats/quantized_mesh.hpp), and its vertices as terrain::TinVertex.
#pragma once

#include <filesystem>
#include <vector>

#include "core/result.hpp"
#include "formats/quantized_mesh.hpp"
#include "terrain/tin_tile.hpp"

namespace globe::testing {

Result<formats::QuantizedMesh> readQuantizedMeshFile(const std::filesystem::path& path);

// u and v of 0..32767 as 0..1, with the heights.
std::vector<terrain::TinVertex> tinVertices(const formats::QuantizedMesh& mesh);

}  // namespace globe::testing
