/*
 * Same bits in every JavaScript engine: the golden suite of trajectories.test.ts (every scene,
 * every step of its trajectory, digests equal to the C++ reference's) run again in SpiderMonkey
 * (headless Firefox ESR, through the testbed page's sceneDigests) and in JavaScriptCore (Bun
 * running engineSuite.ts). Node's V8 runs it in trajectories.test.ts, Chromium's in
 * test/browser/determinism.test.ts.
 */

import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { openTestbed, repoRoot, serveTestbed } from '../browser/chromium';
import type { LaunchedBrowser, Testbed } from '../browser/chromium';
import { launchFirefox } from '../browser/firefox';
import { goldenDir } from '../support/golden';
import { goldenSceneNames, readTrajectory } from '../support/scene';

/** The first step whose digest differs from the reference's, or -1. */
function firstDifference(digests: readonly string[], reference: readonly string[]): number {
  const n = Math.max(digests.length, reference.length);
  for (let k = 0; k < n; ++k) if (digests[k] !== reference[k]) return k;
  return -1;
}

describe('the golden suite in SpiderMonkey (Firefox ESR)', () => {
  let testbed: Testbed;
  let firefox: LaunchedBrowser;
  let page: Awaited<ReturnType<typeof openTestbed>>['page'];
  let errors: string[];

  beforeAll(async () => {
    testbed = await serveTestbed();
    firefox = await launchFirefox();
    ({ page, errors } = await openTestbed(firefox.browser, testbed.url));
  }, 120_000);

  afterAll(async () => {
    await firefox?.close();
    await testbed?.close();
  });

  it('runs in Firefox', async () => {
    expect(await page.evaluate(() => navigator.userAgent)).toMatch(/Firefox\//);
  });

  for (const name of goldenSceneNames()) {
    it(`${name} follows the C++ reference trajectory in every step`, async () => {
      const reference = readTrajectory(name).digests;
      const json = readFileSync(path.join(goldenDir, 'scenes', `${name}.scene.json`), 'utf8');
      const digests = await page.evaluate((text: string, steps: number) => window.testbed.sceneDigests(JSON.parse(text), steps), json, reference.length - 1);
      expect(firstDifference(digests, reference), 'first step where SpiderMonkey differs from the C++ reference').toBe(-1);
      expect(errors).toEqual([]);
    });
  }
});

describe('the golden suite in JavaScriptCore (Bun)', () => {
  it('every scene follows the C++ reference trajectory in every step', () => {
    const bun = path.join(path.dirname(createRequire(import.meta.url).resolve('bun/package.json')), 'bin', 'bun.exe');
    const stdout = execFileSync(bun, [path.join(repoRoot, 'test', 'golden', 'engineSuite.ts')], {
      cwd: repoRoot,
      encoding: 'utf8',
      env: { ...process.env, WEBPHYSICS_GOLDEN: goldenDir },
    });
    const report = JSON.parse(stdout) as { engine: string; scenes: { name: string; failure: string | null }[] };
    expect(report.engine).toMatch(/^Bun .*JavaScriptCore/);
    expect(report.scenes.map((s) => s.name)).toEqual(goldenSceneNames());
    expect(report.scenes.filter((s) => s.failure !== null).map((s) => s.failure)).toEqual([]);
  });
});
