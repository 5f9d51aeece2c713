/*
 * The golden suite as a program, for JavaScript engines that run TypeScript but not vitest (Bun,
 * which is JavaScriptCore): every golden scene stepped for its whole trajectory, and one JSON line
 * on stdout with the engine's name and version and each scene's first divergence (null: none).
 *   bun test/golden/engineSuite.ts
 */

import { goldenSceneNames, runGoldenScene } from '../support/scene';

const bun = (globalThis as { Bun?: { version: string } }).Bun;
const engine =
  bun !== undefined ? `Bun ${bun.version} (JavaScriptCore ${process.versions.webkit ?? '?'})` : `Node ${process.version} (V8 ${process.versions.v8})`;
const scenes = goldenSceneNames().map((name) => ({ name, failure: runGoldenScene(name) }));
process.stdout.write(JSON.stringify({ engine, scenes }) + '\n');
