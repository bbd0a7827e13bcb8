// Decodes every tile of a quantized-mesh tree with @here/quantized-mesh-decoder (an independent
// decoder from npm, in tools/web) and prints one JSON line per tile: what it holds, for
// tests/publish to compare with globe's own decoder. Usage: node quantized_mesh_node_check.mjs TREE
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const require = createRequire(path.join(here, '../../tools/web/package.json'));
const decode = require('@here/quantized-mesh-decoder').default;

function* tiles(dir) {
  for (const entry of fs.readdirSync(dir, { withFileTypes: true })) {
    const full = path.join(dir, entry.name);
    if (entry.isDirectory()) yield* tiles(full);
    else if (entry.name.endsWith('.terrain')) yield full;
  }
}

const tree = process.argv[2];
for (const file of tiles(tree)) {
  const stored = fs.readFileSync(file);
  const bytes = stored[0] === 0x1f && stored[1] === 0x8b ? zlib.gunzipSync(stored) : stored;
  const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
  const mesh = decode(buffer);
  const vertexCount = mesh.vertexData.length / 3;
  let bad = 0;
  for (const index of mesh.triangleIndices) if (index >= vertexCount) bad++;
  const heights = mesh.vertexData.subarray(2 * vertexCount);
  const { minHeight, maxHeight } = mesh.header;
  const metres = Array.from(heights, (h) => minHeight + (h / 32767) * (maxHeight - minHeight));
  console.log(JSON.stringify({
    tile: path.relative(tree, file),
    vertices: vertexCount,
    triangles: mesh.triangleIndices.length / 3,
    indicesOutOfRange: bad,
    edges: [mesh.westIndices.length, mesh.southIndices.length, mesh.eastIndices.length, mesh.northIndices.length],
    lowestMeters: Math.min(...metres),
    highestMeters: Math.max(...metres),
    normals: mesh.extensions.vertexNormals ? mesh.extensions.vertexNormals.length / 2 : 0,
    waterMaskBytes: mesh.extensions.waterMask ? mesh.extensions.waterMask.byteLength : 0,
    metadata: mesh.extensions.metadata ?? null,
  }));
}
