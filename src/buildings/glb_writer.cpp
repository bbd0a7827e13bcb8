#include "buildings/glb_writer.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

namespace globe::buildings {
namespace {

constexpr uint32_t kGlbMagic = 0x46546C67;   // "glTF"
constexpr uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"
constexpr uint32_t kBinChunk = 0x004E4942;   // "BIN\0"
constexpr int kFloat = 5126, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

glm::vec3 yUp(const glm::dvec3& zUp) {
  return {static_cast<float>(zUp.x), static_cast<float>(zUp.z), static_cast<float>(-zUp.y)};
}

template <class T>
void append(std::vector<std::byte>& out, const T& value) {
  const auto* bytes = reinterpret_cast<const std::byte*>(&value);
  out.insert(out.end(), bytes, bytes + sizeof(T));
}

void appendChunk(std::vector<std::byte>& out, uint32_t type, std::vector<std::byte> data,
                 std::byte pad) {
  while (data.size() % 4 != 0) data.push_back(pad);
  append(out, static_cast<uint32_t>(data.size()));
  append(out, type);
  out.insert(out.end(), data.begin(), data.end());
}

nlohmann::json gltfJson(const BuildingMesh& mesh, const glm::dvec3& centre, const glm::vec3& lo,
                        const glm::vec3& hi, size_t vertexBytes, size_t indexBytes) {
  using nlohmann::json;
  const size_t vertices = mesh.positionsEcefMeters.size();
  return json{
      {"asset", {{"version", "2.0"}, {"generator", "globe-tiler buildings"}}},
      {"scene", 0},
      {"scenes", json::array({{{"nodes", {0}}}})},
      {"nodes", json::array({{{"mesh", 0}, {"translation", {centre.x, centre.z, -centre.y}}}})},
      {"meshes",
       json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}},
                                                  {"indices", 2},
                                                  {"material", 0},
                                                  {"mode", 4}}})}}})},
      {"materials", json::array({{{"name", "building"},
                                  {"pbrMetallicRoughness",
                                   {{"baseColorFactor", {0.85, 0.82, 0.76, 1.0}},
                                    {"metallicFactor", 0.0},
                                    {"roughnessFactor", 0.9}}}}})},
      {"buffers", json::array({{{"byteLength", 2 * vertexBytes + indexBytes}}})},
      {"bufferViews", json::array({{{"buffer", 0},
                                    {"byteOffset", 0},
                                    {"byteLength", vertexBytes},
                                    {"target", kArrayBuffer}},
                                   {{"buffer", 0},
                                    {"byteOffset", vertexBytes},
                                    {"byteLength", vertexBytes},
                                    {"target", kArrayBuffer}},
                                   {{"buffer", 0},
                                    {"byteOffset", 2 * vertexBytes},
                                    {"byteLength", indexBytes},
                                    {"target", kElementArrayBuffer}}})},
      {"accessors",
       json::array(
           {{{"bufferView", 0},
             {"componentType", kFloat},
             {"count", vertices},
             {"type", "VEC3"},
             {"min", {lo.x, lo.y, lo.z}},
             {"max", {hi.x, hi.y, hi.z}}},
            {{"bufferView", 1}, {"componentType", kFloat}, {"count", vertices}, {"type", "VEC3"}},
            {{"bufferView", 2},
             {"componentType", kUnsignedInt},
             {"count", mesh.indices.size()},
             {"type", "SCALAR"}}})}};
}

}  // namespace

std::vector<std::byte> encodeGlb(const BuildingMesh& mesh, const glm::dvec3& centreEcefMeters) {
  std::vector<std::byte> bin;
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
  for (const glm::dvec3& p : mesh.positionsEcefMeters) {
    const glm::vec3 v = yUp(p - centreEcefMeters);
    lo = glm::min(lo, v), hi = glm::max(hi, v);
    append(bin, v);
  }
  const size_t vertexBytes = bin.size();
  for (const glm::vec3& n : mesh.normals) append(bin, yUp(glm::dvec3(n)));
  for (const uint32_t i : mesh.indices) append(bin, i);
  const size_t indexBytes = bin.size() - 2 * vertexBytes;
  if (mesh.positionsEcefMeters.empty()) lo = hi = glm::vec3(0);
  const std::string text = gltfJson(mesh, centreEcefMeters, lo, hi, vertexBytes, indexBytes).dump();
  std::vector<std::byte> json(text.size());
  std::memcpy(json.data(), text.data(), text.size());
  std::vector<std::byte> body;
  appendChunk(body, kJsonChunk, std::move(json), std::byte{' '});
  appendChunk(body, kBinChunk, std::move(bin), std::byte{0});
  std::vector<std::byte> out;
  append(out, kGlbMagic);
  append(out, uint32_t{2});
  append(out, static_cast<uint32_t>(12 + body.size()));
  out.insert(out.end(), body.begin(), body.end());
  return out;
}

}  // namespace globe::buildings
