// CesiumJS reads globe-tiler's quantized-mesh export: the bundled pyramid (ETOPO20, W002N52,
// Fuji's 3″ DEM) exported as test_export_trees.cpp does, served by nginx on 127.0.0.1 with the
// page and Cesium's build, opened in headless Chromium (software WebGL).
//   1. sampleTerrainMostDetailed at 300 points over Fuji's DEM square against
//      `globe query --mode exact` of the pyramid: within the geometric error CesiumJS assumes for
//      the level each sample came from (levelZero = 6378137·2π·0.25/(65·2) m, halved per level).
//   2. A low view towards Fuji against a black sky: the sky/terrain silhouette per column against
//      `globe snapshot` of the same camera over the same served tree, and against CesiumJS over
//      the bare ellipsoid (which must differ: the relief is drawn). cesium-fuji.png is saved.
import fs from 'node:fs';
import path from 'node:path';
import * as h from '../../tools/web/lib/harness.mjs';
import { silhouette, rowDifferences } from '../../tools/web/lib/silhouette.mjs';

h.watchdog(Number(process.env.GLOBE_WEB_TIMEOUT_S || 540), 'the CesiumJS test');
const WIDTH = 960;
const HEIGHT = 540;
// Low over the plain south-west of Fuji, looking at the summit, 2° up: the cone above the horizon.
const CAMERA = [138.60, 35.20, 2200, 33, 2, 0];
const LEVEL_ZERO_ERROR = (6378137 * 2 * Math.PI * 0.25) / (65 * 2);

const { check, finish } = h.checks();

const work = h.tempDir('cesium');
const pyramid = h.bundledPyramid(work);
const tree = path.join(work, 'qm');
const layer = h.exportQuantizedMesh(pyramid, tree);
const site = h.makeSite(path.join(work, 'site'), { cesium: h.cesiumBuild, pages: h.pagesDir, qm: tree });
const server = await h.startNginx(site);
const { browser } = await h.launchBrowser({ width: WIDTH, height: HEIGHT });

const pngOf = (dataUrl) => Buffer.from(dataUrl.slice(dataUrl.indexOf(',') + 1), 'base64');

