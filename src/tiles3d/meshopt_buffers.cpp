#include "tiles3d/meshopt_buffers.hpp"

#include <meshoptimizer.h>
#include <tiny_gltf.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>

namespace globe::tiles3d {
namespace {

using nlohmann::json;

const char* const kExtensionNames[] = {"EXT_meshopt_compression", "KHR_meshopt_compression"};

// The object of either extension in `o`'s "extensions", or nullptr.
const json* meshoptExtension(const json& o) {
  if (!o.is_object()) return nullptr;
  const auto extensions = o.find("extensions");
  if (extensions == o.end() || !extensions->is_object()) return nullptr;
  for (const char* key : kExtensionNames) {
    const auto it = extensions->find(key);
    if (it != extensions->end() && it->is_object()) return &*it;
  }
  return nullptr;
}

// A non-negative integer member (an integral float below 2^53 too), `fallback` when absent.
std::optional<uint64_t> unsignedMember(const json& o, const char* key,
                                       std::optional<uint64_t> fallback = std::nullopt) {
  const auto it = o.find(key);
  if (it == o.end()) return fallback;
  if (it->is_number_unsigned()) return it->get<uint64_t>();
  if (it->is_number_integer()) {
    const auto v = it->get<int64_t>();
    return v >= 0 ? std::optional<uint64_t>(static_cast<uint64_t>(v)) : std::nullopt;
  }
  if (it->is_number_float()) {
    const double v = it->get<double>();
    if (v >= 0 && v < 9007199254740992.0 && std::floor(v) == v) return static_cast<uint64_t>(v);
  }
  return std::nullopt;
}

std::string stringMember(const json& o, const char* key, const std::string& fallback) {
  const auto it = o.find(key);
  return it != o.end() && it->is_string() ? it->get<std::string>() : fallback;
}

std::optional<MeshoptMode> modeNamed(const std::string& mode) {
  if (mode == "ATTRIBUTES") return MeshoptMode::Attributes;
  if (mode == "TRIANGLES") return MeshoptMode::Triangles;
  if (mode == "INDICES") return MeshoptMode::Indices;
  return std::nullopt;
}

std::optional<MeshoptFilter> filterNamed(const std::string& filter) {
  if (filter == "NONE") return MeshoptFilter::None;
  if (filter == "OCTAHEDRAL") return MeshoptFilter::Octahedral;
  if (filter == "QUATERNION") return MeshoptFilter::Quaternion;
  if (filter == "EXPONENTIAL") return MeshoptFilter::Exponential;
  return std::nullopt;  // KHR_meshopt_compression's COLOR included: meshoptimizer 0.18 lacks it
}

// The spec's rules on byteStride, count and filter for each mode (meshoptimizer asserts them).
bool layoutAllowed(const MeshoptView& v) {
  const uint64_t s = v.byteStride;
  if (v.mode == MeshoptMode::Attributes) {
    if (s == 0 || s % 4 != 0 || s > 256) return false;
  } else if ((s != 2 && s != 4) || v.filter != MeshoptFilter::None) {
    return false;
  }
  if (v.mode == MeshoptMode::Triangles && v.count % 3 != 0) return false;
  switch (v.filter) {
    case MeshoptFilter::Octahedral:
      return s == 4 || s == 8;
    case MeshoptFilter::Quaternion:
      return s == 8;
    case MeshoptFilter::Exponential:
      return s % 4 == 0;
    case MeshoptFilter::None:
      return true;
  }
  return false;
}

// One buffer view's extension read and checked; `decodedBytes` counts the model's total.
Result<MeshoptView> readView(const json& view, const json& extension, size_t index,
                             uint64_t& decodedBytes, const std::string& name) {
  const std::string where = name + ": bufferView " + std::to_string(index) + " (meshopt)";
  MeshoptView v;
  v.view = index;
  const auto buffer = unsignedMember(extension, "buffer");
  const auto offset = unsignedMember(extension, "byteOffset", 0);
  const auto length = unsignedMember(extension, "byteLength");
  const auto stride = unsignedMember(extension, "byteStride");
  const auto count = unsignedMember(extension, "count");
  if (!buffer || !offset || !length || !stride || !count) {
    return makeError(where +
                     ": buffer, byteOffset, byteLength, byteStride or count missing or "
                     "not a non-negative integer");
  }
  const std::string modeName = stringMember(extension, "mode", "");
  const std::string filterName = stringMember(extension, "filter", "NONE");
  const auto mode = modeNamed(modeName);
  const auto filter = filterNamed(filterName);
  if (!mode) return makeError(where + ": an unknown mode '" + modeName + "'");
  if (!filter) return makeError(where + ": an unsupported filter '" + filterName + "'");
  v.buffer = static_cast<size_t>(std::min<uint64_t>(*buffer, SIZE_MAX));
  v.byteOffset = *offset, v.byteLength = *length, v.byteStride = *stride, v.count = *count;
  v.mode = *mode, v.filter = *filter;
  if (!layoutAllowed(v)) {
    return makeError(where + ": byteStride " + std::to_string(v.byteStride) + " and count " +
                     std::to_string(v.count) + " not allowed for " + modeName + "/" + filterName);
  }
  const uint64_t room = kMaxMeshoptDecodedBytes - decodedBytes;
  if (v.count > room / v.byteStride) {
    return makeError(where + ": decodes past " + std::to_string(kMaxMeshoptDecodedBytes >> 20) +
                     " MiB (" + std::to_string(v.count) + " × " + std::to_string(v.byteStride) +
                     " bytes)");
  }
  decodedBytes += v.count * v.byteStride;
  const auto parentStride = unsignedMember(view, "byteStride", 0);
  const auto parentLength = unsignedMember(view, "byteLength");
  if (!parentStride || (*parentStride != 0 && *parentStride != v.byteStride) || !parentLength ||
      *parentLength != v.count * v.byteStride) {
    return makeError(where + ": its bufferView's byteLength or byteStride disagrees with " +
                     "count × byteStride");
  }
  return v;
}

// Buffers tagged as fallbacks, and buffers with no URI (GLB's first aside) that compressed views
// fill: what a loader that decodes never reads.
std::set<size_t> fallbackBuffers(const json& buffers, const std::vector<MeshoptView>& views,
                                 const json& bufferViews, bool glb) {
  std::set<size_t> parents;
  for (const MeshoptView& v : views) {
    const auto parent = unsignedMember(bufferViews[v.view], "buffer");
    if (parent) parents.insert(static_cast<size_t>(std::min<uint64_t>(*parent, SIZE_MAX)));
  }
  std::set<size_t> out;
  for (size_t b = 0; b < buffers.size(); ++b) {
    const json& buffer = buffers[b];
    if (!buffer.is_object()) continue;
    const json* tag = meshoptExtension(buffer);
    bool tagged = false;
    if (tag != nullptr) {
      const auto fallback = tag->find("fallback");
      tagged = fallback != tag->end() && *fallback == true;
    }
    const bool noData = !buffer.contains("uri") && !(glb && b == 0);
    if (tagged || (noData && parents.count(b) != 0)) out.insert(b);
  }
  return out;
}

Result<std::vector<unsigned char>> decodeView(const MeshoptView& v, const unsigned char* source,
                                              const std::string& where) {
  std::vector<unsigned char> out(static_cast<size_t>(v.count * v.byteStride));
  const auto count = static_cast<size_t>(v.count), stride = static_cast<size_t>(v.byteStride);
  const auto length = static_cast<size_t>(v.byteLength);
  int rc = 0;
  switch (v.mode) {
    case MeshoptMode::Attributes:
      rc = meshopt_decodeVertexBuffer(out.data(), count, stride, source, length);
      break;
    case MeshoptMode::Triangles:
      rc = meshopt_decodeIndexBuffer(out.data(), count, stride, source, length);
      break;
    case MeshoptMode::Indices:
      rc = meshopt_decodeIndexSequence(out.data(), count, stride, source, length);
      break;
  }
  if (rc != 0) {
    return makeError(where + ": its compressed bytes will not decode (meshoptimizer error " +
                     std::to_string(rc) + ")");
  }
  if (v.filter == MeshoptFilter::Octahedral) meshopt_decodeFilterOct(out.data(), count, stride);
  if (v.filter == MeshoptFilter::Quaternion) meshopt_decodeFilterQuat(out.data(), count, stride);
  if (v.filter == MeshoptFilter::Exponential) meshopt_decodeFilterExp(out.data(), count, stride);
  return out;
}

}  // namespace

Result<std::vector<MeshoptView>> takeMeshoptViews(json& gltf, bool glb, const std::string& name) {
  std::vector<MeshoptView> views;
  if (!gltf.is_object()) return views;
  const auto bufferViews = gltf.find("bufferViews");
  if (bufferViews == gltf.end() || !bufferViews->is_array()) return views;
  uint64_t decodedBytes = 0;
  for (size_t i = 0; i < bufferViews->size(); ++i) {
    const json* extension = meshoptExtension((*bufferViews)[i]);
    if (extension == nullptr) continue;
    auto view = readView((*bufferViews)[i], *extension, i, decodedBytes, name);
    if (!view) return Error{view.error()};
    views.push_back(*view);
  }
  const auto buffers = gltf.find("buffers");
  if (views.empty() || buffers == gltf.end() || !buffers->is_array()) return views;
  for (const size_t b : fallbackBuffers(*buffers, views, *bufferViews, glb)) {
    (*buffers)[b] = json{{"byteLength", 1}, {"uri", "data:application/octet-stream;base64,AA=="}};
  }
  return views;
}

Result<void> decodeMeshoptViews(const std::vector<MeshoptView>& views, tinygltf::Model& model,
                                const std::string& name) {
  for (const MeshoptView& v : views) {
    const std::string where = name + ": bufferView " + std::to_string(v.view) + " (meshopt)";
    if (v.view >= model.bufferViews.size() || v.buffer >= model.buffers.size()) {
      return makeError(where + ": a buffer index out of range");
    }
    const auto& source = model.buffers[v.buffer].data;
    if (v.byteOffset > source.size() || v.byteLength > source.size() - v.byteOffset) {
      return makeError(where + ": its compressed range reaches past buffer " +
                       std::to_string(v.buffer));
    }
    auto decoded = decodeView(v, source.data() + v.byteOffset, where);
    if (!decoded) return Error{decoded.error()};
    tinygltf::Buffer buffer;
    buffer.data = std::move(*decoded);
    tinygltf::BufferView& view = model.bufferViews[v.view];
    view.byteLength = buffer.data.size();
    view.byteOffset = 0;
    view.buffer = static_cast<int>(model.buffers.size());
    model.buffers.push_back(std::move(buffer));
  }
  return {};
}

}  // namespace globe::tiles3d
