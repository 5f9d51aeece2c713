/*
 * The working tree's bundles (`node scripts/build.mjs <dir>`: dist/webphysics.mjs, box2d.js and
 * the rest) built into a temporary folder, for tests that load them as users and the benchmarks do;
 * and the package as `npm pack` makes it from them, for tests that install it.
 */

import { cpSync, mkdirSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

/** A built dist folder in a temporary directory; remove() deletes it. */
export function buildBundles(): { dir: string; remove(): void } {
  const dir = mkdtempSync(path.join(tmpdir(), 'webphysics-bundles-'));
  execFileSync(process.execPath, [path.join(repoRoot, 'scripts/build.mjs'), dir], { cwd: repoRoot });
  return { dir, remove: () => rmSync(dir, { recursive: true, force: true }) };
}

export interface PackedPackage {
  /** The .tgz file. */
  tarball: string;
  /** The paths it holds, as `npm pack` lists them (dist/webphysics.mjs...). */
  files: string[];
  remove(): void;
}

/**
 * `npm run build` then `npm pack`, without touching the checkout's dist: package.json and the
 * entries of its `files` are copied into a temporary folder, dist is built there (bundles, then
 * declarations) and npm packs that folder.
 */
export function packPackage(): PackedPackage {
  const dir = mkdtempSync(path.join(tmpdir(), 'webphysics-pack-'));
  const stage = path.join(dir, 'package');
  mkdirSync(stage);
  const { files } = JSON.parse(readFileSync(path.join(repoRoot, 'package.json'), 'utf8')) as { files: string[] };
  for (const entry of ['package.json', ...files.filter((f) => f !== 'dist')]) {
    cpSync(path.join(repoRoot, entry), path.join(stage, entry), { recursive: true });
  }
  const dist = path.join(stage, 'dist');
  execFileSync(process.execPath, [path.join(repoRoot, 'scripts/build.mjs'), dist], { cwd: repoRoot });
  execFileSync(process.execPath, [path.join(repoRoot, 'scripts/build-types.mjs'), dist], { cwd: repoRoot });
  // --ignore-scripts: prepack would build again, from a folder that has no sources.
  const [packed] = JSON.parse(execFileSync('npm', ['pack', '--json', '--ignore-scripts', '--pack-destination', dir], { cwd: stage, encoding: 'utf8' })) as {
    filename: string;
    files: { path: string }[];
  }[];
  return {
    tarball: path.join(dir, packed.filename),
    files: packed.files.map((f) => f.path),
    remove: () => rmSync(dir, { recursive: true, force: true }),
  };
}
