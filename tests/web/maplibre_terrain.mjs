// MapLibre GL JS reads globe-tiler's Terrarium export: the bundled pyramid exported over Fuji's
// DEM square to zoom 11 (its pixels as fine as the pyramid's finest samples), served by nginx on
// 127.0.0.1 with the page and MapLibre's build, opened in headless Chromium (software WebGL) as
// the map's terrain (exaggeration 1).
//   map.queryTerrainElevation at 100 points of the view once the map is idle, against
//   `globe query --mode exact` of the pyramid: each within the pixel resolution of the zoom drawn,
//   i.e. the span of the exact surface over the four DEM pixel centres around the point (MapLibre
//   interpolates between them) plus Terrarium's 1/256 m; and, tighter, the bilinear interpolation
//   of the exact surface at those centres (what the exporter samples) within 2 cm.
//   maplibre-fuji.png (an oblique view) is saved.
import fs from 'node:fs';
import path from 'node:path';
import * as h from '../../tools/web/lib/harness.mjs';

h.watchdog(Number(process.env.GLOBE_WEB_TIMEOUT_S || 540), 'the MapLibre test');
const WIDTH = 960;
const HEIGHT = 540;
const MAX_ZOOM = 11;
// Straight down over the upper slopes, close enough that MapLibre draws its terrain from the
// tree's deepest zoom (its terrain tiles are 512 px: zoom 12 tiles read zoom 11 DEM tiles).
const TOP_VIEW = { center: [138.7274, 35.3606], zoom: 12.5, pitch: 0, bearing: 0 };
// Oblique, from the south-west like the CesiumJS picture.
const PICTURE_VIEW = { center: [138.7274, 35.3606], zoom: 11.2, pitch: 72, bearing: 33 };

const { check, finish } = h.checks();
const pngOf = (dataUrl) => Buffer.from(dataUrl.slice(dataUrl.indexOf(',') + 1), 'base64');

const work = h.tempDir('maplibre');
const pyramid = h.bundledPyramid(work);
const tree = path.join(work, 'terrarium');
h.exportRaster('terrarium', pyramid, tree, MAX_ZOOM);
const site = h.makeSite(path.join(work, 'site'), { maplibre: h.maplibreDist, pages: h.pagesDir, tr: tree });
const server = await h.startNginx(site);
const { browser } = await h.launchBrowser({ width: WIDTH, height: HEIGHT });

// Web Mercator: degrees <-> world pixels at zoom z (256 px tiles).
const toPixel = ([lon, lat], z) => {
  const size = 256 * 2 ** z;
  const s = Math.sin((lat * Math.PI) / 180);
  return [((lon + 180) / 360) * size, (0.5 - Math.log((1 + s) / (1 - s)) / (4 * Math.PI)) * size];
};
const toLonLat = ([x, y], z) => {
  const size = 256 * 2 ** z;
  const n = Math.PI - (2 * Math.PI * y) / size;
  return [(x / size) * 360 - 180, (180 / Math.PI) * Math.atan(Math.sinh(n))];
};

