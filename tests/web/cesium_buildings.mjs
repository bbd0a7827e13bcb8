// CesiumJS reads `globe-tiler buildings`: the synthetic footprints of tests/data/buildings on the
// bundled pyramid (ETOPO20, W002N52, Fuji's 3″ DEM) as a 3D Tiles 1.1 tileset, served by nginx on
// 127.0.0.1 with the page, Cesium's build and a quantized-mesh export of the same pyramid, opened
// in headless Chromium (software WebGL) with Cesium3DTileset.fromUrl.
//   1. A view of the Fujiyoshida buildings over the terrain: cesium-buildings.png, which must
//      draw building tiles (the CesiumJS viewer starts on the terrain: started on the bare
//      ellipsoid and switched, it drew neither terrain nor sky here).
//   0. Every GLB through the Khronos glTF validator (npm gltf-validator): no error, no warning.
//   2. Over the bare ellipsoid (the terrain stands above part of a roof on a slope: the base is
//      the lowest ground), scene.sampleHeightMostDetailed inside every footprint against the
//      expected roof, worked out here from the GeoJSON's attributes (height, else
//      building:levels × 3 m) and the lowest ground `globe query --mode exact` gives at the
//      footprint's vertices and centre: within 1 m. And 20 m beside each building: nothing as
//      high.
import fs from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';
import * as h from '../../tools/web/lib/harness.mjs';

// The validator from tools/web/node_modules (beside the harness, not this folder).
let validator;
try {
  validator = createRequire(path.join(h.webDir, 'package.json'))('gltf-validator');
} catch {
  console.log("SKIP: tools/web/node_modules/gltf-validator is missing: run 'bash tools/web/install.sh'");
  process.exit(77);
}

h.watchdog(Number(process.env.GLOBE_WEB_TIMEOUT_S || 540), 'the CesiumJS buildings test');
const WIDTH = 960;
const HEIGHT = 540;
const LEVEL_HEIGHT_M = 3;
// Low in the south-west of the Fujiyoshida footprints (A-D), looking north-east, 12° down.
const CAMERA = [138.7988, 35.4772, 880, 50, -12, 0];
const FOOTPRINTS = path.join(h.sourceDir, 'tests/data/buildings/fuji_footprints.geojson');

const { check, finish } = h.checks();

// Each footprint of the file (each part of a multi-polygon) with the height its attributes give.
function footprints() {
  const geojson = JSON.parse(fs.readFileSync(FOOTPRINTS, 'utf8'));
  const out = [];
  for (const [id, f] of geojson.features.entries()) {
    const p = f.properties;
    const height = p.height !== undefined ? parseFloat(p.height)
      : p['building:levels'] !== undefined ? LEVEL_HEIGHT_M * parseFloat(p['building:levels']) : undefined;
    if (height === undefined) continue;
    const polygons = f.geometry.type === 'Polygon' ? [f.geometry.coordinates] : f.geometry.coordinates;
    for (const rings of polygons) {
      out.push({ id, name: p.name, height, rings: rings.map((r) => r.slice(0, -1)) });
    }
  }
  return out;
}

function inside(rings, [x, y]) {
  let odd = false;
  for (const r of rings) {
    for (let i = 0, j = r.length - 1; i < r.length; j = i++) {
      if ((r[i][1] > y) !== (r[j][1] > y) &&
          x < ((r[j][0] - r[i][0]) * (y - r[i][1])) / (r[j][1] - r[i][1]) + r[i][0]) odd = !odd;
    }
  }
  return odd;
}

function extent(ring) {
  const xs = ring.map((p) => p[0]);
  const ys = ring.map((p) => p[1]);
  return [Math.min(...xs), Math.min(...ys), Math.max(...xs), Math.max(...ys)];
}

// Points of a 9×9 grid over the footprint that lie inside it, nearest its middle first.
function probes(fp, count) {
  const [w, s, e, n] = extent(fp.rings[0]);
  const grid = [];
  for (let i = 1; i < 10; ++i) {
    for (let j = 1; j < 10; ++j) grid.push([w + ((e - w) * i) / 10, s + ((n - s) * j) / 10]);
  }
  const mid = [(w + e) / 2, (s + n) / 2];
  const d = (p) => (p[0] - mid[0]) ** 2 + (p[1] - mid[1]) ** 2;
  return grid.filter((p) => inside(fp.rings, p)).sort((a, b) => d(a) - d(b)).slice(0, count);
}

