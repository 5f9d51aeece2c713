// The demo pages (demos/): bundles the testbed (demos/main.ts) into <outDir>/testbed.js, the
// comparison page (demos/compare/main.ts, and its worker) into compare.js and compare-worker.js
// the accuracy page (demos/accuracy/main.ts) into accuracy.js, the large-world page
// (demos/large/main.ts) into large.js, and the sand, Brownian motion and touch pages
// (demos/sand, demos/brownian, demos/touch) into sand.js, brownian.js and touch.js with esbuild,
// and copies the
// HTML and CSS beside them, and the accuracy studies' results (accuracy.json, accuracy-h100.json). `node scripts/build-demos.mjs [outDir]`
// (default demos/dist); `npm start` calls buildDemos() and serves the folder. The WebGPU backend's
// WGSL is inlined as text; its Node-only imports (Dawn, node:*) are on a code path a browser never
// takes, so they stay external.
//
// The benchmark scenes come from bench/scenes.mjs, a Node module: its node:fs, node:path and
// node:url imports are replaced by small browser stand-ins, and the one data file it reads (the
// golden mixed-rain scene) is embedded when the golden folder is there at build time.
import { build, context } from 'esbuild';
import { copyFileSync, existsSync, mkdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

export const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
export const defaultOutDir = path.join(repoRoot, 'demos', 'dist');

/** The golden folder ($WEBPHYSICS_GOLDEN or ../shared/golden beside the checkout), or null. */
function goldenDir() {
  const dir = process.env.WEBPHYSICS_GOLDEN ?? path.resolve(repoRoot, '..', 'shared', 'golden');
  return existsSync(dir) ? dir : null;
}

/** esbuild plugin: browser stand-ins for the Node built-ins bench/scenes.mjs imports. */
function nodeShims() {
  const golden = goldenDir();
  const files = {};
  if (golden !== null) {
    const mixedRain = path.join(golden, 'scenes', 'mixed-rain.scene.json');
    if (existsSync(mixedRain)) files['mixed-rain.scene.json'] = readFileSync(mixedRain, 'utf8');
  }
  const sources = {
    fs: `const files = ${JSON.stringify(files)};
const base = (f) => String(f).split('/').pop();
export function existsSync(f) { return Object.prototype.hasOwnProperty.call(files, base(f)); }
export function readFileSync(f) {
  if (!existsSync(f)) throw new Error('not embedded in the testbed bundle: ' + f);
  return files[base(f)];
}`,
    path: `const join = (...parts) => parts.filter((p) => p !== '').join('/');
export default { join, resolve: join, dirname: (p) => String(p).split('/').slice(0, -1).join('/') };`,
    url: `export function fileURLToPath(u) { return String(u ?? ''); }
export function pathToFileURL(p) { return new URL(String(p), 'file:///'); }`,
  };
  return {
    name: 'node-shims',
    setup(b) {
      b.onResolve({ filter: /^node:(fs|path|url)$/ }, (args) => ({ path: args.path.slice(5), namespace: 'node-shim' }));
      b.onLoad({ filter: /.*/, namespace: 'node-shim' }, (args) => ({ contents: sources[args.path], loader: 'js' }));
    },
  };
}

const kEntries = {
  testbed: path.join(repoRoot, 'demos', 'main.ts'),
  compare: path.join(repoRoot, 'demos', 'compare', 'main.ts'),
  'compare-worker': path.join(repoRoot, 'demos', 'compare', 'worker.ts'),
  accuracy: path.join(repoRoot, 'demos', 'accuracy', 'main.ts'),
  large: path.join(repoRoot, 'demos', 'large', 'main.ts'),
  sand: path.join(repoRoot, 'demos', 'sand', 'main.ts'),
  brownian: path.join(repoRoot, 'demos', 'brownian', 'main.ts'),
  touch: path.join(repoRoot, 'demos', 'touch', 'main.ts'),
};
const kStatic = [
  'index.html',
  'page.css',
  'testbed.css',
  'header.css',
  'compare.html',
  'compare.css',
  'accuracy.html',
  'accuracy.css',
  'large.html',
  'large.css',
  'sand.html',
  'brownian.html',
  'touch.html',
];
/**
 * The accuracy studies the accuracy page draws (bench/accuracy/run.mjs writes them): this
 * machine's, and one on an H100 where the GPU's runs are timed.
 */
const kAccuracyResults = ['accuracy.json', 'accuracy-h100.json'];

function options(outDir) {
  return {
    entryPoints: kEntries,
    outdir: outDir,
    bundle: true,
    format: 'esm',
    platform: 'browser',
    target: 'es2020',
    sourcemap: true,
    logLevel: 'warning',
    legalComments: 'inline',
    define: { 'process.env.WEBPHYSICS_GOLDEN': 'undefined' },
    loader: { '.wgsl': 'text' },
    external: ['webgpu', 'node:*'],
    plugins: [nodeShims()],
  };
}

function copyStatic(outDir) {
  for (const file of kStatic) copyFileSync(path.join(repoRoot, 'demos', file), path.join(outDir, file));
  for (const file of kAccuracyResults) copyFileSync(path.join(repoRoot, 'bench', 'results', 'accuracy', file), path.join(outDir, file));
}

/** Build the page into outDir. With watch, rebuild on every change (returns the esbuild context). */
export async function buildDemos(outDir = defaultOutDir, { watch = false } = {}) {
  mkdirSync(outDir, { recursive: true });
  copyStatic(outDir);
  if (!watch) {
    await build(options(outDir));
    return null;
  }
  const ctx = await context({
    ...options(outDir),
    plugins: [...options(outDir).plugins, { name: 'copy-static', setup: (b) => b.onEnd(() => copyStatic(outDir)) }],
  });
  await ctx.watch();
  return ctx;
}

if (import.meta.url === pathToFileURL(process.argv[1] ?? '').href) {
  const outDir = path.resolve(process.argv[2] ?? defaultOutDir);
  await buildDemos(outDir);
  console.log(`Built the demo pages into ${path.relative(process.cwd(), outDir) || '.'}`);
}
