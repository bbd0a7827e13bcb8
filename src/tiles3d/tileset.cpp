#include "tiles3d/tileset.hpp"

#include <nlohmann/json.hpp>

#include "transport/atomic_file.hpp"

namespace globe::tiles3d {
namespace {

constexpr uint64_t kMaxTilesetBytes = uint64_t{64} << 20;
constexpr size_t kMaxTiles = 1'000'000;
constexpr int kMaxDepth = 64;  // nested tiles and external tilesets together
constexpr int kMaxExternalTilesets = 1000;

namespace fs = std::filesystem;

struct Reader {
  fs::path root;  // the first tileset's folder: everything must lie under it
  Tileset& out;
  int externals = 0;

  // A content URI as a file under the root, or the reason it is not read.
  Result<fs::path> resolve(const fs::path& base, const std::string& uri) const {
    if (uri.rfind("data:", 0) == 0) return makeError("a data URI (not read)");
    if (uri.find("://") != std::string::npos) return makeError("a URL (not read from a folder)");
    const std::string plain = uri.substr(0, uri.find_first_of("?#"));
    const fs::path relative(plain);
    if (relative.is_absolute()) return makeError("an absolute path");
    const fs::path file = (base / relative).lexically_normal();
    const auto inside = file.lexically_relative(root);
    if (inside.empty() || *inside.begin() == "..") return makeError("outside the tileset's folder");
    return file;
  }

  Result<TileNode> tile(const nlohmann::json& j, const fs::path& base, const glm::dmat4& parent,
                        bool parentAdditive, int depth, const std::string& name);
  Result<TileNode> external(const fs::path& file, const glm::dmat4& parent, bool additive,
                            int depth);
};

Result<nlohmann::json> parseFile(const fs::path& file) {
  auto bytes = transport::readWholeFile(file, kMaxTilesetBytes);
  if (!bytes) return Error{bytes.error()};
  try {
    const auto* text = reinterpret_cast<const char*>(bytes->data());
    return nlohmann::json::parse(text, text + bytes->size());
  } catch (const nlohmann::json::exception& e) {
    return makeError(file.string() + ": not JSON (" + e.what() + ")");
  }
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
  if (j.contains("implicitTiling"))
    return makeError(name + ": implicit tiling (3D Tiles 1.1) is not read yet");
  TileNode node;
  auto transform = transformOf(j, name);
  if (!transform) return Error{transform.error()};
  node.transform = parent * *transform;
  node.geometricErrorMeters = j.value("geometricError", 0.0);
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
    if (file->extension() == ".json") {
      auto sub = external(*file, node.transform, node.additive, depth + 1);
      if (!sub) return sub;
      node.children.push_back(std::move(*sub));
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

Result<TileNode> Reader::external(const fs::path& file, const glm::dmat4& parent, bool additive,
                                  int depth) {
  if (++externals > kMaxExternalTilesets)
    return makeError(file.string() + ": too many external tilesets");
  auto j = parseFile(file);
  if (!j) return Error{j.error()};
  if (!j->is_object() || !j->contains("root"))
    return makeError(file.string() + ": a tileset without a root");
  return tile((*j)["root"], file.parent_path(), parent, additive, depth, file.string());
}

}  // namespace

Result<Tileset> readTileset(const fs::path& path) {
  Tileset tileset;
  tileset.file = fs::absolute(fs::is_directory(path) ? path / "tileset.json" : path);
  auto j = parseFile(tileset.file);
  if (!j) return Error{j.error()};
  const std::string name = tileset.file.string();
  if (!j->is_object() || !j->contains("asset") || !j->contains("root")) {
    return makeError(name + ": not a 3D Tiles tileset (no asset or root)");
  }
  const std::string version = (*j)["asset"].is_object() ? (*j)["asset"].value("version", "") : "";
  if (version != "1.0" && version != "1.1" && version != "0.0") {
    tileset.warnings.push_back(name + ": asset version '" + version + "' (read as 1.1)");
  }
  Reader reader{tileset.file.parent_path().lexically_normal(), tileset};
  auto root = reader.tile((*j)["root"], reader.root, glm::dmat4(1.0), false, 0, name);
  if (!root) return Error{root.error()};
  tileset.root = std::move(*root);
  return tileset;
}

}  // namespace globe::tiles3d
