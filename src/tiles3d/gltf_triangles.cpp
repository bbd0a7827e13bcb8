#include "tiles3d/gltf_triangles.hpp"

#include <tiny_gltf.h>

#include <cstring>
#include <functional>
#include <optional>

#include <glm/ext/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>

#include "formats/image_io.hpp"
#include "tiles3d/gltf_load.hpp"

namespace globe::tiles3d {
namespace {

// Past these a model is refused: a small file that decodes (Draco) into a flood of triangles, or
// a node graph with a cycle.
constexpr size_t kMaxTriangles = size_t{8} << 20;
constexpr int kMaxNodeDepth = 64;

// glTF's y-up turned to z-up (3D Tiles: a rotation of π/2 about x).
const glm::dmat4 kYUpToZUp(1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1);

// Images decoded by the project's decoders (stb_image, libwebp), each at most 4096² a side; one
// that will not decode (larger, KTX2/Basis) leaves its triangles in their base colour alone.
struct DecodedImages {
  std::vector<std::shared_ptr<const MeshTexture>> byIndex;
};
bool decodeImage(tinygltf::Image*, const int index, std::string*, std::string*, int, int,
                 const unsigned char* bytes, int size, void* user) {
  auto& images = static_cast<DecodedImages*>(user)->byIndex;
  if (index < 0 || size <= 0) return true;
  if (images.size() <= static_cast<size_t>(index)) images.resize(static_cast<size_t>(index) + 1);
  auto decoded = formats::decodeImageRgba(
      std::span(reinterpret_cast<const std::byte*>(bytes), static_cast<size_t>(size)), "image");
  if (!decoded) return true;  // untextured, not fatal
  auto texture = std::make_shared<MeshTexture>();
  texture->widthPixels = decoded->widthPixels;
  texture->heightPixels = decoded->heightPixels;
  texture->rgba = std::move(decoded->pixels);
  images[static_cast<size_t>(index)] = std::move(texture);
  return true;
}

// A glTF's external files are not read: its buffers must be inside it (GLB, data URIs).
bool noFileExists(const std::string&, void*) { return false; }
std::string sameName(const std::string& path, void*) { return path; }
bool refuseRead(std::vector<unsigned char>*, std::string* err, const std::string& path, void*) {
  if (err != nullptr) *err += "an external file (" + path + ") is not read";
  return false;
}
bool refuseWrite(std::string*, const std::string&, const std::vector<unsigned char>&, void*) {
  return false;
}

// Element i of an accessor: its components as doubles (normalized integers scaled as glTF says).
class Accessor {
 public:
  static Result<Accessor> open(const tinygltf::Model& model, int index, const std::string& name) {
    if (index < 0 || static_cast<size_t>(index) >= model.accessors.size()) {
      return makeError(name + ": an accessor index out of range");
    }
    Accessor a;
    a.accessor_ = &model.accessors[static_cast<size_t>(index)];
    a.components_ = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.accessor_->type));
    a.componentBytes_ =
        tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.accessor_->componentType));
    if (a.components_ <= 0 || a.componentBytes_ <= 0) {
      return makeError(name + ": an accessor of an unknown type");
    }
    if (a.accessor_->bufferView < 0) return a;  // all zeros
    if (static_cast<size_t>(a.accessor_->bufferView) >= model.bufferViews.size()) {
      return makeError(name + ": a buffer view index out of range");
    }
    const auto& view = model.bufferViews[static_cast<size_t>(a.accessor_->bufferView)];
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size()) {
      return makeError(name + ": a buffer index out of range");
    }
    const auto& data = model.buffers[static_cast<size_t>(view.buffer)].data;
    const size_t element = size_t(a.components_) * size_t(a.componentBytes_);
    a.stride_ = view.byteStride > 0 ? view.byteStride : element;
    const size_t start = view.byteOffset + a.accessor_->byteOffset;
    // count from the JSON may be near 2^64: bounded by the view before it is multiplied.
    const size_t count = a.accessor_->count;
    const bool fits = count == 0 || (a.accessor_->byteOffset <= view.byteLength &&
                                     count - 1 <= view.byteLength / a.stride_);
    const size_t needed =
        count == 0 || !fits ? 0 : a.accessor_->byteOffset + a.stride_ * (count - 1) + element;
    if (!fits || view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset ||
        needed > view.byteLength) {
      return makeError(name + ": an accessor reaches past its buffer");
    }
    a.bytes_ = data.data() + start;
    return a;
  }

  size_t count() const { return accessor_->count; }
  double component(size_t i, int c) const {
    if (bytes_ == nullptr) return 0;
    const unsigned char* p = bytes_ + i * stride_ + size_t(c) * size_t(componentBytes_);
    return decode(p);
  }
  glm::dvec3 vec3(size_t i) const { return {component(i, 0), component(i, 1), component(i, 2)}; }
  int components() const { return components_; }

 private:
  template <typename T>
  static T load(const unsigned char* p) {
    T value;
    std::memcpy(&value, p, sizeof value);
    return value;
  }
  double decode(const unsigned char* p) const {
    const bool n = accessor_->normalized;
    switch (accessor_->componentType) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return load<float>(p);
      case TINYGLTF_COMPONENT_TYPE_DOUBLE:
        return load<double>(p);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return load<uint32_t>(p);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return n ? load<uint16_t>(p) / 65535.0 : load<uint16_t>(p);
      case TINYGLTF_COMPONENT_TYPE_SHORT:
        return n ? std::max(load<int16_t>(p) / 32767.0, -1.0) : load<int16_t>(p);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return n ? load<uint8_t>(p) / 255.0 : load<uint8_t>(p);
      case TINYGLTF_COMPONENT_TYPE_BYTE:
        return n ? std::max(load<int8_t>(p) / 127.0, -1.0) : load<int8_t>(p);
      default:
        return 0;
    }
  }

  const tinygltf::Accessor* accessor_ = nullptr;
  const unsigned char* bytes_ = nullptr;
  size_t stride_ = 0;
  int components_ = 0, componentBytes_ = 0;
};

