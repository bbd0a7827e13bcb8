#include "tiles3d/tile_content.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "geo/cartographic.hpp"
#include "geo/ecef.hpp"
#include "tiles3d/gltf_triangles.hpp"

namespace globe::tiles3d {
namespace {

constexpr int kMaxCompositeDepth = 8;  // cmpt inside cmpt
constexpr size_t kMaxInstancedTriangles = size_t{8} << 20;
constexpr size_t kMaxInstances = size_t{1} << 24;

uint32_t u32(std::span<const std::byte> bytes, size_t at) {
  uint32_t v;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;
}

// A member that is a number, `fallback` when absent, NaN when something else (nlohmann's value()
// throws on a wrong type: a string byteOffset ended the program).
double numberOr(const nlohmann::json& o, const char* key, double fallback) {
  const auto it = o.find(key);
  if (it == o.end()) return fallback;
  return it->is_number() ? it->get<double>() : std::numeric_limits<double>::quiet_NaN();
}

// A feature table: its JSON and binary body, read as the 3D Tiles spec lays them out.
struct FeatureTable {
  nlohmann::json json;
  std::span<const std::byte> binary;

  // `count` values of `components` floats (or uint16 when `shorts`) at a property's byteOffset,
  // or the JSON array itself; nullopt where absent. Errors when out of the binary body.
  Result<std::optional<std::vector<double>>> numbers(const std::string& key, size_t count,
                                                     size_t components, bool shorts,
                                                     const std::string& name) const {
    const auto it = json.find(key);
    if (it == json.end()) return std::optional<std::vector<double>>();
    std::vector<double> out;
    if (it->is_array()) {
      for (const auto& v : *it) out.push_back(v.is_number() ? v.get<double>() : 0.0);
      if (out.size() != count * components)
        return makeError(name + ": " + key + " of a wrong length");
      return std::optional(out);
    }
    const double offset = it->is_object() ? numberOr(*it, "byteOffset", -1.0) : -1.0;
    const size_t size = shorts ? 2 : 4;
    if (!(offset >= 0 && offset <= static_cast<double>(binary.size())) ||
        count * components * size > binary.size() ||
        static_cast<size_t>(offset) > binary.size() - count * components * size) {
      return makeError(name + ": " + key + " reaches past its feature table");
    }
    const std::byte* p = binary.data() + static_cast<size_t>(offset);
    for (size_t k = 0; k < count * components; ++k) {
      if (shorts) {
        uint16_t v;
        std::memcpy(&v, p + 2 * k, 2);
        out.push_back(v);
      } else {
        float v;
        std::memcpy(&v, p + 4 * k, 4);
        out.push_back(v);
      }
    }
    return std::optional(out);
  }
};

// The header's feature table (after `headerBytes`) and what follows the batch table.
struct Sections {
  FeatureTable features;
  std::span<const std::byte> payload;
};

Result<Sections> sectionsOf(std::span<const std::byte> bytes, size_t headerBytes,
                            const std::string& name) {
  if (bytes.size() < headerBytes) return makeError(name + ": shorter than its header");
  const uint64_t byteLength = u32(bytes, 8);
  const uint64_t ftJson = u32(bytes, 12), ftBinary = u32(bytes, 16);
  const uint64_t btJson = u32(bytes, 20), btBinary = u32(bytes, 24);
  if (byteLength > bytes.size() ||
      headerBytes + ftJson + ftBinary + btJson + btBinary > byteLength) {
    return makeError(name + ": its header's lengths reach past its " +
                     std::to_string(bytes.size()) + " bytes");
  }
  Sections s;
  const auto* json = reinterpret_cast<const char*>(bytes.data() + headerBytes);
  try {
    s.features.json =
        ftJson > 0 ? nlohmann::json::parse(json, json + ftJson) : nlohmann::json::object();
  } catch (const nlohmann::json::exception& e) {
    return makeError(name + ": its feature table is not JSON (" + e.what() + ")");
  }
  if (!s.features.json.is_object()) return makeError(name + ": its feature table is not an object");
  s.features.binary = bytes.subspan(headerBytes + ftJson, ftBinary);
  const size_t payload = headerBytes + ftJson + ftBinary + btJson + btBinary;
  s.payload = bytes.subspan(payload, byteLength - payload);
  return s;
}

Result<glm::dvec3> rtcCenter(const FeatureTable& table, const std::string& name) {
  auto rtc = table.numbers("RTC_CENTER", 1, 3, false, name);
  if (!rtc) return Error{rtc.error()};
  return *rtc ? glm::dvec3((**rtc)[0], (**rtc)[1], (**rtc)[2]) : glm::dvec3(0.0);
}

// 3D Tiles' oct encoding in 16 bits a component.
glm::dvec3 octDecode(double x, double y) {
  glm::dvec3 v(x / 65535.0 * 2 - 1, y / 65535.0 * 2 - 1, 0);
  v.z = 1 - std::fabs(v.x) - std::fabs(v.y);
  if (v.z < 0) {
    const double ox = v.x;
    v.x = (1 - std::fabs(v.y)) * (ox >= 0 ? 1 : -1);
    v.y = (1 - std::fabs(ox)) * (v.y >= 0 ? 1 : -1);
  }
  return glm::normalize(v);
}

Result<TriangleMesh> readContent(std::span<const std::byte> bytes, const geo::Ellipsoid& ellipsoid,
                                 const std::string& name, int depth);

Result<TriangleMesh> readBatched(std::span<const std::byte> bytes, const std::string& name) {
  auto s = sectionsOf(bytes, 28, name);
  if (!s) return Error{s.error()};
  auto mesh = readGltfTriangles(s->payload, name);
  if (!mesh) return mesh;
  auto rtc = rtcCenter(s->features, name);
  if (!rtc) return Error{rtc.error()};
  mesh->transform(glm::translate(glm::dmat4(1.0), *rtc));
  return mesh;
}

// Instance k's rotation columns (right, up, forward) from the feature table.
struct Orientations {
  std::optional<std::vector<double>> up, right;  // three a instance, unit
  bool eastNorthUp = false;
};

Result<Orientations> orientationsOf(const FeatureTable& t, size_t n, const std::string& name) {
  Orientations o;
  auto up = t.numbers("NORMAL_UP", n, 3, false, name);
  auto right = t.numbers("NORMAL_RIGHT", n, 3, false, name);
  if (!up || !right) return Error{!up ? up.error() : right.error()};
  o.up = *up, o.right = *right;
  if (!o.up) {
    auto upOct = t.numbers("NORMAL_UP_OCT32P", n, 2, true, name);
    auto rightOct = t.numbers("NORMAL_RIGHT_OCT32P", n, 2, true, name);
    if (!upOct || !rightOct) return Error{!upOct ? upOct.error() : rightOct.error()};
    if (*upOct && *rightOct) {
      o.up.emplace(), o.right.emplace();
      for (size_t k = 0; k < n; ++k) {
        const glm::dvec3 u = octDecode((**upOct)[2 * k], (**upOct)[2 * k + 1]);
        const glm::dvec3 r = octDecode((**rightOct)[2 * k], (**rightOct)[2 * k + 1]);
        o.up->insert(o.up->end(), {u.x, u.y, u.z});
        o.right->insert(o.right->end(), {r.x, r.y, r.z});
      }
    }
  }
  const auto eastNorthUp = t.json.find("EAST_NORTH_UP");
  o.eastNorthUp =
      eastNorthUp != t.json.end() && eastNorthUp->is_boolean() && eastNorthUp->get<bool>();
  return o;
}

Result<std::vector<glm::dvec3>> instancePositions(const FeatureTable& t, size_t n,
                                                  const std::string& name) {
  auto plain = t.numbers("POSITION", n, 3, false, name);
  if (!plain) return Error{plain.error()};
  std::vector<glm::dvec3> out;
  if (*plain) {
    for (size_t k = 0; k < n; ++k)
      out.emplace_back((**plain)[3 * k], (**plain)[3 * k + 1], (**plain)[3 * k + 2]);
    return out;
  }
  auto quantized = t.numbers("POSITION_QUANTIZED", n, 3, true, name);
  auto offset = t.numbers("QUANTIZED_VOLUME_OFFSET", 1, 3, false, name);
  auto scale = t.numbers("QUANTIZED_VOLUME_SCALE", 1, 3, false, name);
  if (!quantized || !offset || !scale) return makeError(name + ": malformed quantized positions");
  if (!*quantized || !*offset || !*scale) return makeError(name + ": instances without POSITION");
  for (size_t k = 0; k < n; ++k) {
    glm::dvec3 p;
    for (int c = 0; c < 3; ++c)
      p[c] = (**offset)[c] + (**quantized)[3 * k + c] / 65535.0 * (**scale)[c];
    out.push_back(p);
  }
  return out;
}

// Instance k's placement: translation, rotation (right, up, right × up; or east, north, up),
// scale.
glm::dmat4 instanceMatrix(const glm::dvec3& position, const Orientations& o, size_t k,
                          const glm::dvec3& scale, const geo::Ellipsoid& ellipsoid) {
  glm::dmat4 m(1.0);
  if (o.up && o.right) {
    const glm::dvec3 up((*o.up)[3 * k], (*o.up)[3 * k + 1], (*o.up)[3 * k + 2]);
    const glm::dvec3 right((*o.right)[3 * k], (*o.right)[3 * k + 1], (*o.right)[3 * k + 2]);
    m[0] = glm::dvec4(right, 0), m[1] = glm::dvec4(up, 0),
    m[2] = glm::dvec4(glm::cross(right, up), 0);
  } else if (o.eastNorthUp) {
    const glm::dvec3 up = geo::geodeticSurfaceNormal(ellipsoid, position);
    glm::dvec3 east = glm::cross(glm::dvec3(0, 0, 1), up);
    east = glm::length(east) > 1e-12 ? glm::normalize(east) : glm::dvec3(0, 1, 0);
    m[0] = glm::dvec4(east, 0), m[1] = glm::dvec4(glm::cross(up, east), 0),
    m[2] = glm::dvec4(up, 0);
  }
  m[3] = glm::dvec4(position, 1);
  return m * glm::scale(glm::dmat4(1.0), scale);
}

Result<TriangleMesh> readInstanced(std::span<const std::byte> bytes,
                                   const geo::Ellipsoid& ellipsoid, const std::string& name) {
  auto s = sectionsOf(bytes, 32, name);
  if (!s) return Error{s.error()};
  if (u32(bytes, 28) != 1) return makeError(name + ": an i3dm naming an external glTF (not read)");
  // A whole number up to 2^24 (the triangle bound below stops far fewer instances of a model).
  const double instances = numberOr(s->features.json, "INSTANCES_LENGTH", 0.0);
  if (!(instances >= 0 && instances <= double(kMaxInstances) &&
        std::floor(instances) == instances)) {
    return makeError(name + ": INSTANCES_LENGTH is not a whole number in 0.." +
                     std::to_string(kMaxInstances));
  }
  const auto n = static_cast<size_t>(instances);
  auto model = readGltfTriangles(s->payload, name);
  if (!model) return model;
  if (n * model->positions.size() / 3 > kMaxInstancedTriangles) {
    return makeError(name + ": more than " + std::to_string(kMaxInstancedTriangles) + " triangles");
  }
  auto positions = instancePositions(s->features, n, name);
  auto orientations = orientationsOf(s->features, n, name);
  auto rtc = rtcCenter(s->features, name);
  auto scales = s->features.numbers("SCALE", n, 1, false, name);
  auto nonUniform = s->features.numbers("SCALE_NON_UNIFORM", n, 3, false, name);
  if (!positions) return Error{positions.error()};
  if (!orientations || !rtc || !scales || !nonUniform)
    return makeError(name + ": a malformed instance property");
  TriangleMesh mesh;
  for (size_t k = 0; k < n; ++k) {
    glm::dvec3 scale(1.0);
    if (*scales) scale = glm::dvec3((**scales)[k]);
    if (*nonUniform)
      scale =
          glm::dvec3((**nonUniform)[3 * k], (**nonUniform)[3 * k + 1], (**nonUniform)[3 * k + 2]);
    const glm::dvec3 at = (*positions)[k] + *rtc;
    const glm::dmat4 m = instanceMatrix(at, *orientations, k, scale, ellipsoid);
    mesh.append(*model, m);
  }
  mesh.pointPrimitives = model->pointPrimitives;
  return mesh;
}

Result<TriangleMesh> readComposite(std::span<const std::byte> bytes,
                                   const geo::Ellipsoid& ellipsoid, const std::string& name,
                                   int depth) {
  if (bytes.size() < 16) return makeError(name + ": shorter than its header");
  if (depth > kMaxCompositeDepth) return makeError(name + ": composites nested too deep");
  const uint32_t tiles = u32(bytes, 12);
  TriangleMesh mesh;
  size_t at = 16;
  for (uint32_t t = 0; t < tiles; ++t) {
    if (bytes.size() - at < 12)
      return makeError(name + ": inner tile " + std::to_string(t) + " past its end");
    const uint32_t length = u32(bytes, at + 8);
    if (length < 12 || length > bytes.size() - at) {
      return makeError(name + ": inner tile " + std::to_string(t) + " of a wrong length");
    }
    auto inner = readContent(bytes.subspan(at, length), ellipsoid,
                             name + " (inner tile " + std::to_string(t) + ")", depth + 1);
    if (!inner) return inner;
    mesh.append(*inner, glm::dmat4(1.0));
    if (mesh.triangleCount() > kMaxInstancedTriangles)
      return makeError(name + ": too many triangles");
    at += length;
  }
  return mesh;
}

Result<TriangleMesh> readContent(std::span<const std::byte> bytes, const geo::Ellipsoid& ellipsoid,
                                 const std::string& name, int depth) {
  const std::string magic =
      bytes.size() >= 4 ? std::string(reinterpret_cast<const char*>(bytes.data()), 4) : "";
  if (magic == "b3dm") return readBatched(bytes, name);
  if (magic == "i3dm") return readInstanced(bytes, ellipsoid, name);
  if (magic == "cmpt") return readComposite(bytes, ellipsoid, name, depth);
  if (magic == "pnts") {
    TriangleMesh points;
    points.pointPrimitives = 1;
    return points;
  }
  if (magic == "glTF" || (!bytes.empty() && static_cast<char>(bytes[0]) == '{')) {
    return readGltfTriangles(bytes, name);
  }
  return makeError(name + ": not a 3D Tiles content (b3dm, i3dm, cmpt, pnts, glb or glTF)");
}

}  // namespace

Result<TriangleMesh> readTileContent(std::span<const std::byte> bytes,
                                     const glm::dmat4& tileTransform,
                                     const geo::Ellipsoid& ellipsoid, const std::string& name) {
  // (Instances' east-north-up frames are taken at their positions in the content's frame: the
  // world's where, as usual with them, the tile has no transform.)
  auto mesh = readContent(bytes, ellipsoid, name, 0);
  if (!mesh) return mesh;
  mesh->transform(tileTransform);
  return mesh;
}

}  // namespace globe::tiles3d
