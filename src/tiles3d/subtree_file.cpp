#include "tiles3d/subtree_file.hpp"

#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>

#include <nlohmann/json.hpp>

namespace globe::tiles3d {
namespace {

constexpr size_t kHeaderBytes = 24;
constexpr size_t kMaxBuffers = 1024;
constexpr size_t kMaxBufferViews = 4096;

using Json = nlohmann::json;
using Bytes = std::span<const std::byte>;

// A non-negative integer member, nullopt when absent; an error text when it is something else.
Result<std::optional<uint64_t>> count(const Json& j, const char* key) {
  const auto it = j.find(key);
  if (it == j.end()) return std::optional<uint64_t>{};
  if (it->is_number_unsigned()) return std::optional<uint64_t>(it->get<uint64_t>());
  if (it->is_number_integer() && it->get<int64_t>() >= 0)
    return std::optional<uint64_t>(static_cast<uint64_t>(it->get<int64_t>()));
  if (it->is_number_float()) {
    const double v = it->get<double>();
    if (v >= 0 && v < 9.0e18 && std::floor(v) == v)
      return std::optional<uint64_t>(static_cast<uint64_t>(v));
  }
  return makeError(std::string("'") + key + "' is not a non-negative integer");
}

uint64_t u64At(Bytes bytes, size_t at) {
  uint64_t v;
  std::memcpy(&v, bytes.data() + at, 8);
  return v;
}

struct Split {
  Json json;
  Bytes binary;
};

Result<Json> parseJson(Bytes bytes) {
  try {
    const auto* text = reinterpret_cast<const char*>(bytes.data());
    Json j = Json::parse(text, text + bytes.size());
    if (!j.is_object()) return makeError("its JSON is not an object");
    return j;
  } catch (const Json::exception& e) {
    return makeError(std::string("its JSON does not parse (") + e.what() + ")");
  }
}

// The binary form's header, JSON and binary chunk, or the JSON form whole.
Result<Split> split(Bytes bytes) {
  const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "subt", 4) == 0;
  if (!binary) {
    size_t first = 0;
    while (first < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[first]))) ++first;
    if (first == bytes.size() || bytes[first] != std::byte{'{'})
      return makeError("not a subtree file (neither the magic \"subt\" nor JSON)");
    auto j = parseJson(bytes);
    if (!j) return Error{j.error()};
    return Split{std::move(*j), {}};
  }
  if (bytes.size() < kHeaderBytes)
    return makeError("truncated: " + std::to_string(bytes.size()) + " bytes, shorter than its " +
                     std::to_string(kHeaderBytes) + "-byte header");
  uint32_t version;
  std::memcpy(&version, bytes.data() + 4, 4);
  if (version != 1) return makeError("subtree version " + std::to_string(version) + " (not 1)");
  const uint64_t jsonBytes = u64At(bytes, 8), binaryBytes = u64At(bytes, 16);
  const uint64_t rest = bytes.size() - kHeaderBytes;
  if (jsonBytes > rest || binaryBytes > rest - jsonBytes)
    return makeError("truncated: its header says " + std::to_string(jsonBytes) + " JSON and " +
                     std::to_string(binaryBytes) + " binary bytes, the file holds " +
                     std::to_string(rest) + " after the header");
  auto j = parseJson(bytes.subspan(kHeaderBytes, jsonBytes));
  if (!j) return Error{j.error()};
  return Split{std::move(*j), bytes.subspan(kHeaderBytes + jsonBytes, binaryBytes)};
}

struct Loaded {
  std::vector<std::vector<std::byte>> owned;  // external buffers' bytes
  std::vector<Bytes> buffers;
  std::vector<Bytes> views;
};

// An external buffer, named relative to the subtree file's folder.
Result<Bytes> externalBuffer(const std::string& bufferUri, const std::string& subtreeUri,
                             const ReadRelativeFile& read, Loaded& loaded) {
  if (bufferUri.rfind("data:", 0) == 0 || bufferUri.find("://") != std::string::npos)
    return makeError("buffer '" + bufferUri + "': a URL or data URI (not read)");
  const std::string file =
      (std::filesystem::path(subtreeUri).parent_path() / bufferUri).generic_string();
  auto bytes = read(file);
  if (!bytes) return makeError("buffer '" + bufferUri + "': " + bytes.error());
  if (!bytes->has_value()) return makeError("buffer '" + bufferUri + "': no such file");
  loaded.owned.push_back(std::move(**bytes));
  return Bytes(loaded.owned.back());
}

Result<void> loadBuffers(const Json& j, Bytes binary, const std::string& subtreeUri,
                         const ReadRelativeFile& read, Loaded& loaded) {
  const auto buffers = j.find("buffers");
  if (buffers == j.end()) return {};
  if (!buffers->is_array() || buffers->size() > kMaxBuffers)
    return makeError("'buffers' is not an array of at most " + std::to_string(kMaxBuffers));
  loaded.owned.reserve(buffers->size());  // spans into it stay valid
  for (const Json& b : *buffers) {
    if (!b.is_object()) return makeError("a buffer that is not an object");
    auto length = count(b, "byteLength");
    if (!length) return Error{length.error()};
    if (!length->has_value()) return makeError("a buffer without a byteLength");
    Bytes bytes = binary;
    if (const auto uri = b.find("uri"); uri != b.end()) {
      if (!uri->is_string()) return makeError("a buffer uri that is not a string");
      auto external = externalBuffer(uri->get<std::string>(), subtreeUri, read, loaded);
      if (!external) return Error{external.error()};
      bytes = *external;
    }
    if (**length > bytes.size())
      return makeError("a buffer of byteLength " + std::to_string(**length) + " holds only " +
                       std::to_string(bytes.size()) + " bytes");
    loaded.buffers.push_back(bytes.first(**length));
  }
  return {};
}

