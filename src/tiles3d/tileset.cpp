#include "tiles3d/tileset.hpp"

#include <algorithm>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "tiles3d/implicit_tiling.hpp"

namespace globe::tiles3d {
namespace {

constexpr size_t kMaxTiles = 1'000'000;
constexpr int kMaxDepth = 64;  // nested tiles and external tilesets together
constexpr int kMaxExternalTilesets = 1000;

namespace fs = std::filesystem;

struct Reader {
  Tileset& out;
  const geo::Ellipsoid& ellipsoid;
  int externals = 0;

  // A content URI as a name in the source (relative to its folder), or why it is not read.
  // `base`: the folder (in the source) of the tileset.json that names it.
  static Result<std::string> resolve(const fs::path& base, const std::string& uri) {
    if (uri.rfind("data:", 0) == 0) return makeError("a data URI (not read)");
    if (uri.find("://") != std::string::npos) return makeError("a URL (not read from a folder)");
    const std::string plain = uri.substr(0, uri.find_first_of("?#"));
    const fs::path relative(plain);
    if (plain.empty() || relative.has_root_path()) return makeError("an absolute path or none");
    const fs::path file = (base / relative).lexically_normal();
    if (file.empty() || *file.begin() == ".." || file.has_root_path())
      return makeError("outside the tileset's folder");
    return file.generic_string();
  }
  Result<nlohmann::json> parse(const std::string& name) const;