glm::dmat4 localMatrix(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    glm::dmat4 m;
    for (int k = 0; k < 16; ++k) m[k / 4][k % 4] = node.matrix[static_cast<size_t>(k)];
    return m;
  }
  glm::dmat4 m(1.0);
  if (node.translation.size() == 3) {
    m = glm::translate(m,
                       glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
  }
  if (node.rotation.size() == 4) {
    m *= glm::mat4_cast(
        glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
  }
  if (node.scale.size() == 3)
    m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
  return m;
}

// The vertex indices of triangle t of a primitive in `mode`, from its index list.
void triangleCorners(int mode, size_t t, size_t out[3]) {
  if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    out[0] = t, out[1] = t % 2 == 0 ? t + 1 : t + 2, out[2] = t % 2 == 0 ? t + 2 : t + 1;
  } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
    out[0] = 0, out[1] = t + 1, out[2] = t + 2;
  } else {
    out[0] = 3 * t, out[1] = 3 * t + 1, out[2] = 3 * t + 2;
  }
}

// The primitive's surface: its material's base colour and texture, and which TEXCOORD it reads.
struct PrimitiveSurface {
  SurfacePart part;
  std::string texcoord;  // "" when untextured
};
PrimitiveSurface surfaceOf(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                           const DecodedImages& images) {
  PrimitiveSurface surface;
  if (primitive.material < 0 || static_cast<size_t>(primitive.material) >= model.materials.size())
    return surface;
  const auto& material = model.materials[static_cast<size_t>(primitive.material)];
  const auto& pbr = material.pbrMetallicRoughness;
  if (material.alphaMode == "MASK")
    surface.part.alphaCutoff = static_cast<float>(material.alphaCutoff);
  if (material.alphaMode == "BLEND") surface.part.alphaCutoff = 0.5f;
  if (pbr.baseColorFactor.size() == 4) {
    for (int c = 0; c < 4; ++c)
      surface.part.baseColor[c] = static_cast<float>(pbr.baseColorFactor[static_cast<size_t>(c)]);
  }
  const int t = pbr.baseColorTexture.index;
  if (t < 0 || static_cast<size_t>(t) >= model.textures.size()) return surface;
  const int source = model.textures[static_cast<size_t>(t)].source;
  if (source < 0 || static_cast<size_t>(source) >= images.byIndex.size()) return surface;
  surface.part.texture = images.byIndex[static_cast<size_t>(source)];
  if (surface.part.texture)
    surface.texcoord = "TEXCOORD_" + std::to_string(std::max(pbr.baseColorTexture.texCoord, 0));
  return surface;
}

// An optional attribute of `components` components, or nullopt when the primitive has none.
Result<std::optional<Accessor>> attribute(const tinygltf::Model& model,
                                          const tinygltf::Primitive& primitive,
                                          const std::string& key, int components,
                                          const std::string& name) {
  const auto it = primitive.attributes.find(key);
  if (key.empty() || it == primitive.attributes.end()) return std::optional<Accessor>();
  auto opened = Accessor::open(model, it->second, name);
  if (!opened) return Error{opened.error()};
  if (opened->components() != components) return std::optional<Accessor>();  // read past
  return std::optional<Accessor>(*opened);
}

