#include "tests/support/quantized_mesh_file.hpp"

#include <fstream>
#include <iterator>
#include <span>

#include "compression/gzip_bytes.hpp"

namespace globe::testing {

Result<formats::QuantizedMesh> readQuantizedMeshFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return makeError(path.string() + ": cannot open");
  const std::vector<char> raw{std::istreambuf_iterator<char>(in), {}};
  auto inflated = compression::gunzipIfNeeded(std::as_bytes(std::span(raw.data(), raw.size())),
                                              path.string(), size_t{64} << 20);
  if (!inflated) return Error{inflated.error()};
  return formats::decodeQuantizedMesh(*inflated, path.string());
}

std::vector<terrain::TinVertex> tinVertices(const formats::QuantizedMesh& mesh) {
  constexpr double q = formats::kQuantizedMax;
  std::vector<terrain::TinVertex> vertices(mesh.vertexCount());
  for (size_t i = 0; i < vertices.size(); ++i) {
    vertices[i] = {mesh.u[i] / q, mesh.v[i] / q, mesh.heightMeters[i]};
  }
  return vertices;
}

}  // namespace globe::testing
