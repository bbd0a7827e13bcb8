// A 3D Tiles tileset (1.0 or 1.1) read from a directory or any static web server
// (transport::ByteSource): its tree of tiles with their bounding volumes, geometric errors,
// refinement (REPLACE or ADD, inherited), the transform chain and their content files, external
// tilesets (a content that is a tileset.json) read in as subtrees. Every file it names must lie
// under the first tileset's folder: a tileset that points outside (an absolute path, "..", a URL
// elsewhere) is refused, never read.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "core/result.hpp"
#include "geo/ellipsoid.hpp"
#include "tiles3d/bounding_sphere.hpp"
#include "transport/byte_source.hpp"

namespace globe::tiles3d {

struct TileNode {
  double geometricErrorMeters = 0;
  bool additive = false;              // ADD refinement; REPLACE otherwise
  glm::dmat4 transform{1.0};          // content frame to ECEF: the chain's product
  BoundingSphere bounds;              // around the tile and its content
  std::vector<std::string> contents;  // names in the source (b3dm, i3dm, glb, ...)
  std::vector<TileNode> children;
};

struct Tileset {
  std::shared_ptr<transport::ByteSource> source;  // where `contents` are read from
  std::string file;                               // the tileset.json's path or URL
  TileNode root;
  size_t tileCount = 0;
  std::vector<std::string> warnings;  // what was read past (extensions, metadata, data URIs)
};

inline constexpr uint64_t kMaxTilesetBytes = uint64_t{64} << 20;
inline constexpr uint64_t kMaxContentBytes = uint64_t{256} << 20;

// `name`: the tileset.json's name in `source` ("tileset.json"). Errors name the file and the
// problem. A region's corners are placed on `ellipsoid`.
Result<Tileset> readTileset(std::shared_ptr<transport::ByteSource> source, const std::string& name,
                            const geo::Ellipsoid& ellipsoid = geo::Ellipsoid::wgs84());
// `path`: a tileset.json or the folder holding one.
Result<Tileset> readTileset(const std::filesystem::path& path,
                            const geo::Ellipsoid& ellipsoid = geo::Ellipsoid::wgs84());
// `location`: a tileset.json or the folder holding one, as a path or an http(s) URL read through
// `network` (without one, a URL is an error naming it).
Result<Tileset> openTileset(const std::string& location, transport::Network* network,
                            const geo::Ellipsoid& ellipsoid = geo::Ellipsoid::wgs84());
// Moves a whole tileset by `placement` (applied after every tile's transform, its bounds with
// it): a tileset lifted onto the terrain (--tileset-clamp), or one in a local frame placed.
void placeTileset(Tileset& tileset, const glm::dmat4& placement);
// A content's bytes, or an error naming it (a content that is not there is an error too).
Result<std::vector<std::byte>> readContentBytes(const Tileset& tileset, const std::string& name);

}  // namespace globe::tiles3d
