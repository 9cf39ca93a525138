// Headless-browser checks of view.html (run by scripts/browser-tests.sh, which installs
// playwright-core next to a copy of this file). Usage:
//   node check.mjs OUT_DIR [--screenshots DIR]
// OUT_DIR holds the run folders tennis_racket, four_bar, business_jet_doublet, chain30.
// Each page is opened from file:// with every other request refused, and checked for: no console
// error; a canvas that is not blank; frames at t = start and t = end that differ where the moving
// parts are drawn and agree elsewhere (statistics of 64 × 40 cells of mean luminance; the moving
// parts are found by drawing each instant again with them hidden; with them hidden the two
// instants look the same, except under the flight view's following camera); the slider,
// play and keyboard changing the drawn time through the page's hooks (window.vectrixView).
// The 30-link chain is played for 3 s and its frame time printed.
import { chromium } from 'playwright-core';
import path from 'node:path';

const [outDir, flag, shots] = process.argv.slice(2);
const executablePath = process.env.CHROMIUM || '/usr/bin/chromium';
const browser = await chromium.launch({
  executablePath,
  args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist'],
});
let failures = 0;
const fail = (scene, what) => { failures++; console.log(`FAIL ${scene}: ${what}`); };
const CELLS = [64, 40];
// Differences of mean cell luminance above TOL (of 255) count as "differ": antialiasing and
// the software rasterizer's rounding stay far below it.
const TOL = 6;

async function open(scene) {
  const page = await browser.newPage({ viewport: { width: 960, height: 600 } });
  const errors = [], requests = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.route('**/*', (route) => {
    const url = route.request().url();
    if (url.startsWith('file:') && url.endsWith('/view.html')) return route.continue();
    requests.push(url);
    return route.abort();
  });
  await page.goto('file://' + path.resolve(outDir, scene, 'view.html'));
  await page.waitForFunction(() => window.vectrixView !== undefined, null, { timeout: 20000 });
  await page.evaluate(() => window.vectrixView.pause());
  return { page, errors, requests };
}

// mean luminance of each cell of the WebGL canvas, after drawing time t
async function cells(page, t, moving = true) {
  return page.evaluate(([t, moving, [nx, ny]]) => {
    const v = window.vectrixView;
    v.showMoving(moving);
    v.setTime(t);
    const src = document.querySelector('#view canvas');
    const c = document.createElement('canvas');
    c.width = src.width; c.height = src.height;
    const g = c.getContext('2d');
    g.drawImage(src, 0, 0);
    const px = g.getImageData(0, 0, c.width, c.height).data;
    const out = new Array(nx * ny).fill(0), n = new Array(nx * ny).fill(0);
    for (let y = 0; y < c.height; y++) for (let x = 0; x < c.width; x++) {
      const i = 4 * (y * c.width + x), k = Math.floor(y * ny / c.height) * nx + Math.floor(x * nx / c.width);
      out[k] += 0.2126 * px[i] + 0.7152 * px[i + 1] + 0.0722 * px[i + 2]; n[k]++;
    }
    v.showMoving(true);
    return out.map((s, k) => s / n[k]);
  }, [t, moving, CELLS]);
}

