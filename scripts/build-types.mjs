// npm run build, second half: the declarations, into <dist>/types (default dist/types; the tests
// build into a temporary folder). tsc emits src and src-gpu (tsconfig.build.json) into a scratch
// folder; src becomes types/ and src-gpu types/gpu, whose engine imports then point at types/, so a
// b2World from 'webphysics' is the type GpuWorld expects. Every relative specifier is written as
// the .js file it stands for ('./common/b2Settings' -> './common/b2Settings.js',
// './dynamics' -> './dynamics/index.js'): the package is ES modules, and TypeScript under
// moduleResolution Node16 or NodeNext resolves ESM imports as Node does, extensions included.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const tsc = createRequire(import.meta.url).resolve('typescript/bin/tsc');

/** `from '...'`, `import('...')`, `import '...'` and `declare module '...'` with a relative path ('..' included). */
const kRelativeSpecifier = /(\bfrom\s*|\bimport\s*\(\s*|\bimport\s+|\bdeclare\s+module\s+)(['"])(\.\.?(?:\/[^'"\n]*)?)\2/g;

/** The .js path that `specifier`, written in `file`, names: a declaration beside it or a folder's index. */
function explicitSpecifier(file, specifier) {
  const target = path.resolve(path.dirname(file), specifier);
  if (existsSync(`${target}.d.ts`)) return `${specifier}.js`;
  if (existsSync(path.join(target, 'index.d.ts'))) return `${specifier}/index.js`;
  throw new Error(`${file}: no declaration for '${specifier}'`);
}

// The dist folder: dist, or the first argument.
const outDir = path.resolve(process.argv[2] ?? 'dist');
const scratch = path.join(outDir, '.types');
const types = path.join(outDir, 'types');
rmSync(scratch, { recursive: true, force: true });
rmSync(types, { recursive: true, force: true });
execFileSync(process.execPath, [tsc, '-p', path.join(repoRoot, 'tsconfig.build.json'), '--outDir', scratch], { cwd: repoRoot, stdio: 'inherit' });
const written = [];
for (const [from, to, gpu] of [
  [path.join(scratch, 'src'), types, false],
  [path.join(scratch, 'src-gpu'), path.join(types, 'gpu'), true],
]) {
  for (const file of readdirSync(from, { recursive: true })) {
    if (!file.endsWith('.d.ts')) continue;
    let text = readFileSync(path.join(from, file), 'utf8');
    if (gpu) {
      // src-gpu/<folder>/x.ts imports '../../src/common/...'; types/gpu/<folder>/x.d.ts reaches types/common as '../../common/...'.
      text = text.replace(/(['"])((?:\.\.\/)+)src\//g, '$1$2');
      // GPUDevice, GPUBuffer...: the WebGPU types, from the package's dependency @webgpu/types.
      if (file === 'index.d.ts') text = `/// <reference types="@webgpu/types" />\n${text}`;
    }
    const target = path.join(to, file);
    mkdirSync(path.dirname(target), { recursive: true });
    writeFileSync(target, text);
    written.push(target);
  }
}
for (const file of written) {
  const text = readFileSync(file, 'utf8');
  writeFileSync(
    file,
    text.replace(kRelativeSpecifier, (_, keyword, quote, specifier) => `${keyword}${quote}${explicitSpecifier(file, specifier)}${quote}`),
  );
}
rmSync(scratch, { recursive: true, force: true });
console.log(`wrote ${types}`);
