// globe-tiler's commands. Each parses its own command line (argv[0] is the command's name, or
// the program's for the default one), runs, prints, and returns the exit status.
#pragma once

namespace globe::tiler_app {

// globe-tiler -o PYRAMID INPUT... (elevation rasters to a pyramid, or one shard of it with
// --shard K/N), globe-tiler merge (after the shards) and globe-tiler plan --shards N.
enum class TileCommandKind { Tile, Merge, Plan };
int runTileCommand(int argc, char** argv, TileCommandKind kind = TileCommandKind::Tile);

// Measured tiling rate of one shard on one core (docs/performance/sharded-tiling.md), the
// planning step's default.
inline constexpr double kMeasuredTilesPerSecond = 10814;
// globe-tiler export: a tile tree for other viewers (--format), or one block as a GTOPO30 file.
int runExportCommand(int argc, char** argv);
// globe-tiler export-imagery --format xyz|tms|pmtiles -o OUT LAYER: a layer for web maps.
int runExportImageryCommand(int argc, char** argv);
// globe-tiler imagery -o LAYER INPUT...: imagery to a layer.
int runImageryCommand(int argc, char** argv);
// globe-tiler water-mask -o LAYER POLYGONS...: land polygons to a water-mask layer.
int runWaterMaskCommand(int argc, char** argv);
// globe-tiler buildings -o DIR FOOTPRINTS... --pyramid PYRAMID: footprints to a 3D Tiles tileset.
int runBuildingsCommand(int argc, char** argv);

}  // namespace globe::tiler_app
