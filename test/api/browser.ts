/*
 * The classic-script bundle as a browser loads it: buildBundles (test/support/bundles.ts) builds
 * dist/box2d.js into a temporary folder, and each page is a fresh vm context whose global object
 * is its `window` (no require, process, module or other Node globals), in which box2d.js and then
 * the page's scripts run as <script> elements would.
 */

import { readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import vm from 'node:vm';

export const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const fixturesDir = path.join(repoRoot, 'test/api/fixtures');

export interface Page {
  /** The page's global object. */
  readonly window: Record<string, any>;
  /** Run a script in the page, as a <script> element (`filename` names it in stack traces). */
  run(source: string, filename?: string): unknown;
  /** Run test/api/fixtures/<name> in the page. */
  runFixture(name: string): unknown;
}

/**
 * A fresh page that has loaded `<script src="box2d.js">` from the built folder, after the page's
 * own `prelude` script when one is given.
 */
export function openPage(distDir: string, script = 'box2d.js', prelude = ''): Page {
  const context = vm.createContext({});
  const run = (source: string, filename = 'inline.js') => vm.runInContext(source, context, { filename });
  run('var window = this; var self = this;', 'page.js');
  if (prelude !== '') run(prelude, 'prelude.js');
  run(readFileSync(path.join(distDir, script), 'utf8'), script);
  return {
    window: context as Record<string, any>,
    run,
    runFixture: (name) => run(readFileSync(path.join(fixturesDir, name), 'utf8'), name),
  };
}
