// A 3D Tiles tileset (1.0 or 1.1, explicit tiling) read from a directory: its tree of tiles with
// their geometric errors, refinement (REPLACE or ADD, inherited), the transform chain and their
// content files, external tilesets (a content that is a tileset.json) read in as subtrees.
// Every file it names must lie under the first tileset's folder: a tileset that points outside
// (an absolute path, "..") is refused, never read.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "core/result.hpp"

namespace globe::tiles3d {

struct TileNode {
  double geometricErrorMeters = 0;
  bool additive = false;                        // ADD refinement; REPLACE otherwise
  glm::dmat4 transform{1.0};                    // content frame to ECEF: the chain's product
  std::vector<std::filesystem::path> contents;  // files (b3dm, i3dm, cmpt, pnts, glb, gltf)
  std::vector<TileNode> children;
};

struct Tileset {
  std::filesystem::path file;
  TileNode root;
  size_t tileCount = 0;
  std::vector<std::string> warnings;  // what was read past (extensions, metadata, data URIs)
};

// `path`: a tileset.json or the folder holding one. Errors name the file and the problem.
Result<Tileset> readTileset(const std::filesystem::path& path);

}  // namespace globe::tiles3d