async function check(scene, follows) {
  const { page, errors, requests } = await open(scene);
  const v = await page.evaluate(() => ({ start: window.vectrixView.start, end: window.vectrixView.end, frames: window.vectrixView.frames }));
  if (!(v.frames >= 2 && v.end > v.start)) fail(scene, `no motion: ${JSON.stringify(v)}`);
  const a = await cells(page, v.start), b = await cells(page, v.end);
  const a0 = await cells(page, v.start, false), b0 = await cells(page, v.end, false);
  // not blank: the cells are not all one shade
  const mean = a.reduce((s, x) => s + x, 0) / a.length;
  const sd = Math.sqrt(a.reduce((s, x) => s + (x - mean) ** 2, 0) / a.length);
  if (!(sd > 2)) fail(scene, `blank canvas (luminance sd ${sd.toFixed(2)})`);
  // where the moving parts are drawn at either end (they change a cell of the background)
  const moving = a.map((x, k) => Math.abs(x - a0[k]) > TOL || Math.abs(b[k] - b0[k]) > TOL);
  // where the background itself is the same at both ends
  const still = a0.map((x, k) => !moving[k] && Math.abs(x - b0[k]) <= TOL);
  const nMoving = moving.filter(Boolean).length, nStill = still.filter(Boolean).length;
  const changed = moving.filter((m, k) => m && Math.abs(a[k] - b[k]) > TOL).length;
  const stillDiff = still.reduce((m, s, k) => (s ? Math.max(m, Math.abs(a[k] - b[k])) : m), 0);
  if (nMoving === 0) fail(scene, 'nothing that moves is drawn');
  if (!(changed >= 0.1 * nMoving)) fail(scene, `t = start and t = end agree where the bodies are (${changed} of ${nMoving} cells differ)`);
  if (!(nStill >= 0.3 * a.length)) fail(scene, `too little still background (${nStill} cells)`);
  if (!(stillDiff <= TOL)) fail(scene, `t = start and t = end differ where nothing moves (by ${stillDiff.toFixed(1)})`);
  // with the moving parts hidden, a fixed camera sees the same picture at both ends; a flight
  // view follows the aircraft, so its ground grid moves and only the other cells are compared
  const background = a0.filter((x, k) => Math.abs(x - b0[k]) > TOL).length;
  if (!follows && background > 0) fail(scene, `with the moving parts hidden, ${background} cells differ between t = start and t = end`);
  // the slider, play and the keyboard change the drawn time
  const mid = v.start + 0.5 * (v.end - v.start);
  const slid = await page.evaluate(() => { const s = document.getElementById('slider'); s.value = '500'; s.dispatchEvent(new Event('input')); return window.vectrixView.drawnTime(); });
  if (!(Math.abs(slid - mid) <= 1e-9 * Math.max(1, Math.abs(mid)))) fail(scene, `slider to 500/1000 drew t = ${slid}, not ${mid}`);
  await page.keyboard.press('ArrowRight');
  const stepped = await page.evaluate(() => window.vectrixView.drawnTime());
  if (!(Math.abs(stepped - (mid + (v.end - v.start) / 100)) <= 1e-9 * Math.max(1, Math.abs(mid)))) fail(scene, `→ drew t = ${stepped}`);
  await page.keyboard.press('9');
  if ((await page.evaluate(() => window.vectrixView.speed())) !== 10) fail(scene, 'digit 9 did not set 10×');
  await page.keyboard.press('4');
  await page.evaluate((t) => { window.vectrixView.setTime(t); window.vectrixView.play(); }, v.start);
  await page.waitForTimeout(600);
  const played = await page.evaluate(() => { window.vectrixView.pause(); return window.vectrixView.drawnTime(); });
  if (!(played > v.start)) fail(scene, `play did not advance the drawn time (${played})`);
  await page.keyboard.press(' ');
  const spacePlays = await page.evaluate(() => window.vectrixView.playing());
  if (!spacePlays) fail(scene, 'space did not start playing');
  if (errors.length) fail(scene, `console errors: ${errors.join(' | ')}`);
  if (requests.length) fail(scene, `requests beyond the file: ${requests.join(', ')}`);
  console.log(`${scene}: ${v.frames} frames, t = ${v.start} … ${v.end}; ${nMoving} moving cells (${changed} differ), ` +
    `${nStill} still cells (largest difference ${stillDiff.toFixed(1)}/255), ${background} background cells differ, slider/keys/play ok`);
  return page;
}

for (const scene of ['tennis_racket', 'four_bar', 'business_jet_doublet']) {
  const page = await check(scene, scene === 'business_jet_doublet');
  if (scene === 'tennis_racket' && flag === '--screenshots') {
    for (const [name, f] of [['view-start', 0], ['view-flip', 0.36]]) {
      await page.evaluate((f) => { const v = window.vectrixView; v.pause(); v.setTime(v.start + f * (v.end - v.start)); }, f);
      await page.screenshot({ path: path.join(shots, `tennis_racket-${name}.png`) });
    }
  }
  await page.close();
}

// frame time of a 30-link chain: play for 3 s and average the intervals between frames
{
  const { page, errors } = await open('chain30');
  await page.evaluate(() => { window.vectrixView.setSpeed(1); window.vectrixView.play(); });
  await page.waitForTimeout(3000);
  const m = await page.evaluate(() => ({ frame: window.vectrixView.frameTimeMs(), render: window.vectrixView.renderMs(), bodies: window.vectrixView.bodies }));
  if (errors.length) fail('chain30', `console errors: ${errors.join(' | ')}`);
  if (!(m.bodies === 30 && Number.isFinite(m.frame) && Number.isFinite(m.render))) fail('chain30', JSON.stringify(m));
  console.log(`chain30: ${m.bodies} bodies, mean frame interval ${m.frame.toFixed(1)} ms (${(1000 / m.frame).toFixed(0)} fps), ` +
    `mean update + render ${m.render.toFixed(1)} ms (headless Chromium, software WebGL: SwiftShader)`);
  await page.close();
}
await browser.close();
if (failures) { console.log(`${failures} browser check(s) failed`); process.exit(1); }
console.log('browser checks passed');
