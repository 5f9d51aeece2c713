// The comparison page (demos/compare.html) measured in headless Chromium: for each scene and body
// count, the page is opened at ?scene=NAME&bodies=N, both panes step until each has taken `--steps`
// steps after `--warmup` (or the time budget runs out), and the page's own medians
// (window.webphysicsDemo: step time over the last second) are read. Where no GPU is, Chromium's
// WebGPU runs on SwiftShader (a CPU Vulkan driver), so this gives the crossover as the page shows
// it on such a machine; bench/gpu-compare.ts times the same code on a real GPU through Dawn.
//
//   node bench/compare-browser.mjs [--scenes pyramids,rain] [--sizes 100,1000,10000,100000]
//        [--steps 5] [--warmup 3] [--budget 90] [--out DIR]
//
// Writes compare-browser.json and .md to --out or bench/results; the table on stdout.
import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { cpus, tmpdir } from 'node:os';
import path from 'node:path';
import { parseArgs } from 'node:util';
import puppeteer from 'puppeteer-core';
import { chromiumArgs, chromiumPath } from '../scripts/chromium.mjs';
import { buildDemos } from '../scripts/build-demos.mjs';
import { startServer } from '../scripts/serve.mjs';

const { values } = parseArgs({
  options: {
    scenes: { type: 'string', default: 'pyramids,rain' },
    sizes: { type: 'string', default: '100,1000,10000,100000' },
    steps: { type: 'string', default: '5' },
    warmup: { type: 'string', default: '3' },
    budget: { type: 'string', default: '90' },
    out: { type: 'string', default: path.resolve('bench/results') },
  },
});
const scenes = values.scenes.split(',');
const sizes = values.sizes.split(',').map(Number);
const steps = Number(values.steps);
const warmup = Number(values.warmup);
const budget = Number(values.budget);

const dir = mkdtempSync(path.join(tmpdir(), 'webphysics-compare-'));
await buildDemos(dir);
const server = await startServer({ root: dir, port: 0 });
const browser = await puppeteer.launch({ executablePath: chromiumPath(), headless: true, args: chromiumArgs({ webgpu: true }), protocolTimeout: 600_000 });
const rows = [];
const version = await browser.version();
let adapter = null;
try {
  for (const scene of scenes) {
    for (const bodies of sizes) {
      const page = await browser.newPage();
      await page.goto(`${server.url}compare.html?scene=${scene}&bodies=${bodies}`);
      const started = Date.now();
      // Steps each pane has taken when its warm-up ended, then the medians once `steps` more came.
      const mark = { js: null, webgpu: null };
      const result = { scene, bodies, js: null, webgpu: null };
      while (Date.now() - started < 1000 * budget) {
        await new Promise((resolve) => setTimeout(resolve, 500));
        const demo = await page.evaluate(() => window.webphysicsDemo);
        for (const pane of demo.panes) {
          if (pane.backend === 'webgpu') adapter = pane.adapter;
          if (mark[pane.backend] === null && pane.steps >= warmup) mark[pane.backend] = pane.steps;
          if (mark[pane.backend] !== null && pane.steps >= mark[pane.backend] + steps) result[pane.backend] = { ms: pane.stepMs, steps: pane.steps };
        }
        if (result.js !== null && result.webgpu !== null) break;
      }
      // A pane too slow for the budget: its median so far, if it stepped at all.
      const demo = await page.evaluate(() => window.webphysicsDemo);
      for (const pane of demo.panes)
        if (result[pane.backend] === null && pane.steps > 0) result[pane.backend] = { ms: pane.stepMs, steps: pane.steps, partial: true };
      rows.push(result);
      const cell = (r) => (r === null ? '–' : `${r.ms.toFixed(1)} ms (${r.steps} steps${r.partial ? ', budget ran out' : ''})`);
      console.error(`${scene.padEnd(10)} ${String(bodies).padStart(7)}  js ${cell(result.js)}, webgpu ${cell(result.webgpu)}`);
      await page.close();
    }
  }
} finally {
  await browser.close();
  await server.close();
  rmSync(dir, { recursive: true, force: true });
}

const meta = {
  browser: version,
  adapter,
  cpu: `${cpus()[0]?.model ?? 'unknown'} (${cpus().length} threads)`,
  date: new Date().toISOString(),
  steps,
  warmup,
  budget,
};
const fmt = (r) => (r === null ? '–' : `${r.ms < 10 ? r.ms.toFixed(2) : r.ms.toFixed(0)}${r.partial ? '*' : ''}`);
const lines = [
  '# The comparison page in headless Chromium, WebGPU on SwiftShader',
  '',
  `${meta.browser}; WebGPU adapter: ${meta.adapter}; CPU: ${meta.cpu}. ${meta.date}.`,
  `\`node bench/compare-browser.mjs\`: compare.html at each scene and size; each pane's median step time over the last second (the page's`,
  `own figure) once it has taken ${steps} steps after ${warmup}, within ${budget} s. Milliseconds per step; * the budget ran out first.`,
  '',
  '| scene | bodies | JS pane | WebGPU pane | JS/GPU |',
  '| --- | ---: | ---: | ---: | ---: |',
  ...rows.map((r) => `| ${r.scene} | ${r.bodies} | ${fmt(r.js)} | ${fmt(r.webgpu)} | ${r.js && r.webgpu ? (r.js.ms / r.webgpu.ms).toPrecision(3) : '–'} |`),
  '',
];
mkdirSync(values.out, { recursive: true });
writeFileSync(path.join(values.out, 'compare-browser.json'), JSON.stringify({ meta, rows }, null, 2) + '\n');
writeFileSync(path.join(values.out, 'compare-browser.md'), lines.join('\n'));
process.stdout.write(lines.join('\n'));
