/*
 * Type-checking small apps against built declarations with the repository's TypeScript, as an
 * app's own `tsc -p` would.
 */

import { execFileSync } from 'node:child_process';
import { writeFileSync } from 'node:fs';
import path from 'node:path';
import { repoRoot } from './bundles';

export const tsc = path.join(repoRoot, 'node_modules/typescript/bin/tsc');

/** Writes `config` as dir/tsconfig.<name>.json and type-checks it; tsc's output, '' if clean. */
export function typeCheck(dir: string, name: string, config: object): string {
  const file = path.join(dir, `tsconfig.${name}.json`);
  writeFileSync(file, JSON.stringify(config));
  try {
    execFileSync(process.execPath, [tsc, '-p', file], { cwd: dir, encoding: 'utf8' });
    return '';
  } catch (e) {
    return String((e as { stdout?: string }).stdout ?? e);
  }
}