Result<void> loadViews(const Json& j, Loaded& loaded) {
  const auto views = j.find("bufferViews");
  if (views == j.end()) return {};
  if (!views->is_array() || views->size() > kMaxBufferViews)
    return makeError("'bufferViews' is not an array of at most " + std::to_string(kMaxBufferViews));
  for (const Json& v : *views) {
    if (!v.is_object()) return makeError("a bufferView that is not an object");
    auto buffer = count(v, "buffer");
    auto offset = count(v, "byteOffset");
    auto length = count(v, "byteLength");
    if (!buffer || !offset || !length)
      return makeError("a bufferView's " + (!buffer   ? buffer.error()
                                            : !offset ? offset.error()
                                                      : length.error()));
    if (!buffer->has_value() || **buffer >= loaded.buffers.size())
      return makeError("a bufferView of a buffer that is not there");
    const Bytes b = loaded.buffers[**buffer];
    const uint64_t at = offset->value_or(0), size = length->value_or(0);
    if (at > b.size() || size > b.size() - at)
      return makeError("a bufferView (offset " + std::to_string(at) + ", " + std::to_string(size) +
                       " bytes) past the end of its buffer of " + std::to_string(b.size()) +
                       " bytes");
    loaded.views.push_back(b.subspan(at, size));
  }
  return {};
}

Result<Availability> availability(const Json& j, uint64_t bitCount, const Loaded& loaded,
                                  const std::string& what) {
  if (!j.is_object()) return makeError(what + " is not an object");
  Availability a;
  const char* key = j.contains("bitstream") ? "bitstream" : "bufferView";  // 1.0 draft's name
  auto index = count(j, key);
  if (!index) return makeError(what + ": " + index.error());
  if (index->has_value()) {
    if (**index >= loaded.views.size())
      return makeError(what + ": bitstream " + std::to_string(**index) + " is not a bufferView");
    const Bytes view = loaded.views[**index];
    const uint64_t needed = bitCount / 8 + (bitCount % 8 != 0);
    if (view.size() < needed)
      return makeError(what + ": a bitstream of " + std::to_string(view.size()) +
                       " bytes, shorter than the " + std::to_string(needed) + " its " +
                       std::to_string(bitCount) + " bits need");
    a.bits.resize(needed);
    std::memcpy(a.bits.data(), view.data(), needed);
    if (a.bits.empty()) a.constant = false;  // no bits: nothing available
    return a;
  }
  auto constant = count(j, "constant");
  if (!constant || !constant->has_value() || **constant > 1)
    return makeError(what + ": neither a bitstream nor a constant of 0 or 1");
  a.constant = **constant == 1;
  return a;
}

Result<Subtree> readParts(const Json& j, const SubtreeShape& shape, const Loaded& loaded) {
  Subtree s;
  const auto tiles = j.find("tileAvailability");
  if (tiles == j.end()) return makeError("no tileAvailability");
  auto t = availability(*tiles, shape.tileCount, loaded, "tileAvailability");
  if (!t) return Error{t.error()};
  s.tiles = std::move(*t);
  s.contents.resize(shape.contentCount);  // absent: no content available
  if (const auto c = j.find("contentAvailability"); c != j.end()) {
    if (!c->is_array()) return makeError("contentAvailability is not an array");
    for (size_t k = 0; k < c->size() && k < shape.contentCount; ++k) {
      auto a = availability((*c)[k], shape.tileCount, loaded,
                            "contentAvailability[" + std::to_string(k) + "]");
      if (!a) return Error{a.error()};
      s.contents[k] = std::move(*a);
    }
  }
  if (const auto c = j.find("childSubtreeAvailability"); c != j.end()) {
    auto a = availability(*c, shape.childSubtreeCount, loaded, "childSubtreeAvailability");
    if (!a) return Error{a.error()};
    s.childSubtrees = std::move(*a);
  }
  return s;
}

}  // namespace

Result<Subtree> readSubtree(std::span<const std::byte> bytes, const std::string& uri,
                            const SubtreeShape& shape, const ReadRelativeFile& read,
                            const std::string& name) {
  const auto fail = [&](const std::string& why) {
    return makeError(name + ": subtree '" + uri + "': " + why);
  };
  auto parts = split(bytes);
  if (!parts) return fail(parts.error());
  Loaded loaded;
  if (auto ok = loadBuffers(parts->json, parts->binary, uri, read, loaded); !ok)
    return fail(ok.error());
  if (auto ok = loadViews(parts->json, loaded); !ok) return fail(ok.error());
  auto subtree = readParts(parts->json, shape, loaded);
  if (!subtree) return fail(subtree.error());
  return subtree;
}

}  // namespace globe::tiles3d
