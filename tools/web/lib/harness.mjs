// What the web-client tests (tests/web) and the benchmark (tools/bench_web) share: the bundled
// pyramid and its exports made by globe-tiler, a real nginx on 127.0.0.1 serving them with the
// pages and the clients' builds, headless Chromium (Debian's) driven over DevTools by
// puppeteer-core with every request beyond 127.0.0.1 refused, and `globe query --mode exact`.
// Everything started here is stopped on exit, and bounded by timeouts in any case.
import { spawn, spawnSync } from 'node:child_process';
import fs from 'node:fs';
import net from 'node:net';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const webDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
export const sourceDir = path.resolve(webDir, '../..');
export const chromiumPath = process.env.GLOBE_CHROMIUM || '/usr/bin/chromium';
export const nginxPath = '/usr/sbin/nginx';

// The Fuji DEM's square (data/dem/E138N35_FUJI.DEM).
export const FUJI_BOUNDS = [138, 35, 139, 36];

const cleanups = [];
export function atExit(fn) { cleanups.push(fn); }
function runCleanups() {
  while (cleanups.length) {
    try { cleanups.pop()(); } catch { /* best effort */ }
  }
}
process.on('exit', runCleanups);
for (const sig of ['SIGINT', 'SIGTERM', 'SIGHUP']) {
  process.on(sig, () => { runCleanups(); process.exit(128 + (os.constants.signals[sig] || 1)); });
}

const t0 = Date.now();
// console.log with the seconds since the start.
export function log(...args) { console.log(`[${((Date.now() - t0) / 1000).toFixed(1)} s]`, ...args); }

// Exits the whole run after `seconds`, whatever is pending (a hung browser, a page that never
// settles): the test fails rather than hangs.
export function watchdog(seconds, what = 'the run') {
  const t = setTimeout(() => {
    console.error(`FAIL: ${what} took longer than ${seconds} s`);
    process.exit(1);
  }, seconds * 1000);
  t.unref();
}

// A program of the build: the environment's GLOBE_EXE / GLOBE_TILER_EXE (CTest passes
// $<TARGET_FILE:...>), else build/apps/... of the checkout.
export function globeExe() {
  return process.env.GLOBE_EXE || path.join(sourceDir, 'build/apps/globe/globe');
}
export function tilerExe() {
  return process.env.GLOBE_TILER_EXE || path.join(sourceDir, 'build/apps/globe-tiler/globe-tiler');
}

// Runs a program to completion; retried a few times where the binary is missing or busy (being
// relinked); throws with its output when it fails.
export function run(exe, args, { input, timeoutS = 300, quiet = false } = {}) {
  for (let attempt = 0; ; ++attempt) {
    const r = spawnSync(exe, args, { input, encoding: 'utf8', timeout: timeoutS * 1000,
      maxBuffer: 256 << 20 });
    const busy = r.error && ['ETXTBSY', 'ENOENT', 'EACCES'].includes(r.error.code);
    if (busy && attempt < 5) {
      spawnSync('sleep', ['3']);
      continue;
    }
    if (r.error || r.status !== 0) {
      throw new Error(`${exe} ${args.join(' ')} failed (${r.error ? r.error.message : 'exit ' +
        r.status}):\n${r.stdout || ''}${r.stderr || ''}`);
    }
    if (!quiet && r.stdout.trim()) log(r.stdout.trim().split('\n').slice(-3).join('\n'));
    return r.stdout;
  }
}

export function tempDir(name) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), `globe-web-${name}-`));
  if (!process.env.GLOBE_WEB_KEEP) atExit(() => fs.rmSync(dir, { recursive: true, force: true }));
  return dir;
}

// The pyramid the C++ tests call bundled (tests/support/tiler_test_fixture.cpp): the world's
// ETOPO20, the W002N52 square and Fuji's 3″ DEM.
export function bundledPyramid(dir) {
  const out = path.join(dir, 'pyramid');
  const dem = (f) => path.join(sourceDir, 'data/dem', f);
  run(tilerExe(), ['-q', '-o', out, dem('ETOPO20.DEM'), dem('W002N52.DEM'), dem('E138N35_FUJI.DEM')]);
  return out;
}

// A quantized-mesh tree as test_export_trees.cpp makes it: the world's coarse levels, then Fuji's
// square to the deepest level the exporter makes.
export function exportQuantizedMesh(pyramid, out) {
  const bounds = FUJI_BOUNDS.join(',');
  run(tilerExe(), ['export', '--format', 'quantized-mesh', '-o', out, '--levels', '0-3', pyramid]);
  run(tilerExe(), ['export', '--format', 'quantized-mesh', '-o', out, '--levels', '4-14',
    '--bounds', bounds, pyramid]);
  return JSON.parse(fs.readFileSync(path.join(out, 'layer.json'), 'utf8'));
}

export function exportRaster(format, pyramid, out, maxZoom) {
  run(tilerExe(), ['export', '--format', format, '-o', out, '--levels', `0-${maxZoom}`,
    '--bounds', FUJI_BOUNDS.join(','), pyramid]);
}

