// npm run build: the ES module, the classic-script bundle that defines the global `Box2D` as
// Box2DWeb's script does (plain and minified), the WebGPU backend (webphysics-gpu.mjs) and the
// command line (cli.mjs), all with source maps. Types come from tsc (tsconfig.build.json), run by the npm script after this.
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

await Promise.all([
  build({ ...common, entryPoints: ['src/index.ts'], format: 'esm', outfile: path.join(outDir, 'webphysics.mjs') }),
  build({ ...common, entryPoints: ['src/api/Box2D.ts'], format: 'iife', globalName: 'Box2D', outfile: path.join(outDir, 'box2d.js') }),
  build({
    ...common,
    entryPoints: ['src/api/Box2D.ts'],
    format: 'iife',
    globalName: 'Box2D',
    minify: true,
    outfile: path.join(outDir, 'box2d.min.js'),
  }),
  // The WebGPU backend (`webphysics/gpu`): src-gpu imports only types from the engine, so this
  // bundle holds no second copy of it. WGSL is inlined as text; Dawn (`webgpu`) stays an import
  // for Node, and Node built-ins are imported only on Node's code path.
  build({
    ...common,
    entryPoints: ['src-gpu/index.ts'],
    format: 'esm',
    loader: { '.wgsl': 'text' },
    external: ['webgpu', 'node:*'],
    outfile: path.join(outDir, 'webphysics-gpu.mjs'),
  }),
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
