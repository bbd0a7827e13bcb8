// Fuzz entry points: one per parser, shared by the libFuzzer targets and the corpus replay test.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace globe::fuzz {

// Each feeds arbitrary bytes to one parser; any outcome but a crash, leak or UB is a pass.
void gtopo30Header(const uint8_t* data, size_t size);
void pack(const uint8_t* data, size_t size);
void manifest(const uint8_t* data, size_t size);
void pathJson(const uint8_t* data, size_t size);
void pathKml(const uint8_t* data, size_t size);
// What a web server controls beyond the pyramid's own formats: a Content-Range header, an
// imagery pack's head and index, a layer manifest.
void remote(const uint8_t* data, size_t size);
// An imagery tile as served: decoded, and its JPEG edge segment (formats/tile_edges.hpp) parsed
// into a tile of its own size and into a 256×256 one.
void imageTile(const uint8_t* data, size_t size);

// A terrain service's tile as served: gunzipped when gzip, decoded as quantized-mesh-1.0 and as
// heightmap-1.0, and a decoded mesh sampled onto a block's grid.
void terrainTile(const uint8_t* data, size_t size);
// A terrain service's layer.json.
void terrainLayerJson(const uint8_t* data, size_t size);
// A Terrarium / Terrain-RGB elevation tile: decoded and every pixel read as a height.
void elevationImage(const uint8_t* data, size_t size);

// A PMTiles archive's head: header, root directory (raw and gzip) and a tile id lookup.
void pmtiles(const uint8_t* data, size_t size);
// A service's XML: as a WMTS GetCapabilities document and as a TMS tile map.
void serviceXml(const uint8_t* data, size_t size);

// An overlay file (overlays/overlay_file.hpp) saved as .kml, .geojson, .gpx and .kmz, each read.
void overlayFile(const uint8_t* data, size_t size);

// A 3D Tiles content (b3dm, i3dm, cmpt, pnts, glb, glTF JSON) read into triangles under a tile
// transform and rasterised into its height grid (tiles3d/tile_content.hpp, height_grid.hpp).
void tileContent(const uint8_t* data, size_t size);
// A 3D Tiles 1.1 implicit quadtree (6 levels, subtrees of 3) whose every subtree file is these
// bytes, expanded into explicit tiles (tiles3d/implicit_tiling.hpp, subtree_file.hpp).
void implicitSubtree(const uint8_t* data, size_t size);

// The entry for a corpus folder name (gtopo30_header, pack, ...), or nullptr.
using Entry = void (*)(const uint8_t*, size_t);
Entry entryNamed(std::string_view target);

}  // namespace globe::fuzz
