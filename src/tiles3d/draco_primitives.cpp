#include "tiles3d/draco_primitives.hpp"

#include <draco/compression/decode.h>
#include <tiny_gltf.h>

#include <cstring>
#include <nlohmann/json.hpp>

namespace globe::tiles3d {
namespace {

using nlohmann::json;

constexpr uint64_t kMaxCorners = uint64_t{3} * (uint64_t{8} << 20);  // 8 M triangles
constexpr uint64_t kMaxAttributeBytes = uint64_t{256} << 20;
const char* const kDraco = "KHR_draco_mesh_compression";

// The primitive's Draco extension read (bufferView, attribute ids) or an error.
Result<DracoPrimitive> readExtension(const json& draco, size_t mesh, size_t primitive,
                                     const std::string& name) {
  const std::string where = name + ": mesh " + std::to_string(mesh) + " primitive " +
                            std::to_string(primitive) + " (Draco)";
  DracoPrimitive out;
  out.mesh = mesh, out.primitive = primitive;
  const auto view = draco.is_object() ? draco.find("bufferView") : draco.end();
  const auto attributes = draco.is_object() ? draco.find("attributes") : draco.end();
  if (view == draco.end() || !view->is_number_integer() || attributes == draco.end() ||
      !attributes->is_object()) {
    return makeError(where + ": no bufferView or attributes");
  }
  out.bufferView = view->get<int64_t>();
  for (const auto& [key, id] : attributes->items()) {
    if (!id.is_number_integer()) return makeError(where + ": attribute " + key + " not an id");
    out.attributes.emplace_back(key, id.get<int64_t>());
  }
  return out;
}

template <typename T>
void appendBytes(std::vector<unsigned char>& out, const T* values, size_t count) {
  const size_t at = out.size();
  out.resize(at + count * sizeof(T));
  if (count > 0) std::memcpy(out.data() + at, values, count * sizeof(T));
}

// `bytes` as a new buffer and view; the accessor pointed at it as `componentType` × `count`.
void pointAccessor(tinygltf::Model& model, tinygltf::Accessor& accessor,
                   std::vector<unsigned char> bytes, int componentType, size_t count) {
  tinygltf::Buffer buffer;
  buffer.data = std::move(bytes);
  tinygltf::BufferView view;
  view.buffer = static_cast<int>(model.buffers.size());
  view.byteLength = buffer.data.size();
  model.buffers.push_back(std::move(buffer));
  accessor.bufferView = static_cast<int>(model.bufferViews.size());
  model.bufferViews.push_back(view);
  accessor.byteOffset = 0;
  accessor.componentType = componentType;
  accessor.normalized = false;
  accessor.count = count;
  accessor.sparse.isSparse = false;
}

Result<void> decodeIndices(const draco::Mesh& mesh, tinygltf::Accessor& accessor,
                           tinygltf::Model& model) {
  std::vector<uint32_t> corners;
  corners.reserve(size_t{mesh.num_faces()} * 3);
  for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f) {
    for (int c = 0; c < 3; ++c) corners.push_back(mesh.face(f)[c].value());
  }
  std::vector<unsigned char> bytes;
  appendBytes(bytes, corners.data(), corners.size());
  pointAccessor(model, accessor, std::move(bytes), TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                corners.size());
  return {};
}

Result<void> decodeAttribute(const draco::Mesh& mesh, const draco::PointAttribute& attribute,
                             tinygltf::Accessor& accessor, tinygltf::Model& model,
                             const std::string& where) {
  const int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(accessor.type));
  if (components <= 0 || components != attribute.num_components()) {
    return makeError(where + ": its components disagree with its accessor's type");
  }
  const uint64_t bytes = uint64_t{mesh.num_points()} * uint64_t(components) * 4;
  if (bytes > kMaxAttributeBytes) return makeError(where + ": decodes past 256 MiB");
  std::vector<float> values(size_t{mesh.num_points()} * size_t(components));
  for (draco::PointIndex p(0); p < mesh.num_points(); ++p) {
    if (!attribute.ConvertValue<float>(attribute.mapped_index(p), static_cast<int8_t>(components),
                                       values.data() + size_t{p.value()} * size_t(components))) {
      return makeError(where + ": a value that will not convert to float");
    }
  }
  std::vector<unsigned char> out;
  appendBytes(out, values.data(), values.size());
  pointAccessor(model, accessor, std::move(out), TINYGLTF_COMPONENT_TYPE_FLOAT, mesh.num_points());
  return {};
}

// The compressed bytes of `view`, inside its buffer, or an error.
Result<std::pair<const char*, size_t>> viewBytes(const tinygltf::Model& model, int64_t index,
                                                 const std::string& where) {
  if (index < 0 || static_cast<uint64_t>(index) >= model.bufferViews.size()) {
    return makeError(where + ": its bufferView out of range");
  }
  const auto& view = model.bufferViews[static_cast<size_t>(index)];
  if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size()) {
    return makeError(where + ": its bufferView's buffer out of range");
  }
  const auto& data = model.buffers[static_cast<size_t>(view.buffer)].data;
  if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset) {
    return makeError(where + ": its bufferView reaches past its buffer");
  }
  return std::pair(reinterpret_cast<const char*>(data.data() + view.byteOffset), view.byteLength);
}