await finish(async () => {
  const { page, refused } = await h.openPage(browser, server.url('/pages/maplibre.html'));
  await page.waitForFunction(() => window.globeTestReady === true, { timeout: 60000 });
  const api = (fn, ...args) => page.evaluate((f, a) => window.globeTest[f](...a), fn, args);
  const started = Date.now();
  const state = await api('init', { tiles: '/tr/{z}/{x}/{y}.png', maxzoom: MAX_ZOOM,
    bounds: h.FUJI_BOUNDS, ...TOP_VIEW });
  h.log(`map idle in ${((Date.now() - started) / 1000).toFixed(1)} s: tile zoom ${state.tileZoom}, ` +
    `terrain tiles drawn at zooms ${state.zooms.join(',')} from DEM tiles of zoom ${state.demZooms.join(',')}, ` +
    `exaggeration ${state.exaggeration}`);
  check(state.exaggeration === 1, 'terrain exaggeration 1');
  const demZoom = Math.min(...state.demZooms);
  check(state.demZooms.length === 1 && demZoom === MAX_ZOOM, `the view drawn from the tree's deepest zoom (${MAX_ZOOM})`);

  // 100 points over the middle 90% of the view.
  const [w, s, e, n] = state.bounds;
  const mw = 0.05 * (e - w);
  const mh = 0.05 * (n - s);
  const points = h.randomPoints(100, [w + mw, s + mh, e - mw, n - mh], 7);
  const sampled = await api('sample', points);
  const own = sampled.filter(([, o]) => o).length;
  check(own === points.length, `every point on a drawn tile with its own DEM data (${own} of ${points.length})`);

  // The exact surface at each point and at the centres of the four DEM pixels around it (what
  // the exporter samples, and MapLibre interpolates between).
  const around = [];
  const weights = [];
  for (const p of points) {
    const [x, y] = toPixel(p, demZoom);
    const i = Math.floor(x - 0.5);
    const j = Math.floor(y - 0.5);
    weights.push([x - 0.5 - i, y - 0.5 - j]);
    for (const [di, dj] of [[0, 0], [1, 0], [0, 1], [1, 1]]) around.push(toLonLat([i + di + 0.5, j + dj + 0.5], demZoom));
  }
  const exactAround = h.exactHeights(pyramid, around);
  const exact = h.exactHeights(pyramid, points);
  const diffs = [];
  const bounds = [];
  const readBack = [];
  let over = 0;
  let worst = null;
  let worstRatio = 0;
  for (let i = 0; i < points.length; ++i) {
    const [a00, a10, a01, a11] = exactAround.slice(4 * i, 4 * i + 4);
    const [fx, fy] = weights[i];
    const bilinear = (a00 * (1 - fx) + a10 * fx) * (1 - fy) + (a01 * (1 - fx) + a11 * fx) * fy;
    readBack.push(Math.abs(sampled[i][0] - bilinear));
    const bound = Math.max(a00, a10, a01, a11) - Math.min(a00, a10, a01, a11) + 1 / 256 + 0.01;
    const d = Math.abs(sampled[i][0] - exact[i]);
    diffs.push(d);
    bounds.push(bound);
    if (!(d <= bound)) ++over;
    if (!(d / bound <= worstRatio)) {
      worstRatio = d / bound;
      worst = { point: points[i], maplibre: sampled[i][0], exact: exact[i], bound };
    }
  }
  const st = h.stats(diffs);
  const sb = h.stats(bounds);
  const pixel = (40075016.686 * Math.cos((35.36 * Math.PI) / 180)) / (256 * 2 ** demZoom);
  h.log(`[ maplibre heights ] vs globe query --mode exact: median ${st.median.toFixed(3)} m, ` +
    `95th ${st.p95.toFixed(3)} m, max ${st.max.toFixed(3)} m over ${st.count} points, DEM zoom ${demZoom} ` +
    `(${pixel.toFixed(1)} m pixels; the exact surface's span over the four pixel centres around: ` +
    `median ${sb.median.toFixed(2)} m, max ${sb.max.toFixed(2)} m)`);
  const rb = h.stats(readBack);
  h.log(`[ maplibre heights ] vs the exact surface at the pixel centres, interpolated as MapLibre does: ` +
    `median ${rb.median.toFixed(4)} m, max ${rb.max.toFixed(4)} m`);
  h.log(`  worst against its bound: ${JSON.stringify(worst)}`);
  check(over === 0, `every height within the span of the exact surface over the four DEM pixel centres around it (${over} of ${points.length} beyond)`);
  check(rb.max <= 0.02, 'every height the bilinear interpolation of the exact surface at the pixel centres (within 2 cm: Terrarium\'s 1/256 m)');

  await api('jumpTo', PICTURE_VIEW);
  const out = h.outputPath('maplibre-fuji.png');
  fs.writeFileSync(out, pngOf(await api('capture')));
  h.log(`MapLibre picture: ${out}`);
  const tiles = server.accessLog().filter((l) => l.includes('/tr/'));
  const failed = tiles.filter((l) => !/ (200|304) /.test(l));
  check(tiles.length > 0 && failed.length === 0,
    `MapLibre fetched ${tiles.length} tiles, each served${failed.length ? ': ' + failed.slice(0, 3).join('; ') : ''}`);
  check(refused.length === 0, `no request beyond 127.0.0.1${refused.length ? ': ' + refused.slice(0, 5).join(' ') : ''}`);
}, async () => {
  await browser.close().catch(() => {});
  server.stop();
});