// `globe query --mode exact` of many points: heights in order.
export function exactHeights(pyramid, points, level) {
  const input = points.map(([lon, lat]) => `${lon.toFixed(10)},${lat.toFixed(10)}`).join('\n') + '\n';
  const args = ['query', '--mode', 'exact', ...(level !== undefined ? ['--level', String(level)] : []), pyramid];
  const out = run(globeExe(), args, { input, quiet: true });
  const heights = out.trim().split('\n').map((l) => l.split(',')).filter((f) => f.length === 4)
    .map((f) => Number(f[3]));
  if (heights.length !== points.length) {
    throw new Error(`globe query gave ${heights.length} heights for ${points.length} points:\n${out}`);
  }
  return heights;
}

// Deterministic points (a small LCG) in [w,e]×[s,n].
export function randomPoints(count, [w, s, e, n], seed = 31) {
  let x = seed >>> 0;
  const next = () => ((x = (Math.imul(x, 1664525) + 1013904223) >>> 0) / 4294967296);
  const points = [];
  for (let i = 0; i < count; ++i) points.push([w + (e - w) * next(), s + (n - s) * next()]);
  return points;
}

export function stats(values) {
  const s = [...values].sort((a, b) => a - b);
  const q = (p) => s[Math.min(s.length - 1, Math.floor(p * s.length))];
  return { median: q(0.5), p95: q(0.95), max: s[s.length - 1], count: s.length };
}

function freePort() {
  return new Promise((resolve, reject) => {
    const srv = net.createServer();
    srv.on('error', reject);
    srv.listen(0, '127.0.0.1', () => {
      const { port } = srv.address();
      srv.close(() => resolve(port));
    });
  });
}

function accepts(port) {
  return new Promise((resolve) => {
    const s = net.connect(port, '127.0.0.1');
    s.on('connect', () => { s.destroy(); resolve(true); });
    s.on('error', () => resolve(false));
  });
}

// nginx on 127.0.0.1 at a free port serving `root` (symlinks followed): quantized-mesh tiles
// (*.terrain, stored gzip-compressed as globe-tiler writes them) with Content-Encoding: gzip and
// their media type, as CesiumJS's servers send them. Runs under `timeout` so it never outlives
// the test; stopped at exit.
export async function startNginx(root, { lifetimeS = 600 } = {}) {
  if (!fs.existsSync(nginxPath)) throw new Error(`${nginxPath} is missing: install nginx-light`);
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'globe-web-nginx-'));
  fs.mkdirSync(path.join(dir, 'tmp'));
  const port = await freePort();
  const conf = `daemon off; master_process off; worker_processes 1;
pid ${dir}/nginx.pid; error_log ${dir}/error.log warn;
events { worker_connections 256; }
http {
  log_format t '$request_method $uri $status $bytes_sent ?$args';
  access_log ${dir}/access.log t;
  client_body_temp_path ${dir}/tmp/b; proxy_temp_path ${dir}/tmp/p;
  fastcgi_temp_path ${dir}/tmp/f; uwsgi_temp_path ${dir}/tmp/u; scgi_temp_path ${dir}/tmp/s;
  types {
    text/html html; text/css css; application/javascript js mjs; application/json json;
    image/png png; image/jpeg jpg; image/svg+xml svg; application/wasm wasm; text/plain txt glsl;
    application/vnd.quantized-mesh terrain;
  }
  default_type application/octet-stream;
  keepalive_requests 100000;
  sendfile on;
  server {
    listen 127.0.0.1:${port};
    root ${path.resolve(root)};
    location ~ \\.terrain$ { add_header Content-Encoding gzip; }
  }
}
`;
  fs.writeFileSync(path.join(dir, 'nginx.conf'), conf);
  const child = spawn('timeout', ['-k', '5', String(lifetimeS), nginxPath, '-p', dir, '-c',
    path.join(dir, 'nginx.conf'), '-e', path.join(dir, 'error.log')], { stdio: 'ignore' });
  let exited = false;
  child.on('exit', () => { exited = true; });
  const stop = () => {
    if (!exited) { try { child.kill('SIGTERM'); } catch { /* gone */ } }
    fs.rmSync(dir, { recursive: true, force: true });
  };
  atExit(stop);
  for (let i = 0; i < 200 && !exited; ++i) {
    if (await accepts(port)) {
      return {
        port, url: (p) => `http://127.0.0.1:${port}${p}`, stop,
        accessLog: () => { try { return fs.readFileSync(path.join(dir, 'access.log'), 'utf8').split('\n').filter(Boolean); } catch { return []; } },
      };
    }
    await new Promise((r) => setTimeout(r, 25));
  }
  let errors = '';
  try { errors = fs.readFileSync(path.join(dir, 'error.log'), 'utf8'); } catch { /* none */ }
  stop();
  throw new Error(`nginx did not start on 127.0.0.1:${port}:\n${errors}`);
}

