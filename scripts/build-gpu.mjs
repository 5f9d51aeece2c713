// node scripts/build-gpu.mjs [outDir]: the GPU benchmarks, each as one file for a machine that has
// only Node and the `webgpu` package (left external): dist/bench-gpu-broadphase.mjs,
// dist/bench-gpu-narrowphase.mjs, dist/bench-gpu-step.mjs, dist/bench-gpu-compare.mjs and
// dist/bench-gpu-render.mjs. WGSL is inlined as text. See bench/gpu-*.ts and
// ../shared/gpu/README.md.
import { build } from 'esbuild';
import path from 'node:path';

const outDir = process.argv[2] ?? 'dist';

for (const name of ['broadphase', 'narrowphase', 'step', 'compare', 'render']) {
  await build({
    entryPoints: [`bench/gpu-${name}.ts`],
    bundle: true,
    platform: 'node',
    format: 'esm',
    target: 'node20',
    sourcemap: false,
    logLevel: 'warning',
    legalComments: 'inline',
    external: ['webgpu'],
    loader: { '.wgsl': 'text' },
    outfile: path.join(outDir, `bench-gpu-${name}.mjs`),
  });
  console.log(`built ${path.join(outDir, `bench-gpu-${name}.mjs`)}`);
}
