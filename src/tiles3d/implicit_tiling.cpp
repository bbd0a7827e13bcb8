#include "tiles3d/implicit_tiling.hpp"

#include <cmath>
#include <numbers>

namespace globe::tiles3d {
namespace {

using Json = nlohmann::json;
using MaybeJson = std::optional<Json>;

struct Coord {
  int level = 0;
  uint64_t x = 0, y = 0, z = 0;
  Coord child(uint64_t c) const {
    return {level + 1, 2 * x + (c & 1), 2 * y + ((c >> 1) & 1), 2 * z + ((c >> 2) & 1)};
  }
};

std::string substitute(std::string text, const Coord& c) {
  const std::pair<const char*, uint64_t> keys[] = {
      {"{level}", static_cast<uint64_t>(c.level)}, {"{x}", c.x}, {"{y}", c.y}, {"{z}", c.z}};
  for (const auto& [key, value] : keys) {
    const std::string v = std::to_string(value), k = key;
    for (size_t at = text.find(k); at != std::string::npos; at = text.find(k, at + v.size()))
      text.replace(at, k.size(), v);
  }
  return text;
}

// Reads a member that must be an integer in [low, high].
Result<int> levels(const Json& j, const char* key, int low, int high, const std::string& name) {
  const auto it = j.find(key);
  if (it == j.end() || !it->is_number_integer() || it->get<int64_t>() < low ||
      it->get<int64_t>() > high)
    return makeError(name + ": implicitTiling's " + key + " is not an integer from " +
                     std::to_string(low) + " to " + std::to_string(high));
  return static_cast<int>(it->get<int64_t>());
}

// The root's box or region as numbers, refused otherwise (S2 and spheres are not subdivided).
Result<std::vector<double>> rootVolume(const Json& tile, bool& box, const std::string& name) {
  const auto v = tile.find("boundingVolume");
  if (v == tile.end() || !v->is_object())
    return makeError(name + ": an implicit tile without a boundingVolume");
  if (const auto e = v->find("extensions");
      e != v->end() && e->is_object() && e->contains("3DTILES_bounding_volume_S2"))
    return makeError(name + ": implicit tiling of a 3DTILES_bounding_volume_S2 volume (not read)");
  box = v->contains("box");
  const auto numbers = v->find(box ? "box" : "region");
  const size_t size = box ? 12 : 6;
  if (numbers == v->end())
    return makeError(name + ": implicit tiling needs a box or region bounding volume");
  if (!numbers->is_array() || numbers->size() != size)
    return makeError(name + ": an implicit tile's " + (box ? "box" : "region") + " of other than " +
                     std::to_string(size) + " numbers");
  std::vector<double> out;
  for (const Json& n : *numbers) {
    if (!n.is_number() || !std::isfinite(n.get<double>()))
      return makeError(name + ": an implicit tile's bounding volume that is not finite");
    out.push_back(n.get<double>());
  }
  return out;
}

// The box of tile `c`: each split half-axis scaled by 2^-level, the centre moved to the cell.
Json subdivideBox(const std::vector<double>& b, const Coord& c, int dims) {
  const double s = std::ldexp(1.0, -c.level);
  std::vector<double> out = b;
  const uint64_t coord[3] = {c.x, c.y, c.z};
  for (int a = 0; a < dims; ++a) {
    const double t = -1.0 + (2.0 * static_cast<double>(coord[a]) + 1.0) * s;
    for (int k = 0; k < 3; ++k) {
      const size_t axis = 3 + 3 * static_cast<size_t>(a) + static_cast<size_t>(k);
      out[static_cast<size_t>(k)] += b[axis] * t;
      out[axis] = b[axis] * s;
    }
  }
  return {{"box", out}};
}

// The region of tile `c`: west-east by x, south-north by y, and (octree) heights by z.
Json subdivideRegion(const std::vector<double>& r, const Coord& c, int dims) {
  const double s = std::ldexp(1.0, -c.level), pi = std::numbers::pi;
  double width = r[2] - r[0];
  if (width < 0) width += 2 * pi;  // across the antimeridian
  const auto wrap = [&](double lon) { return lon > pi ? lon - 2 * pi : lon; };
  const auto x = static_cast<double>(c.x), y = static_cast<double>(c.y);
  const double west = wrap(r[0] + width * x * s), east = wrap(r[0] + width * (x + 1) * s);
  const double south = r[1] + (r[3] - r[1]) * y * s, north = r[1] + (r[3] - r[1]) * (y + 1) * s;
  double low = r[4], high = r[5];
  if (dims == 3) {
    const auto z = static_cast<double>(c.z);
    low = r[4] + (r[5] - r[4]) * z * s, high = r[4] + (r[5] - r[4]) * (z + 1) * s;
  }
  return {{"region", {west, south, east, north, low, high}}};
}

class Expander {
 public:
  Expander(const ReadRelativeFile& read, size_t maxTiles, const std::string& name)
      : read_(read), maxTiles_(maxTiles), name_(name) {}
  Result<Json> expand(const Json& tile);