function beside(fp) {
  const [w, s, e, n] = extent(fp.rings[0]);
  const dLon = 20 / (111320 * Math.cos((s * Math.PI) / 180));
  const dLat = 20 / 110574;
  return [[w - dLon, (s + n) / 2], [e + dLon, (s + n) / 2], [(w + e) / 2, s - dLat], [(w + e) / 2, n + dLat]];
}

const work = h.tempDir('cesium-buildings');
const pyramid = h.bundledPyramid(work);
const tiles = path.join(work, 'buildings');
h.run(h.tilerExe(), ['buildings', '-o', tiles, FOOTPRINTS, '--pyramid', pyramid, '--tile-buildings', '3']);
// 0. The GLBs through the Khronos validator.
const glbs = [];
const walk = (dir) => {
  for (const e of fs.readdirSync(dir, { withFileTypes: true })) {
    if (e.isDirectory()) walk(path.join(dir, e.name));
    else if (e.name.endsWith('.glb')) glbs.push(path.join(dir, e.name));
  }
};
walk(tiles);
const validations = [];
for (const f of glbs.sort()) {
  const r = await validator.validateBytes(new Uint8Array(fs.readFileSync(f)));
  validations.push({ file: path.relative(tiles, f), errors: r.issues.numErrors, warnings: r.issues.numWarnings,
    first: r.issues.messages.slice(0, 3).map((m) => `${m.code} ${m.pointer || ''} ${m.message}`) });
}
h.log(`glTF validator ${validator.version()}: ${glbs.length} GLBs, ` +
  `${validations.reduce((a, v) => a + v.errors, 0)} errors, ${validations.reduce((a, v) => a + v.warnings, 0)} warnings`);
const invalid = validations.filter((v) => v.errors > 0 || v.warnings > 0);

// The terrain for the picture: the world's coarse levels and the footprints' surroundings.
const qm = path.join(work, 'qm');
h.run(h.tilerExe(), ['export', '--format', 'quantized-mesh', '-o', qm, '--levels', '0-3', pyramid]);
h.run(h.tilerExe(), ['export', '--format', 'quantized-mesh', '-o', qm, '--levels', '4-16',
  '--bounds', '138.73,35.39,138.89,35.50', pyramid]);
const site = h.makeSite(path.join(work, 'site'),
  { cesium: h.cesiumBuild, pages: h.pagesDir, buildings: tiles, qm });
const server = await h.startNginx(site);
const { browser } = await h.launchBrowser({ width: WIDTH, height: HEIGHT });

// The expected roofs: the lowest exact ground at the vertices and the centre, plus the height.
const fps = footprints();
const groundPoints = fps.flatMap((fp) => {
  const outer = fp.rings[0];
  const c = outer.reduce((a, p) => [a[0] + p[0] / outer.length, a[1] + p[1] / outer.length], [0, 0]);
  return [...outer, c];
});
const ground = h.exactHeights(pyramid, groundPoints);
let at = 0;
for (const fp of fps) {
  const n = fp.rings[0].length + 1;
  fp.base = Math.min(...ground.slice(at, at + n));
  fp.roof = fp.base + fp.height;
  at += n;
}