// Software GL for Chromium's WebGL: Mesa's llvmpipe through ANGLE's EGL backend (the same GL as
// globe's OSMesa), else SwiftShader.
const GL_MODES = {
  llvmpipe: ['--use-gl=angle', '--use-angle=gl-egl'],
  swiftshader: ['--use-gl=angle', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
};

async function launchWith(puppeteer, mode, width, height) {
  const browser = await puppeteer.launch({
    executablePath: chromiumPath,
    headless: true,
    // DevTools over a pipe: Chromium exits when this process does, however it ends.
    pipe: true,
    protocolTimeout: 420000,  // beyond the pages' own waits (300 s), within the test's 540 s
    args: ['--no-sandbox', '--ignore-gpu-blocklist', ...GL_MODES[mode],
      '--disable-dev-shm-usage', '--no-first-run', '--no-default-browser-check',
      '--disable-background-networking', '--disable-component-update', '--disable-sync',
      '--disable-features=Translate,MediaRouter,OptimizationHints',
      '--disable-background-timer-throttling', '--disable-renderer-backgrounding',
      '--disable-backgrounding-occluded-windows', '--disable-frame-rate-limit',
      `--window-size=${width},${height}`],
    defaultViewport: { width, height, deviceScaleFactor: 1 },
  });
  atExit(() => { try { browser.process()?.kill('SIGKILL'); } catch { /* gone */ } });
  const page = await browser.newPage();
  const gl = await page.evaluate(() => {
    const c = document.createElement('canvas');
    const g = c.getContext('webgl2');
    if (!g) return null;
    const ext = g.getExtension('WEBGL_debug_renderer_info');
    return ext ? g.getParameter(ext.UNMASKED_RENDERER_WEBGL) : g.getParameter(g.RENDERER);
  });
  await page.close();
  if (!gl) {
    await browser.close();
    return null;
  }
  return { browser, gl, mode };
}

// Chromium (headless) with WebGL2 on software GL; mode 'llvmpipe' first, else 'swiftshader'
// (GLOBE_WEB_GL forces one).
export async function launchBrowser({ width = 1024, height = 768 } = {}) {
  const { default: puppeteer } = await import('puppeteer-core');
  const modes = process.env.GLOBE_WEB_GL ? [process.env.GLOBE_WEB_GL] : ['llvmpipe', 'swiftshader'];
  for (const mode of modes) {
    const b = await launchWith(puppeteer, mode, width, height);
    if (b) {
      log(`chromium ${await b.browser.version()}, WebGL2 on ${b.gl} (${mode})`);
      return b;
    }
  }
  throw new Error('chromium gives no WebGL2 context with llvmpipe or SwiftShader');
}

// A page whose every request beyond 127.0.0.1 is refused (and listed), whose console errors are
// printed.
export async function openPage(browser, url, { timeoutS = 120 } = {}) {
  const page = await browser.newPage();
  const refused = [];
  await page.setRequestInterception(true);
  page.on('request', (req) => {
    const u = req.url();
    if (/^(data|blob):/.test(u) || u.startsWith('http://127.0.0.1:')) req.continue();
    else { refused.push(u); req.abort('blockedbyclient'); }
  });
  page.on('console', (m) => {
    if ((m.type() === 'error' || m.type() === 'warn') && !m.text().startsWith('Failed to load resource')) {
      log(`  [page ${m.type()}] ${m.text()}`);
    }
  });
  page.on('response', (r) => { if (r.status() >= 400) log(`  [page] ${r.status()} ${r.url()}`); });
  page.on('pageerror', (e) => log(`  [page exception] ${e.message}`));
  page.setDefaultTimeout(timeoutS * 1000);
  await page.goto(url, { waitUntil: 'load', timeout: timeoutS * 1000 });
  return { page, refused };
}

// A site directory for nginx: NAME -> target symlinks.
export function makeSite(dir, links) {
  fs.mkdirSync(dir, { recursive: true });
  for (const [name, target] of Object.entries(links)) {
    fs.symlinkSync(path.resolve(target), path.join(dir, name));
  }
  return dir;
}

export const pagesDir = path.join(webDir, 'pages');
export const cesiumBuild = path.join(webDir, 'node_modules/cesium/Build/Cesium');
export const maplibreDist = path.join(webDir, 'node_modules/maplibre-gl/dist');

// Where the pictures go: GLOBE_WEB_OUT, else the current directory (CTest's: the test's binary
// directory).
export function outputPath(name) {
  const dir = process.env.GLOBE_WEB_OUT || process.cwd();
  fs.mkdirSync(dir, { recursive: true });
  return path.resolve(dir, name);
}

// A web test's checks: check(ok, what) logs each and keeps the failures; finish(body, cleanup)
// runs the test's body, counts a throw as a failure, always cleans up, then exits: 0 when every
// check held, 1 otherwise.
export function checks() {
  const failures = [];
  const check = (ok, what) => {
    log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
    if (!ok) failures.push(what);
  };
  const finish = async (body, cleanup) => {
    try {
      await body();
    } catch (e) {
      failures.push(e.stack || String(e));
      log(`FAIL ${e.stack || e}`);
    } finally {
      await cleanup();
    }
    if (failures.length) {
      console.log(`${failures.length} check(s) failed`);
      process.exit(1);
    }
    console.log('all checks passed');
    process.exit(0);
  };
  return { check, finish };
}
