// globe regress's report.html as a person opens it: a suite of one view of the bundled pyramid
// whose reference was made with another camera heading (so the view fails), the report folder
// served by nginx on 127.0.0.1 and opened in headless Chromium. The failed view's expected,
// actual and diff images must all load, at the view's size, side by side; the summary must say
// one failed. regress-report.png is saved (a screenshot of the page).
import fs from 'node:fs';
import path from 'node:path';
import { spawnSync } from 'node:child_process';
import * as h from '../../tools/web/lib/harness.mjs';

h.watchdog(Number(process.env.GLOBE_WEB_TIMEOUT_S || 540), 'the regress report test');
const { check, finish } = h.checks();

const work = h.tempDir('regress');
h.bundledPyramid(work);
const suiteOf = (heading) => JSON.stringify({ views: [{ name: 'fuji', snapshot: ['pyramid',
  '--camera', `138.60,35.20,6000,${heading},-15,0`, '--size', '320x180'] }] });
const suite = path.join(work, 'suite.json');
const out = path.join(work, 'out');
const regress = (...more) => spawnSync(h.globeExe(),
  ['regress', suite, '--out', out, '--jobs', '1', ...more], { encoding: 'utf8', timeout: 300000 });
fs.writeFileSync(suite, suiteOf(30));
const update = regress('--update');
check(update.status === 0, `--update writes the reference (exit ${update.status}) ${update.stderr}`);
fs.writeFileSync(suite, suiteOf(34));
const changed = regress();
check(changed.status === 1, `globe regress exits 1 for the changed view (exit ${changed.status})`);

const server = await h.startNginx(h.makeSite(path.join(work, 'site'), { report: out }));
const { browser } = await h.launchBrowser({ width: 1280, height: 800 });
await finish(async () => {
  const { page, refused } = await h.openPage(browser, server.url('/report/report.html'));
  const images = await page.evaluate(() => [...document.images].map((i) => ({
    src: i.getAttribute('src'), width: i.naturalWidth, height: i.naturalHeight,
    top: Math.round(i.getBoundingClientRect().top), complete: i.complete })));
  h.log(`images: ${JSON.stringify(images)}`);
  const wanted = ['fuji.expected.png', 'fuji.actual.png', 'fuji.diff.png'];
  check(wanted.every((src) => images.some((i) => i.src === src && i.complete && i.width === 320 &&
    i.height === 180)), 'the expected, actual and diff images load at 320x180');
  check(new Set(images.map((i) => i.top)).size === 1, 'side by side (one row)');
  const summary = await page.evaluate(() => document.querySelector('p').textContent);
  check(/1 failed/.test(summary), `the summary says one failed: "${summary}"`);
  const status = await page.evaluate(() => document.querySelector('td.fail')?.textContent);
  check(status === 'fail', 'the table marks the view failed');
  await page.screenshot({ path: h.outputPath('regress-report.png') });
  check(refused.length === 0, 'no request beyond 127.0.0.1');
}, async () => {
  await browser.close().catch(() => {});
  server.stop();
});
