// Declarations for `webphysics/gpu`: tsc emits src-gpu (and the engine files it imports types from)
// into dist/.types-gpu; the src-gpu part moves to dist/types/gpu with its engine imports pointed at
// dist/types (the engine's own declarations, from tsconfig.build.json), so a b2World from
// 'webphysics' is the type GpuWorld expects.
import { execFileSync } from 'node:child_process';
import { mkdirSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';

const require = createRequire(import.meta.url);
const tsc = require.resolve('typescript/bin/tsc');
const tmp = 'dist/.types-gpu';
rmSync(tmp, { recursive: true, force: true });
execFileSync(process.execPath, [tsc, '-p', 'tsconfig.build-gpu.json'], { stdio: 'inherit' });
const from = path.join(tmp, 'src-gpu');
const to = 'dist/types/gpu';
rmSync(to, { recursive: true, force: true });
mkdirSync(to, { recursive: true });
for (const file of readdirSync(from, { recursive: true })) {
  if (!file.endsWith('.d.ts')) continue;
  // src-gpu/<folder>/x.ts imports '../../src/common/...'; dist/types/gpu/<folder>/x.d.ts reaches dist/types/common as '../../common/...'.
  let text = readFileSync(path.join(from, file), 'utf8').replace(/'((?:\.\.\/)+)src\//g, "'$1");
  // GPUDevice, GPUBuffer...: the WebGPU types (@webgpu/types, which the webgpu package brings).
  if (file === 'index.d.ts') text = `/// <reference types="@webgpu/types" />\n${text}`;
  mkdirSync(path.dirname(path.join(to, file)), { recursive: true });
  writeFileSync(path.join(to, file), text);
}
rmSync(tmp, { recursive: true, force: true });
console.log(`wrote ${to}`);
