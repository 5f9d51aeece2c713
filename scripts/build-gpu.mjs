// node scripts/build-gpu.mjs [outDir]: the GPU benchmark as one file for a machine that has only
// Node and the `webgpu` package (left external): dist/bench-gpu-broadphase.mjs. WGSL is inlined
// as text. See bench/gpu-broadphase.ts and ../shared/gpu/README.md.
import { build } from 'esbuild';
import path from 'node:path';

const outDir = process.argv[2] ?? 'dist';

await build({
  entryPoints: ['bench/gpu-broadphase.ts'],
  bundle: true,
  platform: 'node',
  format: 'esm',
  target: 'node20',
  sourcemap: false,
  logLevel: 'warning',
  legalComments: 'inline',
  external: ['webgpu'],
  loader: { '.wgsl': 'text' },
  outfile: path.join(outDir, 'bench-gpu-broadphase.mjs'),
});
console.log(`built ${path.join(outDir, 'bench-gpu-broadphase.mjs')}`);
