// The same views over the same exported terrain in CesiumJS (headless Chromium, software WebGL)
// and in globe (OSMesa): frame time and triangles drawn. Run by bench_cesium_vs_globe.sh, which
// documents it; prints one JSON object (the measurements) on its last line.
//   terrain: the bundled pyramid's quantized-mesh export (levels 0-3 of the world, Fuji's square to
//     the deepest level) served by nginx on 127.0.0.1; globe reads the same tree from the same
//     server (quantized-mesh:URL), and, for reference, the pyramid itself.
//   CesiumJS: requestRenderMode off, frames back to back once globe.tilesLoaded; the frame time is
//     the interval between successive scene.postRender events (median over FRAMES), besides the
//     time scene.render itself takes (its JavaScript and GL calls; ANGLE's GPU process draws in
//     parallel). Triangles: the indices of the terrain tiles rendered (globe._surface._tilesToRender),
//     with and without CesiumJS's skirts.
//   globe: `globe play --no-frames` of a path that holds the camera still for FRAMES frames (the
//     median total_ms of timing.csv; it renders every frame, nothing written), and
//     `globe snapshot` of the view for the tiles and triangles drawn.
import fs from 'node:fs';
import path from 'node:path';
import * as h from '../web/lib/harness.mjs';

const FRAMES = Number(process.env.FRAMES || 60);
const [WIDTH, HEIGHT] = (process.env.SIZE || '960x540').split('x').map(Number);
const VIEWS = {
  fuji_oblique: [138.60, 35.20, 6000, 30, -15, 0],
  fuji_low: [138.60, 35.20, 2200, 33, 2, 0],
  fuji_above: [138.7274, 35.3606, 25000, 0, -60, 0],
};
h.watchdog(1500, 'the benchmark');

const work = h.tempDir('bench');
const pyramid = h.bundledPyramid(work);
const tree = path.join(work, 'qm');
h.exportQuantizedMesh(pyramid, tree);
const site = h.makeSite(path.join(work, 'site'), { cesium: h.cesiumBuild, pages: h.pagesDir, qm: tree });
const server = await h.startNginx(site, { lifetimeS: 1500 });
const qmSource = `quantized-mesh:${server.url('/qm/layer.json')}`;
const median = (v) => h.stats(v).median;

function globeView(name, camera, source, label) {
  const out = path.join(work, `globe-${label}-${name}`);
  fs.mkdirSync(out, { recursive: true });
  const snap = h.run(h.globeExe(), ['snapshot', `--camera=${camera.join(',')}`, '--size', `${WIDTH}x${HEIGHT}`,
    '--cache-dir', path.join(work, 'cache'), '-o', path.join(out, 'view.png'), source], { quiet: true });
  const m = snap.match(/(\d+) tiles drawn, (\d+) triangles/);
  const [lon, lat, height, heading, pitch, roll] = camera;
  const key = { lon, lat, height, heading, pitch, roll };
  fs.writeFileSync(path.join(out, 'path.json'), JSON.stringify({ description: 'still', interpolation: 'linear',
    keyframes: [{ t: 0, ...key }, { t: FRAMES / 30, ...key }] }));
  h.run(h.globeExe(), ['play', '--no-frames', '--size', `${WIDTH}x${HEIGHT}`, '--cache-dir', path.join(work, 'cache'),
    '--out', path.join(out, 'play'), source, path.join(out, 'path.json')], { quiet: true });
  const rows = fs.readFileSync(path.join(out, 'play/timing.csv'), 'utf8').trim().split('\n').slice(1)
    .map((l) => l.split(',').map(Number));
  const steady = rows.slice(1);  // frame 0 may load
  return { tiles: Number(m[1]), triangles: Number(m[2]), frameMs: median(steady.map((r) => r[6])),
    drawMs: median(steady.map((r) => r[4])), frames: steady.length };
}

const results = { size: `${WIDTH}x${HEIGHT}`, frames: FRAMES, views: {} };
const { browser, gl, mode } = await h.launchBrowser({ width: WIDTH, height: HEIGHT });
results.webgl = `${gl} (${mode})`;
results.chromium = await browser.version();
results.cesium = JSON.parse(fs.readFileSync(path.join(h.webDir, 'node_modules/cesium/package.json'))).version;
try {
  const { page } = await h.openPage(browser, server.url('/pages/cesium.html'));
  const api = (fn, ...args) => page.evaluate((f, a) => window.globeTest[f](...a), fn, args);
  await api('init', { terrainUrl: server.url('/qm/') });
  await api('pictureStyle');  // coloured by height under a sky, as globe draws it by default
  for (const [name, camera] of Object.entries(VIEWS)) {
    await api('setCamera', camera);
    const loadMs = await api('waitTilesLoaded', 180000);
    const tris = await page.evaluate(() => {
      const surface = window.globeTest.viewer.scene.globe._surface;
      let all = 0;
      let noSkirts = 0;
      for (const tile of surface._tilesToRender) {
        const mesh = tile.data && tile.data.renderedMesh;
        if (!mesh) continue;
        all += mesh.indices.length / 3;
        noSkirts += (mesh.indexCountWithoutSkirts ?? mesh.indices.length) / 3;
      }
      return { tiles: surface._tilesToRender.length, all, noSkirts };
    });
    const t = await api('frameTimes', FRAMES);
    const cesium = { tiles: tris.tiles, triangles: tris.noSkirts, trianglesWithSkirts: tris.all,
      frameMs: median(t.intervals), renderMs: median(t.renders), loadS: loadMs / 1000 };
    h.log(`${name}: CesiumJS ${JSON.stringify(cesium)}`);
    await api('setRendering', false);  // leave the CPU to globe
    const globeQm = globeView(name, camera, qmSource, 'qm');
    h.log(`${name}: globe (quantized-mesh) ${JSON.stringify(globeQm)}`);
    const globePyramid = globeView(name, camera, pyramid, 'pyramid');
    h.log(`${name}: globe (pyramid) ${JSON.stringify(globePyramid)}`);
    await api('setRendering', true);
    results.views[name] = { camera: camera.join(','), cesium, globeQm, globePyramid };
  }
} finally {
  await browser.close().catch(() => {});
  server.stop();
}
console.log(JSON.stringify(results));
process.exit(0);