Result<void> addPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                          const glm::dmat4& toModel, const DecodedImages& images,
                          const std::string& name, TriangleMesh& mesh) {
  const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
  const auto position = primitive.attributes.find("POSITION");
  if (mode < TINYGLTF_MODE_TRIANGLES || position == primitive.attributes.end()) {
    ++mesh.pointPrimitives;
    return {};
  }
  auto positions = Accessor::open(model, position->second, name);
  if (!positions) return Error{positions.error()};
  if (positions->components() != 3) return makeError(name + ": POSITION is not a VEC3");
  std::optional<Accessor> indices;
  if (primitive.indices >= 0) {
    auto opened = Accessor::open(model, primitive.indices, name);
    if (!opened) return Error{opened.error()};
    indices = *opened;
  }
  const size_t corners = indices ? indices->count() : positions->count();
  const size_t triangles = mode == TINYGLTF_MODE_TRIANGLES ? corners / 3
                           : corners >= 3                  ? corners - 2
                                                           : 0;
  if (mesh.triangleCount() + triangles > kMaxTriangles) {
    return makeError(name + ": more than " + std::to_string(kMaxTriangles) + " triangles");
  }
  const PrimitiveSurface surface = surfaceOf(model, primitive, images);
  auto normals = attribute(model, primitive, "NORMAL", 3, name);
  auto uvs = attribute(model, primitive, surface.texcoord, 2, name);
  if (!normals) return Error{normals.error()};
  if (!uvs) return Error{uvs.error()};
  const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(toModel)));
  const auto part = static_cast<uint32_t>(mesh.parts.size());
  mesh.parts.push_back(surface.part);
  for (size_t t = 0; t < triangles; ++t) {
    size_t c[3];
    triangleCorners(mode, t, c);
    for (const size_t k : c) {
      const double v = indices ? indices->component(k, 0) : static_cast<double>(k);
      if (!(v >= 0 && v < static_cast<double>(positions->count()))) {
        return makeError(name + ": a vertex index past its positions");
      }
      const auto i = static_cast<size_t>(v);
      mesh.positions.push_back(glm::dvec3(toModel * glm::dvec4(positions->vec3(i), 1.0)));
      const bool hasNormal = *normals && i < (*normals)->count();
      const glm::dvec3 n = hasNormal ? normalMatrix * (*normals)->vec3(i) : glm::dvec3(0.0);
      mesh.normals.push_back(glm::length(n) > 0 ? glm::vec3(glm::normalize(n)) : glm::vec3(0.0f));
      const bool hasUv = *uvs && i < (*uvs)->count();
      mesh.uvs.push_back(hasUv ? glm::vec2((*uvs)->component(i, 0), (*uvs)->component(i, 1))
                               : glm::vec2(0.0f));
    }
    mesh.triangleParts.push_back(part);
  }
  return {};
}

}  // namespace

Result<TriangleMesh> readGltfTriangles(std::span<const std::byte> bytes, const std::string& name) {
  tinygltf::TinyGLTF loader;
  DecodedImages images;
  loader.SetImageLoader(decodeImage, &images);
  loader.SetFsCallbacks({noFileExists, sameName, refuseRead, refuseWrite, nullptr});
  tinygltf::Model model;
  auto loaded = loadGltfModel(loader, bytes, name, model);
  if (!loaded) return Error{loaded.error()};
  TriangleMesh mesh;
  const int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : 0;
  std::vector<int> roots;
  if (static_cast<size_t>(sceneIndex) < model.scenes.size()) {
    roots = model.scenes[static_cast<size_t>(sceneIndex)].nodes;
  } else {
    for (size_t n = 0; n < model.nodes.size(); ++n) roots.push_back(static_cast<int>(n));
  }
  std::function<Result<void>(int, const glm::dmat4&, int)> visit =
      [&](int index, const glm::dmat4& parent, int depth) -> Result<void> {
    if (index < 0 || static_cast<size_t>(index) >= model.nodes.size()) {
      return makeError(name + ": a node index out of range");
    }
    if (depth > kMaxNodeDepth) return makeError(name + ": nodes nested too deep (a cycle?)");
    const tinygltf::Node& node = model.nodes[static_cast<size_t>(index)];
    const glm::dmat4 toModel = parent * localMatrix(node);
    if (node.mesh >= 0) {
      if (static_cast<size_t>(node.mesh) >= model.meshes.size()) {
        return makeError(name + ": a mesh index out of range");
      }
      for (const auto& primitive : model.meshes[static_cast<size_t>(node.mesh)].primitives) {
        auto added = addPrimitive(model, primitive, toModel, images, name, mesh);
        if (!added) return added;
      }
    }
    for (const int child : node.children) {
      auto done = visit(child, toModel, depth + 1);
      if (!done) return done;
    }
    return {};
  };
  for (const int root : roots) {
    auto done = visit(root, kYUpToZUp, 0);
    if (!done) return Error{done.error()};
  }
  return mesh;
}

}  // namespace globe::tiles3d
