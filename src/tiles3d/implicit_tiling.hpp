// 3D Tiles 1.1 implicit tiling (QUADTREE, OCTREE) expanded into explicit tile JSON: the subtree
// files' availability walked in Morton order, bounding volumes subdivided, template URIs filled.
#pragma once

#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "core/result.hpp"
#include "tiles3d/subtree_file.hpp"  // ReadRelativeFile

namespace globe::tiles3d {

inline constexpr int kMaxImplicitLevels = 32;  // availableLevels at most

// `tile`: a tile JSON object with "implicitTiling". Returns the same tile as explicit JSON: no
// implicitTiling, children nested, each with its boundingVolume (subdivided), geometricError
// (halved per level), refine inherited, and content/contents with the template URIs
// ({level},{x},{y},{z}) substituted, only where content availability says so. More than
// `maxTiles` tiles, a subtree file that cannot be read, a bounding volume other than a box or a
// region: a clear error naming `name` (the tileset file) and the subtree file.
Result<nlohmann::json> expandImplicitTiling(const nlohmann::json& tile,
                                            const ReadRelativeFile& read, size_t maxTiles,
                                            const std::string& name);

}  // namespace globe::tiles3d