Result<void> decodePrimitive(const DracoPrimitive& d, tinygltf::Model& model,
                             const std::string& name) {
  const std::string where = name + ": mesh " + std::to_string(d.mesh) + " primitive " +
                            std::to_string(d.primitive) + " (Draco)";
  if (d.mesh >= model.meshes.size() || d.primitive >= model.meshes[d.mesh].primitives.size()) {
    return makeError(where + ": not in the model");
  }
  auto bytes = viewBytes(model, d.bufferView, where);
  if (!bytes) return Error{bytes.error()};
  draco::DecoderBuffer buffer;
  buffer.Init(bytes->first, bytes->second);
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
  if (!decoded.ok() || decoded.value() == nullptr) {
    return makeError(where + ": will not decode (" + decoded.status().error_msg_string() + ")");
  }
  const draco::Mesh& mesh = *decoded.value();
  if (uint64_t{mesh.num_faces()} * 3 > kMaxCorners) {
    return makeError(where + ": more than 8388608 triangles");
  }
  tinygltf::Primitive& primitive = model.meshes[d.mesh].primitives[d.primitive];
  const auto accessor = [&](int index) -> tinygltf::Accessor* {
    if (index < 0 || static_cast<size_t>(index) >= model.accessors.size()) return nullptr;
    return &model.accessors[static_cast<size_t>(index)];
  };
  if (primitive.indices >= 0) {
    tinygltf::Accessor* indices = accessor(primitive.indices);
    if (indices == nullptr) return makeError(where + ": its indices accessor out of range");
    auto done = decodeIndices(mesh, *indices, model);
    if (!done) return done;
  }
  for (const auto& [key, id] : d.attributes) {
    const auto it = primitive.attributes.find(key);
    if (it == primitive.attributes.end()) continue;  // not an attribute of the primitive
    tinygltf::Accessor* target = accessor(it->second);
    const draco::PointAttribute* attribute =
        id >= 0 && id <= int64_t{UINT32_MAX}
            ? mesh.GetAttributeByUniqueId(static_cast<uint32_t>(id))
            : nullptr;
    if (target == nullptr || attribute == nullptr) {
      return makeError(where + ": attribute " + key + " has no accessor or no Draco attribute " +
                       std::to_string(id));
    }
    auto done = decodeAttribute(mesh, *attribute, *target, model, where + " " + key);
    if (!done) return done;
  }
  return {};
}

// tinygltf wants a primitive's indices accessor to have a bufferView when it has read the mesh
// (its own Draco decoding would have set one): the compressed view stands in until decoded.
void lendIndicesTheView(json& gltf, const json& primitive, int64_t bufferView) {
  const auto indices = primitive.find("indices");
  const auto accessors = gltf.find("accessors");
  if (indices == primitive.end() || !indices->is_number_integer() || accessors == gltf.end() ||
      !accessors->is_array() || bufferView < 0) {
    return;
  }
  const auto index = indices->get<int64_t>();
  if (index < 0 || static_cast<uint64_t>(index) >= accessors->size()) return;
  json& accessor = (*accessors)[static_cast<size_t>(index)];
  if (accessor.is_object() && !accessor.contains("bufferView")) accessor["bufferView"] = bufferView;
}

}  // namespace

Result<std::vector<DracoPrimitive>> takeDracoPrimitives(json& gltf, const std::string& name) {
  std::vector<DracoPrimitive> out;
  const auto meshes = gltf.find("meshes");
  if (meshes == gltf.end() || !meshes->is_array()) return out;
  for (size_t m = 0; m < meshes->size(); ++m) {
    json& mesh = (*meshes)[m];
    const auto primitives = mesh.is_object() ? mesh.find("primitives") : mesh.end();
    if (primitives == mesh.end() || !primitives->is_array()) continue;
    for (size_t p = 0; p < primitives->size(); ++p) {
      json& primitive = (*primitives)[p];
      const auto extensions =
          primitive.is_object() ? primitive.find("extensions") : primitive.end();
      if (extensions == primitive.end() || !extensions->is_object()) continue;
      const auto draco = extensions->find(kDraco);
      if (draco == extensions->end()) continue;
      auto read = readExtension(*draco, m, p, name);
      if (!read) return Error{read.error()};
      extensions->erase(draco);
      lendIndicesTheView(gltf, primitive, read->bufferView);
      out.push_back(std::move(*read));
    }
  }
  return out;
}

Result<void> decodeDracoPrimitives(const std::vector<DracoPrimitive>& primitives,
                                   tinygltf::Model& model, const std::string& name) {
  for (const DracoPrimitive& d : primitives) {
    auto done = decodePrimitive(d, model, name);
    if (!done) return done;
  }
  return {};
}

}  // namespace globe::tiles3d
