import { readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

/** The reference data folder: $WEBPHYSICS_GOLDEN, or ../shared/golden beside the checkout. */
export const goldenDir = process.env.WEBPHYSICS_GOLDEN ?? path.resolve(repoRoot, '../shared/golden');

export function readGoldenJson<T = unknown>(relativePath: string): T {
  return JSON.parse(readFileSync(path.join(goldenDir, relativePath), 'utf8')) as T;
}