await finish(async () => {
  check(glbs.length > 0 && invalid.length === 0, `the glTF validator finds no error or warning in ${glbs.length} GLBs` +
    `${invalid.length ? ': ' + JSON.stringify(invalid.slice(0, 3)) : ''}`);
  const { page, refused } = await h.openPage(browser, server.url('/pages/cesium.html'));
  await page.evaluate((o) => window.globeTest.init(o), { terrainUrl: server.url('/qm/'), requestRenderMode: false });
  const loaded = await page.evaluate(async (url) => {
    const t = await Cesium.Cesium3DTileset.fromUrl(url, { maximumScreenSpaceError: 1 });
    const scene = window.globeTest.viewer.scene;
    scene.primitives.add(t);
    window.buildings = t;
    return { version: t.asset.version, add: t.root.refine === Cesium.Cesium3DTileRefine.ADD,
      children: t.root.children.length };
  }, server.url('/buildings/tileset.json'));
  h.log(`CesiumJS read tileset.json: ${JSON.stringify(loaded)}`);
  check(loaded.version === '1.1' && loaded.add && loaded.children > 0,
    'CesiumJS reads a 3D Tiles 1.1 tileset refined by ADD with children');

  // 1. The picture: Fujiyoshida's buildings from the south-west over the pyramid's terrain (a
  // quantized-mesh export of the same pyramid), lit by a May morning's sun.
  await page.evaluate(() => window.globeTest.pictureStyle());
  await page.evaluate((camera) => window.globeTest.setCamera(camera), CAMERA);
  const terrainMs = await page.evaluate(() => window.globeTest.waitTilesLoaded(180000, 10));
  const picture = await page.evaluate(async () => {
    const t = window.buildings;
    const startedAt = performance.now();
    for (let frames = 0; !(t.tilesLoaded && frames > 10); ++frames) {
      await new Promise((r) => requestAnimationFrame(r));
      if (performance.now() - startedAt > 120000) throw new Error('the tileset did not load in 120 s');
    }
    return { png: window.globeTest.capture(), selected: t.statistics.selected,
      triangles: t.statistics.numberOfTrianglesSelected, ms: performance.now() - startedAt };
  });
  picture.ms += terrainMs;
  const out = h.outputPath('cesium-buildings.png');
  fs.writeFileSync(out, Buffer.from(picture.png.slice(picture.png.indexOf(',') + 1), 'base64'));
  h.log(`CesiumJS picture: ${out} (${picture.selected} tiles, ${picture.triangles} triangles drawn, loaded in ${(picture.ms / 1000).toFixed(1)} s)`);
  check(picture.selected > 0 && picture.triangles > 0, 'the view draws building tiles');
  // 2. Heights, over the bare ellipsoid again (the terrain stands above some roofs: the base is
  // the lowest ground under a footprint).
  await page.evaluate(() => window.globeTest.setTerrain({ ellipsoid: true }));
  const points = fps.map((fp) => probes(fp, 3));
  const flat = points.flat();
  const started = Date.now();
  const sampled = await page.evaluate(async (p) => {
    const scene = window.globeTest.viewer.scene;
    if (!scene.sampleHeightSupported) return null;
    const carto = p.map(([lon, lat]) => Cesium.Cartographic.fromDegrees(lon, lat));
    const out = await scene.sampleHeightMostDetailed(carto);
    return out.map((c) => (c.height === undefined ? null : c.height));
  }, flat);
  check(sampled !== null, 'scene.sampleHeightSupported');
  h.log(`sampleHeightMostDetailed: ${flat.length} points in ${((Date.now() - started) / 1000).toFixed(1)} s`);
  const diffs = [];
  let k = 0;
  for (const [i, fp] of fps.entries()) {
    const got = points[i].map(() => sampled[k++]);
    const worst = Math.max(...got.map((g) => (g === null ? Infinity : Math.abs(g - fp.roof))));
    diffs.push(...got.map((g) => (g === null ? Infinity : g - fp.roof)));
    h.log(`[ roof ] ${fp.name}: ground ${fp.base.toFixed(2)} m + ${fp.height} m = ${fp.roof.toFixed(2)} m; ` +
      `CesiumJS ${got.map((g) => (g === null ? 'none' : g.toFixed(3))).join(', ')}`);
    check(points[i].length > 0 && worst <= 1, `${fp.name}: CesiumJS's roof within 1 m of ${fp.roof.toFixed(2)} m (worst ${worst.toFixed(3)} m)`);
  }
  const s = h.stats(diffs.map(Math.abs));
  h.log(`[ cesium roofs ] vs expected: median ${s.median.toFixed(3)} m, max ${s.max.toFixed(3)} m over ${s.count} points`);
  const besidePoints = fps.filter((fp) => fp.id !== 12).flatMap((fp) => beside(fp).map((p) => [p, fp]));
  const besideHeights = await page.evaluate(async (p) => {
    const carto = p.map(([lon, lat]) => Cesium.Cartographic.fromDegrees(lon, lat));
    const out = await window.globeTest.viewer.scene.sampleHeightMostDetailed(carto);
    return out.map((c) => (c.height === undefined ? null : c.height));
  }, besidePoints.map(([p]) => p));
  const standing = besidePoints.filter(([, fp], i) => besideHeights[i] !== null && besideHeights[i] > fp.roof - 5);
  check(standing.length === 0, `nothing as high 20 m beside the buildings (${besidePoints.length} points` +
    `${standing.length ? '; ' + standing.map(([p, fp]) => `${fp.name} at ${p}`).join('; ') : ''})`);

  const glb = server.accessLog().filter((l) => l.includes('.glb'));
  const failed = glb.filter((l) => !/ (200|304) /.test(l));
  check(glb.length > 0 && failed.length === 0, `CesiumJS fetched ${glb.length} GLB contents, each served`);
  check(refused.length === 0, `no request beyond 127.0.0.1${refused.length ? ': ' + refused.slice(0, 5).join(' ') : ''}`);
}, async () => {
  await browser.close().catch(() => {});
  server.stop();
});
