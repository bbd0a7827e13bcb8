// A quantized-mesh tile's TIN sampled at a block's vertices and apron: heights (and normals,
// water) where the grid's points fall in its triangles; the apron, beyond the tile, mirrored
// through the edge (h(-k) = 2 h(0) - h(k)) so edge normals keep the slope.
#pragma once

#include "formats/quantized_mesh.hpp"
#include "services/service_terrain.hpp"

namespace globe::services {

ServiceSamples sampleTin(const formats::QuantizedMesh& mesh);
// A heightmap-1.0 tile: its 65×65 samples are the block's vertices.
ServiceSamples sampleHeightmap(const formats::HeightmapTile& tile);
// Fills the apron of samples whose block part is set, by mirroring through the edges.
void mirrorApron(ServiceSamples& samples);

}  // namespace globe::services
