/*
 * Determinism across JavaScript engines: three golden scenes (shared/golden, the C++ Box2D 2.2.1
 * reference) stepped 300 times in Chromium's V8 give, after every step, the digests Node gives
 * and the digests of the C++ trajectory files. The port computes sin, cos and atan2 itself
 * (fdlibm), so no engine-specific Math rounding can enter.
 */

import { readFileSync } from 'node:fs';
import path from 'node:path';
import type { Page } from 'puppeteer-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { goldenDir } from '../support/golden';
import { loadGoldenScene, readTrajectory, stateDigest } from '../support/scene';
import { launchChromium, openTestbed, serveTestbed } from './chromium';
import type { LaunchedBrowser, Testbed } from './chromium';

const kScenes = ['mixed-rain', 'joint-zoo', 'car'];
const kSteps = 300;

let testbed: Testbed;
let chromium: LaunchedBrowser;
let page: Page;
let errors: string[];

beforeAll(async () => {
  testbed = await serveTestbed();
  chromium = await launchChromium();
  ({ page, errors } = await openTestbed(chromium.browser, testbed.url));
}, 120_000);

afterAll(async () => {
  await chromium?.close();
  await testbed?.close();
});

function nodeDigests(name: string): string[] {
  const scene = loadGoldenScene(name);
  const digests = [stateDigest(scene.bodies)];
  for (let k = 1; k <= kSteps; ++k) {
    scene.step();
    digests.push(stateDigest(scene.bodies));
  }
  return digests;
}

describe(`golden scenes stepped ${kSteps} times in Chromium`, () => {
  for (const name of kScenes) {
    it(`${name}: Chromium's digests equal Node's and the C++ trajectory's`, async () => {
      const json = readFileSync(path.join(goldenDir, 'scenes', `${name}.scene.json`), 'utf8');
      const browser = await page.evaluate(
        (text: string, steps: number) => ({
          digests: window.testbed.sceneDigests(JSON.parse(text), steps),
          userAgent: navigator.userAgent,
        }),
        json,
        kSteps,
      );
      expect(browser.userAgent).toMatch(/Chrome\//);
      const node = nodeDigests(name);
      const reference = readTrajectory(name).digests.slice(0, kSteps + 1);
      expect(browser.digests).toHaveLength(kSteps + 1);
      const firstBrowserDiff = browser.digests.findIndex((d, k) => d !== reference[k]);
      const firstNodeDiff = node.findIndex((d, k) => d !== reference[k]);
      expect(firstBrowserDiff, 'first step where Chromium differs from the C++ reference').toBe(-1);
      expect(firstNodeDiff, 'first step where Node differs from the C++ reference').toBe(-1);
      expect(browser.digests).toEqual(node);
      expect(errors).toEqual([]);
    }, 120_000);
  }
});