 private:
  Result<void> readTemplate(const Json& tile);
  Result<MaybeJson> subtree(const Coord& c);
  Result<MaybeJson> tileAt(const Subtree& s, int local, uint64_t morton, const Coord& c);
  Result<void> children(const Subtree& s, int local, uint64_t morton, const Coord& c, Json& out);
  void addContents(const Subtree& s, uint64_t index, const Coord& c, Json& out) const;

  const ReadRelativeFile& read_;
  size_t maxTiles_;
  const std::string& name_;
  int dims_ = 2, subtreeLevels_ = 1, availableLevels_ = 1;
  uint64_t branching_ = 4;
  std::string subtreeUri_;
  std::vector<Json> contents_;  // the content templates
  bool manyContents_ = false;   // "contents" rather than "content"
  bool box_ = true;
  std::vector<double> volume_;
  double rootError_ = 0;
  Json refine_;
  SubtreeShape shape_;
  size_t tiles_ = 0, subtrees_ = 0;
  Json root_;  // the implicit tile without implicitTiling, content and children
};

Result<void> Expander::readTemplate(const Json& tile) {
  const Json& implicit = tile["implicitTiling"];
  if (!implicit.is_object()) return makeError(name_ + ": implicitTiling is not an object");
  const std::string scheme = implicit.value("subdivisionScheme", "");
  if (scheme != "QUADTREE" && scheme != "OCTREE")
    return makeError(name_ + ": implicit subdivisionScheme '" + scheme +
                     "' (QUADTREE or OCTREE are read)");
  dims_ = scheme == "QUADTREE" ? 2 : 3;
  branching_ = uint64_t{1} << dims_;
  // Bounded so that a subtree's child-subtree count, branching^subtreeLevels, fits 62 bits.
  auto available = levels(implicit, "availableLevels", 1, kMaxImplicitLevels, name_);
  auto subtree = levels(implicit, "subtreeLevels", 1, dims_ == 2 ? 31 : 20, name_);
  if (!available) return Error{available.error()};
  if (!subtree) return Error{subtree.error()};
  availableLevels_ = *available, subtreeLevels_ = *subtree;
  const Json subtrees = implicit.value("subtrees", Json::object());
  if (!subtrees.is_object() || !subtrees.contains("uri") || !subtrees["uri"].is_string())
    return makeError(name_ + ": implicitTiling without a subtrees uri template");
  subtreeUri_ = subtrees["uri"].get<std::string>();
  if (const auto c = tile.find("content"); c != tile.end() && c->is_object())
    contents_.push_back(*c);
  if (const auto c = tile.find("contents"); c != tile.end() && c->is_array()) {
    manyContents_ = true;
    contents_.assign(c->begin(), c->end());
  }
  auto volume = rootVolume(tile, box_, name_);
  if (!volume) return Error{volume.error()};
  volume_ = std::move(*volume);
  const auto error = tile.find("geometricError");
  rootError_ = error != tile.end() && error->is_number() ? error->get<double>() : 0.0;
  refine_ = tile.value("refine", Json());
  uint64_t levelCount = 1;
  for (int l = 0; l < subtreeLevels_; ++l) {
    shape_.tileCount += levelCount;
    levelCount *= branching_;
  }
  shape_.childSubtreeCount = levelCount;
  shape_.contentCount = contents_.size();
  return {};
}

// The subtree whose root is tile `c`, read and expanded; nullopt where its root is unavailable.
Result<MaybeJson> Expander::subtree(const Coord& c) {
  if (++subtrees_ > maxTiles_)
    return makeError(name_ + ": implicit tiling of more than " + std::to_string(maxTiles_) +
                     " subtrees");
  const std::string uri = substitute(subtreeUri_, c);
  auto bytes = read_(uri);
  if (!bytes) return makeError(name_ + ": subtree '" + uri + "': " + bytes.error());
  if (!bytes->has_value()) return makeError(name_ + ": subtree '" + uri + "': no such file");
  auto s = readSubtree(**bytes, uri, shape_, read_, name_);
  if (!s) return Error{s.error()};
  return tileAt(*s, 0, 0, c);
}

void Expander::addContents(const Subtree& s, uint64_t index, const Coord& c, Json& out) const {
  Json available = Json::array();
  for (size_t k = 0; k < contents_.size(); ++k) {
    if (!s.contents[k].at(index)) continue;
    Json content = contents_[k];
    if (c.level > 0) content.erase("boundingVolume");  // the root content's alone
    if (content.contains("uri") && content["uri"].is_string())
      content["uri"] = substitute(content["uri"].get<std::string>(), c);
    available.push_back(std::move(content));
  }
  if (available.empty()) return;
  if (manyContents_) {
    out["contents"] = std::move(available);
  } else {
    out["content"] = std::move(available[0]);
  }
}

// Tile `c`, at level `local` of subtree `s` with Morton index `morton` there.
Result<MaybeJson> Expander::tileAt(const Subtree& s, int local, uint64_t morton, const Coord& c) {
  uint64_t levelStart = 0, levelCount = 1;  // (branching^local - 1) / (branching - 1)
  for (int l = 0; l < local; ++l) levelStart += levelCount, levelCount *= branching_;
  const uint64_t index = levelStart + morton;
  if (c.level >= availableLevels_ || !s.tiles.at(index)) return MaybeJson{};
  if (++tiles_ > maxTiles_)
    return makeError(name_ + ": implicit tiling expands to more than " + std::to_string(maxTiles_) +
                     " tiles");
  Json out;
  if (c.level == 0) {
    out = root_;
  } else {
    out["boundingVolume"] =
        box_ ? subdivideBox(volume_, c, dims_) : subdivideRegion(volume_, c, dims_);
    out["geometricError"] = std::ldexp(rootError_, -c.level);
    if (!refine_.is_null()) out["refine"] = refine_;
  }
  addContents(s, index, c, out);
  if (auto ok = children(s, local, morton, c, out); !ok) return Error{ok.error()};
  return MaybeJson(std::move(out));
}

// Tile `c`'s children: in its subtree, or below its bottom level the roots of child subtrees.
Result<void> Expander::children(const Subtree& s, int local, uint64_t morton, const Coord& c,
                                Json& out) {
  if (c.level + 1 >= availableLevels_) return {};
  Json list = Json::array();
  for (uint64_t k = 0; k < branching_; ++k) {
    Result<MaybeJson> child = MaybeJson{};
    if (local + 1 < subtreeLevels_) {
      child = tileAt(s, local + 1, morton * branching_ + k, c.child(k));
    } else if (s.childSubtrees.at(morton * branching_ + k)) {
      child = subtree(c.child(k));
    }
    if (!child) return Error{child.error()};
    if (child->has_value()) list.push_back(std::move(**child));
  }
  if (!list.empty()) out["children"] = std::move(list);
  return {};
}

Result<Json> Expander::expand(const Json& tile) {
  if (auto ok = readTemplate(tile); !ok) return Error{ok.error()};
  root_ = tile;
  for (const char* key : {"implicitTiling", "content", "contents", "children"}) root_.erase(key);
  auto root = subtree(Coord{});
  if (!root) return Error{root.error()};
  if (!root->has_value()) return root_;  // not even the root is available
  return std::move(**root);
}

}  // namespace

Result<Json> expandImplicitTiling(const Json& tile, const ReadRelativeFile& read, size_t maxTiles,
                                  const std::string& name) {
  if (!tile.is_object() || !tile.contains("implicitTiling"))
    return makeError(name + ": a tile without implicitTiling");
  Expander expander(read, maxTiles, name);
  return expander.expand(tile);
}

}  // namespace globe::tiles3d