await finish(async () => {
  // 1. Heights.
  const { page, refused } = await h.openPage(browser, server.url('/pages/cesium.html'));
  // Frames back to back while tiles load: drawn only on request (requestRenderMode), the view
  // took 94 s instead of 23 s to load beside one busy core, and did not load in 120 s beside two.
  const info = await page.evaluate((o) => window.globeTest.init(o),
    { terrainUrl: server.url('/qm/'), requestRenderMode: false });
  h.log(`layer.json maxzoom ${layer.maxzoom}; CesiumJS availability to level ${info.maxLevel}`);
  check(info.maxLevel === layer.maxzoom, `CesiumJS reads the tree's levels (0-${layer.maxzoom})`);
  const points = h.randomPoints(300, [138.15, 35.15, 138.85, 35.85]);
  const started = Date.now();
  const sampled = await page.evaluate((p) => window.globeTest.sample(p), points);
  h.log(`sampleTerrainMostDetailed: ${points.length} points in ${((Date.now() - started) / 1000).toFixed(1)} s`);
  const exact = h.exactHeights(pyramid, points);
  const diffs = [];
  let worstRatio = 0;
  let worst = null;
  let over = 0;
  for (let i = 0; i < points.length; ++i) {
    const [height, level] = sampled[i];
    const d = Math.abs(height - exact[i]);
    const bound = LEVEL_ZERO_ERROR / 2 ** level;
    diffs.push(d);
    if (!(d <= bound)) ++over;
    if (!Number.isFinite(height) || d / bound > worstRatio) {
      worstRatio = Number.isFinite(height) ? d / bound : Infinity;
      worst = { point: points[i], cesium: height, exact: exact[i], level, bound };
    }
  }
  const levels = [...new Set(sampled.map(([, l]) => l))].sort((a, b) => a - b);
  const s = h.stats(diffs);
  const deepestBound = LEVEL_ZERO_ERROR / 2 ** levels[levels.length - 1];
  h.log(`[ cesium heights ] vs globe query --mode exact: median ${s.median.toFixed(3)} m, ` +
    `95th ${s.p95.toFixed(3)} m, max ${s.max.toFixed(3)} m over ${s.count} points (levels ${levels.join(',')}; ` +
    `CesiumJS's geometric error at level ${levels[levels.length - 1]}: ${deepestBound.toFixed(2)} m)`);
  h.log(`  worst against its bound: ${JSON.stringify(worst)}`);
  check(over === 0, `every sample within the geometric error of its level (${over} of ${points.length} beyond)`);
  check(levels.every((l) => l === layer.maxzoom), `every sample from the deepest level (${layer.maxzoom})`);

  // 2. The view: CesiumJS over the tree (a mask: white terrain, black sky; then as a picture),
  // globe over the same tree, CesiumJS over the bare ellipsoid.
  const api = (fn, ...args) => page.evaluate((f, a) => window.globeTest[f](...a), fn, args);
  const view = async () => {
    await api('setCamera', CAMERA);
    const ms = await api('waitTilesLoaded', 300000);
    return { png: pngOf(await api('capture')), ms };
  };
  const cesium = await view();
  h.log(`CesiumJS view loaded in ${(cesium.ms / 1000).toFixed(1)} s`);
  fs.writeFileSync(path.join(work, 'cesium-mask.png'), cesium.png);
  await api('pictureStyle');
  await api('waitTilesLoaded', 180000, 3);
  const out = h.outputPath('cesium-fuji.png');
  fs.writeFileSync(out, pngOf(await api('capture')));
  h.log(`CesiumJS picture: ${out}`);
  const terrain = server.accessLog().filter((l) => l.includes('.terrain') || l.includes('/qm/layer.json'));
  const failed = terrain.filter((l) => !/ (200|304) /.test(l));
  check(terrain.length > 1 && failed.length === 0,
    `CesiumJS fetched layer.json and ${terrain.length - 1} tiles, each served${failed.length ? ': ' + failed.slice(0, 3).join('; ') : ''}`);
  await api('maskStyle');
  await api('setTerrain', { ellipsoid: true });
  const ellipsoid = await view();
  fs.writeFileSync(path.join(work, 'cesium-ellipsoid.png'), ellipsoid.png);
  await api('setRendering', false);

  const globePng = h.outputPath('globe-fuji-qm.png');
  h.run(h.globeExe(), ['snapshot', `--camera=${CAMERA.join(',')}`, '--size', `${WIDTH}x${HEIGHT}`,
    '--no-sky', '--no-attribution', '--cache-dir', path.join(work, 'cache'), '-o', globePng,
    `quantized-mesh:${server.url('/qm/layer.json')}`]);

  const cs = await silhouette(page, cesium.png);
  const gs = await silhouette(page, fs.readFileSync(globePng));
  const es = await silhouette(page, ellipsoid.png);
  const vsGlobe = h.stats(rowDifferences(cs, gs));
  const vsEllipsoid = rowDifferences(cs, es);
  const se = h.stats(vsEllipsoid);
  const relief = vsEllipsoid.filter((d) => d > 10).length / vsEllipsoid.length;
  const skyTop = Math.min(...cs.rows);
  h.log(`[ cesium silhouette ] vs globe snapshot: median ${vsGlobe.median} px, 95th ${vsGlobe.p95} px, ` +
    `max ${vsGlobe.max} px over ${cs.width} columns; vs the bare ellipsoid: median ${se.median} px, ` +
    `max ${se.max} px, ${(100 * relief).toFixed(0)}% of columns > 10 px apart; the summit at row ${skyTop} ` +
    `(globe: ${Math.min(...gs.rows)}, ellipsoid horizon: ${Math.min(...es.rows)})`);
  check(cs.rows.every((r) => r > 0 && r < HEIGHT), 'CesiumJS draws sky above terrain in every column');
  check(vsGlobe.median <= 2 && vsGlobe.p95 <= 6, 'silhouette within 2 px (median) and 6 px (95th) of globe snapshot');
  check(se.max >= 40 && relief >= 0.2, 'the relief differs from the bare ellipsoid (max ≥ 40 px, ≥ 20% of columns > 10 px)');

  check(refused.length === 0, `no request beyond 127.0.0.1${refused.length ? ': ' + refused.slice(0, 5).join(' ') : ''}`);
}, async () => {
  await browser.close().catch(() => {});
  server.stop();
});
