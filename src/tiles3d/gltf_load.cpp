#include "tiles3d/gltf_load.hpp"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>
#include <optional>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "tiles3d/draco_primitives.hpp"
#include "tiles3d/meshopt_buffers.hpp"

namespace globe::tiles3d {
namespace {

constexpr uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"

uint32_t u32(const unsigned char* p) {
  uint32_t v;
  std::memcpy(&v, p, 4);
  return v;
}

void putU32(std::vector<unsigned char>& out, size_t at, uint32_t v) {
  std::memcpy(out.data() + at, &v, 4);
}

// A GLB's JSON chunk and what follows it (the BIN chunk), or nullopt when the layout is not
// sound (tinygltf then says what is wrong).
struct GlbParts {
  std::string_view json;
  std::span<const unsigned char> rest;
};
std::optional<GlbParts> glbParts(std::span<const unsigned char> bytes) {
  if (bytes.size() < 20 || std::memcmp(bytes.data(), "glTF", 4) != 0) return std::nullopt;
  const size_t total = std::min<size_t>(u32(bytes.data() + 8), bytes.size());
  const size_t jsonLength = u32(bytes.data() + 12);
  if (u32(bytes.data() + 16) != kJsonChunk || total < 20 || jsonLength > total - 20) {
    return std::nullopt;
  }
  return GlbParts{{reinterpret_cast<const char*>(bytes.data() + 20), jsonLength},
                  bytes.subspan(20 + jsonLength, total - 20 - jsonLength)};
}

// A GLB with `json` as its JSON chunk (padded with spaces) and `rest` after it.
std::vector<unsigned char> makeGlb(const std::string& json, std::span<const unsigned char> rest) {
  const size_t jsonLength = (json.size() + 3) / 4 * 4;
  std::vector<unsigned char> out(20 + jsonLength, ' ');
  std::memcpy(out.data(), "glTF", 4);
  putU32(out, 4, 2);
  putU32(out, 8, static_cast<uint32_t>(out.size() + rest.size()));
  putU32(out, 12, static_cast<uint32_t>(jsonLength));
  putU32(out, 16, kJsonChunk);
  std::memcpy(out.data() + 20, json.data(), json.size());
  out.insert(out.end(), rest.begin(), rest.end());
  return out;
}

// The bytes tinygltf gets (rewritten when meshopt fallback buffers had to be replaced or Draco
// extensions taken out) and what to decode after it has loaded them. tinygltf fails a buffer with
// no data (a GLB's placeholder past its BIN chunk, a glTF buffer without URI), so the placeholders
// are swapped before it reads the JSON; the views are decoded after, from the buffers it loaded
// (GLB chunk or data URI alike), which keeps its buffer handling as the one source of bytes.
struct Prepared {
  std::vector<unsigned char> rewritten;  // empty: the input as it is
  std::vector<MeshoptView> meshopt;
  std::vector<DracoPrimitive> draco;
};
Result<Prepared> prepare(std::span<const unsigned char> bytes, const std::string& name) {
  const auto glb = glbParts(bytes);
  const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  if (binary && !glb) return Prepared{};
  const std::string_view text =
      glb ? glb->json : std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  const bool meshopt = text.find("meshopt_compression") != std::string_view::npos;
  // (a key spelt with \u escapes is only seen once parsed)
  const bool draco = text.find("KHR_draco_mesh_compression") != std::string_view::npos ||
                     text.find("\\u") != std::string_view::npos;
  if (!meshopt && !draco) return Prepared{};
  auto json = nlohmann::json::parse(text.begin(), text.end(), nullptr, false);
  if (json.is_discarded() || !json.is_object()) {
    if (!draco) return Prepared{};  // tinygltf says what is wrong
    return makeError(name + ": not a glTF 2.0 model (its JSON will not parse)");
  }
  auto views = takeMeshoptViews(json, binary, name);
  if (!views) return Error{views.error()};
  auto dracoPrimitives = takeDracoPrimitives(json, name);
  if (!dracoPrimitives) return Error{dracoPrimitives.error()};
  if (views->empty() && dracoPrimitives->empty()) return Prepared{};
  Prepared prepared;
  prepared.meshopt = std::move(*views);
  prepared.draco = std::move(*dracoPrimitives);
  const std::string dumped = json.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  if (glb) {
    prepared.rewritten = makeGlb(dumped, glb->rest);
  } else {
    prepared.rewritten.assign(dumped.begin(), dumped.end());
  }
  return prepared;
}

}  // namespace

Result<void> loadGltfModel(tinygltf::TinyGLTF& loader, std::span<const std::byte> bytes,
                           const std::string& name, tinygltf::Model& model) {
  const std::span<const unsigned char> input(reinterpret_cast<const unsigned char*>(bytes.data()),
                                             bytes.size());
  auto prepared = prepare(input, name);
  if (!prepared) return Error{prepared.error()};
  const std::span<const unsigned char> data =
      prepared->rewritten.empty() ? input : std::span<const unsigned char>(prepared->rewritten);
  if (data.size() > 0xFFFFFFFFu) return makeError(name + ": a glTF over 4 GB");
  const bool binary = data.size() >= 4 && std::memcmp(data.data(), "glTF", 4) == 0;
  const auto size = static_cast<unsigned>(data.size());
  std::string err, warn;
  const bool ok =
      binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, data.data(), size, "")
             : loader.LoadASCIIFromString(&model, &err, &warn,
                                          reinterpret_cast<const char*>(data.data()), size, "");
  if (!ok) return makeError(name + ": not a glTF 2.0 model (" + (err.empty() ? warn : err) + ")");
  auto decoded = decodeMeshoptViews(prepared->meshopt, model, name);
  if (!decoded) return decoded;
  return decodeDracoPrimitives(prepared->draco, model, name);
}

}  // namespace globe::tiles3d
