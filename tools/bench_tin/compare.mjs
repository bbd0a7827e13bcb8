// Sets globe's TINs (globe-bench-tin) beside @mapbox/martini (RTIN) and delatin (greedy Delaunay
// insertion) on the same 65×65 grids at the same maximum errors, in one run: triangles per tile,
// the largest error each actually has (measured here, by one evaluator for all three, over every
// sample), and time per tile. Usage: node compare.mjs DIR... (each written by globe-bench-tin).
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';

const require = createRequire(path.resolve('tools/web/package.json'));
const Martini = require('@mapbox/martini').default ?? require('@mapbox/martini');
const Delatin = require('delatin').default ?? require('delatin');
const SIDE = 65;

// The largest |interpolated - sample| over every sample; Infinity if one lies in no triangle.
function maxError(heights, vertices, triangles) {
  const worst = new Float64Array(SIDE * SIDE).fill(Infinity);
  for (let t = 0; t < triangles.length; t += 3) {
    const [a, b, c] = [triangles[t], triangles[t + 1], triangles[t + 2]];
    const ax = vertices[2 * a], ay = vertices[2 * a + 1];
    const bx = vertices[2 * b], by = vertices[2 * b + 1];
    const cx = vertices[2 * c], cy = vertices[2 * c + 1];
    const area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
    if (area === 0) continue;
    const za = heights[ay * SIDE + ax], zb = heights[by * SIDE + bx], zc = heights[cy * SIDE + cx];
    for (let y = Math.min(ay, by, cy); y <= Math.max(ay, by, cy); y++) {
      for (let x = Math.min(ax, bx, cx); x <= Math.max(ax, bx, cx); x++) {
        const w0 = ((bx - x) * (cy - y) - (by - y) * (cx - x)) / area;
        const w1 = ((cx - x) * (ay - y) - (cy - y) * (ax - x)) / area;
        const w2 = 1 - w0 - w1;
        if (w0 < -1e-12 || w1 < -1e-12 || w2 < -1e-12) continue;
        const e = Math.abs(w0 * za + w1 * zb + w2 * zc - heights[y * SIDE + x]);
        const i = y * SIDE + x;
        worst[i] = worst[i] === Infinity ? e : Math.max(worst[i], e);
      }
    }
  }
  return worst.reduce((m, e) => Math.max(m, e), 0);
}

const median = (values) => { const s = [...values].sort((a, b) => a - b); return s[Math.floor(s.length / 2)]; };

const rows = [];
for (const dir of process.argv.slice(2)) {
  const raw = fs.readFileSync(path.join(dir, 'grids.bin'));
  const all = new Float64Array(raw.buffer, raw.byteOffset, raw.byteLength / 8);
  const count = all.length / (SIDE * SIDE);
  const grids = Array.from({ length: count }, (_, i) => all.subarray(i * SIDE * SIDE, (i + 1) * SIDE * SIDE));
  const martini = new Martini(SIDE);
  for (const file of fs.readdirSync(dir).filter((f) => /^globe-.*\.json$/.test(f))) {
    const tolerance = Number(file.slice(6, -5));
    const ours = JSON.parse(fs.readFileSync(path.join(dir, file)));
    const result = { region: path.basename(dir), tiles: count, tolerance, methods: {} };
    const record = (name, meshes, seconds) => {
      let triangles = 0, worst = 0;
      meshes.forEach((m, i) => { triangles += m.triangles.length / 3; worst = Math.max(worst, maxError(grids[i], m.vertices, m.triangles)); });
      result.methods[name] = { triangles: triangles / count, maxError: worst, msPerTile: (1000 * seconds) / count };
    };
    record('globe', ours.meshes.map((m) => ({ vertices: m.vertices.flat(), triangles: m.triangles })), ours.seconds);
    let start = process.hrtime.bigint();
    const martiniMeshes = grids.map((g) => { const tile = martini.createTile(Float32Array.from(g)); return tile.getMesh(tolerance); });
    record('martini', martiniMeshes, Number(process.hrtime.bigint() - start) / 1e9);
    start = process.hrtime.bigint();
    const delatinMeshes = grids.map((g) => { const tin = new Delatin(Array.from(g), SIDE, SIDE); tin.run(tolerance); return { vertices: tin.coords, triangles: tin.triangles }; });
    record('delatin', delatinMeshes, Number(process.hrtime.bigint() - start) / 1e9);
    rows.push(result);
  }
}
rows.sort((a, b) => a.region.localeCompare(b.region) || a.tolerance - b.tolerance);
console.log('| tiles | max error allowed | globe triangles/tile (max error, ms/tile) | martini | delatin | globe / delatin |');
console.log('|---|---|---|---|---|---|');
for (const r of rows) {
  const cell = (m) => `${m.triangles.toFixed(1)} (${m.maxError.toFixed(3)} m, ${m.msPerTile.toFixed(2)})`;
  const g = r.methods.globe, mt = r.methods.martini, d = r.methods.delatin;
  console.log(`| ${r.region} (${r.tiles}) | ${r.tolerance} m | ${cell(g)} | ${cell(mt)} | ${cell(d)} | ${(g.triangles / d.triangles).toFixed(3)} |`);
}
const fewer = (other) => rows.map((r) => Math.round(100 * (1 - r.methods.globe.triangles / r.methods[other].triangles)));
const range = (values) => `${Math.min(...values)} to ${Math.max(...values)} %`;
console.log(`\nglobe: ${range(fewer('delatin'))} fewer triangles than delatin, ${range(fewer('martini'))} fewer than martini, over these rows.`);
const ok = rows.every((r) => r.methods.globe.maxError <= r.tolerance + 1e-6 && r.methods.globe.triangles < Math.min(r.methods.martini.triangles, r.methods.delatin.triangles));
console.log(ok ? '\nglobe: fewest triangles within the error on every row' : '\nglobe: NOT the fewest on every row (or over its error)');
process.exitCode = ok ? 0 : 1;