  Result<TileNode> tile(const nlohmann::json& j, const fs::path& base, const glm::dmat4& parent,
                        bool parentAdditive, int depth, const std::string& name);
  Result<TileNode> external(const std::string& file, const glm::dmat4& parent, bool additive,
                            int depth);
};

Result<nlohmann::json> Reader::parse(const std::string& name) const {
  auto bytes = out.source->readWhole(name, kMaxTilesetBytes);
  const std::string where = out.source->locationOf(name);
  if (!bytes) return Error{bytes.error()};
  if (!*bytes) return makeError(where + ": no such file");
  try {
    const auto* text = reinterpret_cast<const char*>((*bytes)->data());
    return nlohmann::json::parse(text, text + (*bytes)->size());
  } catch (const nlohmann::json::exception& e) {
    return makeError(where + ": not JSON (" + e.what() + ")");
  }
}

double largestStretch(const glm::dmat4& m) {
  return std::max({glm::length(glm::dvec3(m[0])), glm::length(glm::dvec3(m[1])),
                   glm::length(glm::dvec3(m[2]))});
}

Result<glm::dmat4> transformOf(const nlohmann::json& j, const std::string& name) {
  glm::dmat4 m(1.0);
  const auto t = j.find("transform");
  if (t == j.end()) return m;
  if (!t->is_array() || t->size() != 16)
    return makeError(name + ": a transform of other than 16 numbers");
  for (int k = 0; k < 16; ++k) {
    const auto& v = (*t)[static_cast<size_t>(k)];
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      return makeError(name + ": a transform that is not finite");
    m[k / 4][k % 4] = v.get<double>();  // column-major, as glTF
  }
  return m;
}

Result<TileNode> Reader::tile(const nlohmann::json& j, const fs::path& base,
                              const glm::dmat4& parent, bool parentAdditive, int depth,
                              const std::string& name) {
  if (!j.is_object()) return makeError(name + ": a tile that is not an object");
  if (depth > kMaxDepth)
    return makeError(name + ": tiles nested deeper than " + std::to_string(kMaxDepth));
  if (++out.tileCount > kMaxTiles)
    return makeError(name + ": more than " + std::to_string(kMaxTiles) + " tiles");
  if (j.contains("implicitTiling")) {  // expanded into explicit tiles, read as those
    const ReadRelativeFile read = [&](const std::string& uri) {
      auto file = resolve(base, uri);
      if (!file) return Result<std::optional<std::vector<std::byte>>>(Error{file.error()});
      return out.source->readWhole(*file, kMaxTilesetBytes);
    };
    auto expanded = expandImplicitTiling(j, read, kMaxTiles - out.tileCount + 1, name);
    if (!expanded) return Error{expanded.error()};
    --out.tileCount;  // counted again as the expanded root
    return tile(*expanded, base, parent, parentAdditive, depth, name);
  }
  TileNode node;
  auto transform = transformOf(j, name);
  if (!transform) return Error{transform.error()};
  node.transform = parent * *transform;
  auto bounds = boundingSphereOf(j.value("boundingVolume", nlohmann::json()), node.transform,
                                 ellipsoid, name);
  if (!bounds) return Error{bounds.error()};
  node.bounds = *bounds;
  // In the tile's frame: scaled by its transform's largest stretch, as CesiumJS does
  // (Cesium3DTile.updateGeometricErrorScale), so a model scaled up refines as it looks.
  node.geometricErrorMeters = j.value("geometricError", 0.0) * largestStretch(node.transform);
  const std::string refine = j.value("refine", "");
  node.additive = refine.empty() ? parentAdditive : refine == "ADD" || refine == "add";
  std::vector<nlohmann::json> contents;
  if (const auto c = j.find("content"); c != j.end()) contents.push_back(*c);
  if (const auto c = j.find("contents"); c != j.end() && c->is_array())
    contents.insert(contents.end(), c->begin(), c->end());
  for (const auto& content : contents) {
    const std::string uri =
        content.is_object() ? content.value("uri", content.value("url", "")) : "";
    auto file = resolve(base, uri);
    if (!file) {
      out.warnings.push_back(name + ": content '" + uri + "': " + file.error());
      continue;
    }
    if (fs::path(*file).extension() == ".json") {
      auto sub = external(*file, node.transform, node.additive, depth + 1);
      if (sub) {
        node.children.push_back(std::move(*sub));
      } else {  // drawn without it, as a content that is missing
        out.warnings.push_back(sub.error() + " (read past: its tiles are not drawn)");
      }
    } else {
      node.contents.push_back(*file);
    }
  }
  if (const auto children = j.find("children"); children != j.end() && children->is_array()) {
    for (const auto& child : *children) {
      auto c = tile(child, base, node.transform, node.additive, depth + 1, name);
      if (!c) return c;
      node.children.push_back(std::move(*c));
    }
  }
  return node;
}

Result<TileNode> Reader::external(const std::string& file, const glm::dmat4& parent, bool additive,
                                  int depth) {
  const std::string where = out.source->locationOf(file);
  if (++externals > kMaxExternalTilesets) return makeError(where + ": too many external tilesets");
  auto j = parse(file);
  if (!j) return Error{j.error()};
  if (!j->is_object() || !j->contains("root"))
    return makeError(where + ": a tileset without a root");
  return tile((*j)["root"], fs::path(file).parent_path(), parent, additive, depth, where);
}

}  // namespace

namespace {

Result<Tileset> readTilesetJson(std::shared_ptr<transport::ByteSource> source,
                                const std::string& name, const geo::Ellipsoid& ellipsoid) {
  Tileset tileset;
  tileset.source = std::move(source);
  tileset.file = tileset.source->locationOf(name);
  Reader reader{tileset, ellipsoid};
  auto j = reader.parse(name);
  if (!j) return Error{j.error()};
  if (!j->is_object() || !j->contains("asset") || !j->contains("root")) {
    return makeError(tileset.file + ": not a 3D Tiles tileset (no asset or root)");
  }
  const std::string version = (*j)["asset"].is_object() ? (*j)["asset"].value("version", "") : "";
  if (version != "1.0" && version != "1.1" && version != "0.0") {
    tileset.warnings.push_back(tileset.file + ": asset version '" + version + "' (read as 1.1)");
  }
  auto root = reader.tile((*j)["root"], fs::path(name).parent_path(), glm::dmat4(1.0), false, 0,
                          tileset.file);
  if (!root) return Error{root.error()};
  tileset.root = std::move(*root);
  return tileset;
}

}  // namespace

Result<Tileset> readTileset(std::shared_ptr<transport::ByteSource> source, const std::string& name,
                            const geo::Ellipsoid& ellipsoid) {
  const std::string where = source->locationOf(name);
  try {  // a field of the wrong type (a "geometricError" that is a string) throws in the reader
    return readTilesetJson(std::move(source), name, ellipsoid);
  } catch (const nlohmann::json::exception& e) {
    return makeError(where + ": a field of the wrong type (" + e.what() + ")");
  }
}

Result<Tileset> readTileset(const fs::path& path, const geo::Ellipsoid& ellipsoid) {
  const bool folder = fs::is_directory(path);
  const fs::path dir = fs::absolute(folder ? path : path.parent_path()).lexically_normal();
  return readTileset(transport::localByteSource(dir),
                     folder ? "tileset.json" : path.filename().string(), ellipsoid);
}

Result<Tileset> openTileset(const std::string& location, transport::Network* network,
                            const geo::Ellipsoid& ellipsoid) {
  const bool url = location.find("://") != std::string::npos;
  if (!url) return readTileset(fs::path(location), ellipsoid);
  const std::string path = location.substr(0, location.find_first_of("?#"));
  const bool file = path.size() > 5 && path.compare(path.size() - 5, 5, ".json") == 0;
  const size_t slash = path.find_last_of('/');
  const std::string dir = file ? path.substr(0, slash) : path;
  const std::string name = file ? path.substr(slash + 1) : "tileset.json";
  auto source = transport::openByteSource(dir, network);
  if (!source) return Error{source.error()};
  return readTileset(std::move(*source), name, ellipsoid);
}

void placeTileset(Tileset& tileset, const glm::dmat4& placement) {
  // A sphere and a geometric error through a scaling placement: by its largest stretch.
  const double scale = largestStretch(placement);
  std::vector<TileNode*> stack{&tileset.root};
  while (!stack.empty()) {
    TileNode* node = stack.back();
    stack.pop_back();
    node->transform = placement * node->transform;
    node->bounds.centerEcefMeters =
        glm::dvec3(placement * glm::dvec4(node->bounds.centerEcefMeters, 1.0));
    node->bounds.radiusMeters *= scale;
    node->geometricErrorMeters *= scale;
    for (TileNode& child : node->children) stack.push_back(&child);
  }
}

Result<std::vector<std::byte>> readContentBytes(const Tileset& tileset, const std::string& name) {
  auto bytes = tileset.source->readWhole(name, kMaxContentBytes);
  if (!bytes) return Error{bytes.error()};
  if (!*bytes) return makeError(tileset.source->locationOf(name) + ": no such file");
  return std::move(**bytes);
}

}  // namespace globe::tiles3d
