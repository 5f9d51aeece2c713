// npm run build, first half: the ES module (webphysics.mjs) and its CommonJS twin (webphysics.cjs,
// for require()), the classic-script bundle that defines the global `Box2D` (and Box2DWeb's `Vector`
// globals) as Box2DWeb's script does (plain and minified), the WebGPU backend for browsers (webphysics-gpu.mjs) and for Node
// (webphysics-gpu.node.mjs), and the command line (cli.mjs), all with source maps. The
// declarations come from scripts/build-types.mjs, which the npm script runs after this.
import { build } from 'esbuild';
import { rmSync } from 'node:fs';
import path from 'node:path';

// The output folder: dist, or the first argument (the tests build into a temporary folder).
const outDir = process.argv[2] ?? 'dist';
rmSync(outDir, { recursive: true, force: true });

const common = {
  bundle: true,
  sourcemap: true,
  target: 'es2020',
  logLevel: 'warning',
  legalComments: 'inline',
};

const gpu = { ...common, entryPoints: ['src-gpu/index.ts'], format: 'esm', loader: { '.wgsl': 'text' } };

/** esbuild plugin: src-gpu/device/nodeImports.browser.ts in place of ./nodeImports. */
const browserNodeImports = {
  name: 'browser-node-imports',
  setup(b) {
    b.onResolve({ filter: /^\.\/nodeImports$/ }, (args) => ({ path: path.join(args.resolveDir, 'nodeImports.browser.ts') }));
  },
};

await Promise.all([
  build({ ...common, entryPoints: ['src/index.ts'], format: 'esm', outfile: path.join(outDir, 'webphysics.mjs') }),
  // A second copy of the engine for CommonJS projects: an app that both imports and requires the
  // package gets two engines whose objects must not be mixed.
  build({ ...common, entryPoints: ['src/index.ts'], format: 'cjs', outfile: path.join(outDir, 'webphysics.cjs') }),
  build({ ...common, entryPoints: ['src/api/classic.ts'], format: 'iife', globalName: 'Box2D', outfile: path.join(outDir, 'box2d.js') }),
  build({
    ...common,
    entryPoints: ['src/api/classic.ts'],
    format: 'iife',
    globalName: 'Box2D',
    minify: true,
    outfile: path.join(outDir, 'box2d.min.js'),
  }),
  // The WebGPU backend (`webphysics/gpu`): src-gpu imports only types and constants from the
  // engine, so these bundles hold no second copy of it. WGSL is inlined as text. The browser build
  // has no Node import at all (nodeImports.browser.ts stands in for nodeImports.ts), so bundlers
  // need no flags for it; the Node build loads Dawn (`webgpu`) and node:* when it looks for a device.
  build({ ...gpu, plugins: [browserNodeImports], outfile: path.join(outDir, 'webphysics-gpu.mjs') }),
  build({ ...gpu, platform: 'node', outfile: path.join(outDir, 'webphysics-gpu.node.mjs') }),
  // The `webphysics` command line, run by bin/webphysics.mjs in the published package.
  build({
    ...common,
    entryPoints: ['src/cli/main.ts'],
    format: 'esm',
    platform: 'node',
    target: 'node20',
    outfile: path.join(outDir, 'cli.mjs'),
  }),
]);
