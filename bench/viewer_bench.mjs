#!/usr/bin/env node
// Page size, load time and orbiting frame rate of viewer pages in headless Chromium (docs/benchmarks.md,
// "Viewer"): the demo scenes' pages and a porosity page of a 1e5-sphere bed (a simple cubic lattice of
// spacing 1.02 d in a cylinder, so the bed is made in no time and no two spheres touch).
//   node bench/viewer_bench.mjs --ssimarch build/bin/ssimarch [--work DIR] [--particles 100000] [--loads 3] [--frames 30]
// Load time: navigation start to the viewer's `ready` (data parsed, scene built, first frame drawn),
// median of --loads loads. Frame rate: --frames frames (default 30) of a quarter turn about the target,
// each rendered and finished (gl.finish). Chromium renders with SwiftShader (software WebGL) here: a desktop GPU is faster.
import { createRequire } from 'node:module';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import os from 'node:os';
import { fileURLToPath, pathToFileURL } from 'node:url';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const args = Object.fromEntries(process.argv.slice(2).reduce((a, x, i, all) => (x.startsWith('--') ? [...a, [x.slice(2), all[i + 1]]] : a), []));
const ssimarch = args.ssimarch || path.join(root, 'build/bin/ssimarch');
const work = path.resolve(args.work || path.join(os.tmpdir(), 'ssimarch-viewer-bench'));
const count = Number(args.particles || 100000), loads = Number(args.loads || 3), frames = Number(args.frames || 30);
const puppeteer = createRequire(path.join(root, 'viewer/package.json'))('puppeteer-core');
const run = (...a) => execFileSync(ssimarch, a, { stdio: ['ignore', 'pipe', 'inherit'] });

fs.rmSync(work, { recursive: true, force: true });
fs.mkdirSync(work, { recursive: true });
run('demo', '--out', work, '--no-porosity');
const pages = fs.readdirSync(work).filter((f) => f.endsWith('.html')).map((f) => ({ name: f.replace('.html', ''), file: path.join(work, f) }));

// A simple cubic lattice of unit spheres inside a cylinder of radius R, `count` of them.
const R = 20, a = 1.02, lines = ['x,y,z,d'];
for (let k = 0; lines.length <= count; ++k)
  for (let i = -R; i <= R && lines.length <= count; ++i)
    for (let j = -R; j <= R && lines.length <= count; ++j) {
      const x = i * a, y = j * a;
      if (Math.hypot(x, y) <= R - 0.5) lines.push(`${x.toFixed(4)},${y.toFixed(4)},${(0.5 + k * a).toFixed(4)},1`);
    }
fs.writeFileSync(path.join(work, 'lattice.csv'), lines.join('\n') + '\n');
run('porosity', path.join(work, 'lattice.csv'), '--container-radius', String(R), '--radii', '100', '--axial', '50',
  '-o', path.join(work, 'lattice_profile.csv'), '--html', path.join(work, 'lattice.html'));
pages.push({ name: `bed of ${count} spheres`, file: path.join(work, 'lattice.html') });

const browser = await puppeteer.launch({
  executablePath: args.chromium || '/usr/bin/chromium',
  headless: true,
  protocolTimeout: 1800000,
  args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
});
const version = await browser.version();
const rows = [];
for (const p of pages) {
  const times = [];
  let fps = null;
  for (let l = 0; l < loads; ++l) {
    const page = await browser.newPage();
    await page.setViewport({ width: 1280, height: 800 });
    await page.goto(pathToFileURL(p.file).href, { waitUntil: 'load', timeout: 300000 });
    await page.waitForFunction(() => window.ssimarchViewer?.ready, { timeout: 300000 });
    times.push(await page.evaluate(() => window.ssimarchViewer.readyMs));
    if (l === 0) fps = (await page.evaluate((n) => window.ssimarchViewer.measureOrbit(n, 90), frames)).fps;
    await page.close();
  }
  times.sort((x, y) => x - y);
  rows.push({ page: p.name, bytes: fs.statSync(p.file).size, load_ms: times[Math.floor(times.length / 2)], fps });
}
await browser.close();
console.log(`Chromium ${version}, ${os.cpus().length} CPUs (${os.cpus()[0].model}), load average ${os.loadavg()[0].toFixed(1)}`);
console.log('| page | size (MB) | load (ms) | orbit (frames/s) |\n| --- | --- | --- | --- |');
for (const r of rows) console.log(`| ${r.page} | ${(r.bytes / 1e6).toFixed(2)} | ${Math.round(r.load_ms)} | ${r.fps.toFixed(1)} |`);
