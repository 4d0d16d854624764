#!/usr/bin/env node
// Browser test of the viewer pages (docs/viewer.md): builds pages with the CLI (the demo scenes, a
// `view` of a traced result, a porosity bed), opens each in headless Chromium through
// puppeteer-core, fails on any console error, page error or failed request, checks the scene's
// counts of meshes, curves and markers against the result JSON, clicks a curve and checks the
// point panel against the JSON, switches the colouring, and saves a screenshot of each page.
//   node tests/browser/viewer_test.mjs --ssimarch build/bin/ssimarch --work DIR [--shots DIR]
// Exit 77 (ctest: skipped) with the reason when Chromium or viewer/node_modules is missing.
import { createRequire } from 'node:module';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const args = Object.fromEntries(process.argv.slice(2).reduce((a, x, i, all) => (x.startsWith('--') ? [...a, [x.slice(2), all[i + 1]]] : a), []));
const ssimarch = args.ssimarch, work = path.resolve(args.work || 'browser-test'), shots = path.resolve(args.shots || work);
const chromium = args.chromium || process.env.SSIMARCH_CHROMIUM || ['/usr/bin/chromium', '/usr/bin/chromium-browser'].find((p) => fs.existsSync(p));

function skip(reason) {
  console.log(`SKIPPED: ${reason}`);
  process.exit(77);
}
if (!chromium) skip('no Chromium (Debian package chromium; scripts/install-deps installs it)');
let puppeteer;
try {
  puppeteer = createRequire(path.join(root, 'viewer/package.json'))('puppeteer-core');
} catch {
  skip('viewer/node_modules has no puppeteer-core (scripts/install-deps runs npm ci in viewer/)');
}

let failures = 0;
function check(ok, what) {
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
  if (!ok) failures += 1;
}
const run = (...a) => execFileSync(ssimarch, a, { stdio: ['ignore', 'pipe', 'pipe'] }).toString();
const readJson = (f) => JSON.parse(fs.readFileSync(f, 'utf8'));
const fmt10 = (x) => String(Number(x.toPrecision(10)));

// Pages: the demo's (one per scene), a `view` of a traced result with an isolated point, a bed.
fs.rmSync(work, { recursive: true, force: true });
fs.mkdirSync(work, { recursive: true });
fs.mkdirSync(shots, { recursive: true });
try {
  run('demo', '--out', work, '--no-porosity');
} catch (e) {
  if (/built without the HTML viewer/.test(String(e.stderr))) skip('ssimarch was built without the viewer bundle');
  throw e;
}
if (!fs.existsSync(path.join(work, 'viviani.html'))) skip('ssimarch was built without the viewer bundle (no pages from demo)');
// The reference of each demo page: its scene traced again with the exact geometry (the page's data).
function traceResult(scene, file) {
  try { run('trace', scene, '-o', file, '--geometry', 'exact', '-q'); } catch (e) { if (e.status !== 1) throw e; }
  return readJson(file).intersections;
}
const pages = fs.readdirSync(work).filter((f) => f.endsWith('.html')).map((f) => {
  const stem = f.replace(/\.html$/, ''), sceneFile = path.join(work, `${stem}.scene.json`);
  return { name: stem, file: path.join(work, f), result: traceResult(sceneFile, path.join(work, `${stem}.result.json`)),
    scene: readJson(sceneFile) };
});
{
  const scene = path.join(root, 'examples/thesis_ex16_isolated_point.json');
  const result = path.join(work, 'ex16.json'), intersections = traceResult(scene, result);
  run('view', result, '--scene', scene, '-o', path.join(work, 'ex16.html'));
  pages.push({ name: 'ex16', file: path.join(work, 'ex16.html'), result: intersections, scene: readJson(scene) });
}
const bed = path.join(work, 'bed.csv');
run('packing', 'spheres', '--container-radius', '3', '--count', '400', '--seed', '5', '-o', bed);
run('porosity', bed, '--container-radius', '3', '--radii', '60', '--axial', '30', '--map', '12,16', '-o', path.join(work, 'bed_profile.csv'),
  '--html', path.join(work, 'bed.html'));
const particles = fs.readFileSync(bed, 'utf8').trim().split('\n').length - 1;

