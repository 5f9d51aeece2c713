/*
 * The working tree's bundles (`node scripts/build.mjs <dir>`: dist/webphysics.mjs, box2d.js and
 * the rest) built into a temporary folder, for tests that load them as users and the benchmarks do.
 */

import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

/** A built dist folder in a temporary directory; remove() deletes it. */
export function buildBundles(): { dir: string; remove(): void } {
  const dir = mkdtempSync(path.join(tmpdir(), 'webphysics-bundles-'));
  execFileSync(process.execPath, [path.join(repoRoot, 'scripts/build.mjs'), dir], { cwd: repoRoot });
  return { dir, remove: () => rmSync(dir, { recursive: true, force: true }) };
}