function expectedCounts(p) {
  const used = new Set(p.result.flatMap((r) => r.surfaces));
  let curves = 0, markers = 0;
  for (const r of p.result) {
    curves += r.curves.length;
    markers += r.singular_points.length + r.isolated_points.length + 2 * r.curves.filter((c) => !c.closed).length;
  }
  for (const i of p.scene.intersections) if (i.start && p.result.some((r) => r.name === i.name)) markers += Array.isArray(i.start[0]) ? i.start.length : 1;
  return { meshes: used.size, curves, markers };
}

const browser = await puppeteer.launch({
  executablePath: chromium,
  headless: true,
  args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--window-size=1280,800'],
});
try {
  for (const p of [...pages, { name: 'bed', file: path.join(work, 'bed.html'), porosity: true }]) {
    const page = await browser.newPage();
    await page.setViewport({ width: 1280, height: 800 });
    const errors = [];
    page.on('console', (m) => { if (m.type() === 'error') errors.push(`console: ${m.text()}`); });
    page.on('pageerror', (e) => errors.push(`page error: ${e.message}`));
    page.on('requestfailed', (r) => errors.push(`request failed: ${r.url()} ${r.failure()?.errorText}`));
    const requests = [];
    page.on('request', (r) => requests.push(r.url()));
    await page.goto(pathToFileURL(p.file).href, { waitUntil: 'load' });
    await page.waitForFunction(() => window.ssimarchViewer?.ready, { timeout: 60000 });
    const counts = await page.evaluate(() => window.ssimarchViewer.counts);
    if (p.porosity) {
      check(counts.particles === particles, `${p.name}: ${counts.particles} particles drawn, ${particles} in the packing`);
      check(counts.plots === 3, `${p.name}: radial, axial and map plots (${counts.plots})`);
    } else {
      const want = expectedCounts(p);
      check(counts.meshes === want.meshes && counts.curves === want.curves && counts.markers === want.markers,
        `${p.name}: meshes ${counts.meshes}/${want.meshes}, curves ${counts.curves}/${want.curves}, markers ${counts.markers}/${want.markers}`);
      // Click about a quarter along the first curve, at a point with a curvature and away from
      // singular points (where kappa is undetermined); the panel must show a point of the result.
      const curve = p.result.flatMap((r) => r.curves)[0];
      if (curve) {
        const finite = (i) => [-3, -2, -1, 0, 1, 2, 3].every((d) => curve.points[i + d]?.kappa != null);
        let index = Math.floor(curve.points.length / 4);
        while (index < curve.points.length - 4 && !finite(index)) index += 1;
        const at = await page.evaluate((i) => window.ssimarchViewer.screenPoint(0, i), index);
        await page.mouse.click(at.x, at.y);
        const info = await page.evaluate(() => window.ssimarchViewer.info());
        const m = /^(\S+) · curve (\d+) · point (\d+)/.exec(info);
        const picked = m && p.result.find((r) => r.name === m[1])?.curves[Number(m[2])];
        const point = picked?.points[Number(m[3])];
        const xyzOk = point && info.includes(`xyz    ${point.xyz.map((x) => String(Number(x.toPrecision(7)))).join(', ')}`);
        const kappa = Number(/κ {6}(\S+)/.exec(info)?.[1]);
        const kappaOk = point?.kappa != null && Math.abs(kappa - point.kappa) <= 1e-5 * Math.abs(point.kappa) + 1e-12;
        check(!!picked && xyzOk && kappaOk && info.includes(`length ${fmt10(picked.length)}`),
          `${p.name}: click on a curve shows its point, κ and length (${info.split('\n')[0]})`);
      }
      await page.select('select', 'kappa');
    }
    await page.evaluate(() => window.ssimarchViewer.render());
    await page.screenshot({ path: path.join(shots, `viewer-${p.name}.png`) });
    const remote = requests.filter((u) => !u.startsWith('file:') && !u.startsWith('data:') && !u.startsWith('blob:'));
    check(remote.length === 0, `${p.name}: no network requests (${remote.length})`);
    check(errors.length === 0, `${p.name}: no console errors or failed requests${errors.length ? ': ' + errors.join('; ') : ''}`);
    await page.close();
  }
} finally {
  await browser.close();
}
console.log(failures ? `${failures} check(s) failed` : 'all checks passed');
process.exit(failures ? 1 : 0);
