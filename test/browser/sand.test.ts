/*
 * The sand page (sand.html) in headless Chromium with WebGPU on SwiftShader, and without WebGPU
 * in Firefox: the grain count grows while the spout pours and stops when it stops, a stroke of the
 * pointer becomes a container, the page says what steps it and loads without console errors.
 * Screenshots go to test-artifacts/browser/.
 */

import path from 'node:path';
import type { Page } from 'puppeteer-core';
import { describe, expect, it } from 'vitest';
import { collectErrors, ensureArtifactsDir, launchChromium, useBrowser, useTestbed } from './chromium';
import { launchFirefox } from './firefox';

const testbed = useTestbed();
const artifacts = ensureArtifactsDir();

type Demo = Omit<Window['sandDemo'], 'worldToClient'>;
const state = (page: Page): Promise<Demo> => page.evaluate(() => JSON.parse(JSON.stringify(window.sandDemo)) as Demo);

async function stepsDone(page: Page, steps: number): Promise<Demo> {
  await page.waitForFunction((n) => window.sandDemo.ready && window.sandDemo.steps >= n, { timeout: 240_000, polling: 200 }, steps);
  return state(page);
}

for (const [name, launch, backend, prefix] of [
  ['Chromium, WebGPU on SwiftShader', () => launchChromium({ webgpu: true }), 'webgpu', ''],
  ['Firefox, no WebGPU', launchFirefox, 'js', 'firefox-'],
] as const) {
  describe(`the sand page (${name})`, () => {
    const browser = useBrowser(launch);

    it('pours grains while the spout runs, and a pointer stroke draws a container', async () => {
      const page = await browser().browser.newPage();
      await page.setViewport({ width: 1000, height: 700 });
      const errors = collectErrors(page);
      try {
        await page.goto(`${testbed().url}sand.html`, { waitUntil: 'load' });
        const first = await stepsDone(page, 2);
        expect(first.backend).toBe(backend);
        expect(first.containers).toBe(1);
        const later = await stepsDone(page, first.steps + 5);
        expect(later.grains).toBeGreaterThan(first.grains);
        expect(later.grains).toBeLessThanOrEqual(later.maxGrains);
        expect(later.maxGrains).toBe(backend === 'webgpu' ? 200_000 : 5_000);
        expect(await page.$eval('#adapter', (e) => e.textContent)).toMatch(
          backend === 'webgpu'
            ? /^WebGPU adapter: /
            : /^This browser (lacks WebGPU|has WebGPU but no adapter).*: the JavaScript engine pours up to 5,000 grains/,
        );

        // A V drawn to the right of the first container.
        const points = await page.evaluate(() => [
          window.sandDemo.worldToClient(12, 20),
          window.sandDemo.worldToClient(16, 8),
          window.sandDemo.worldToClient(20, 20),
        ]);
        await page.mouse.move(Math.round(points[0].x), Math.round(points[0].y));
        await page.mouse.down();
        await page.mouse.move(Math.round(points[1].x), Math.round(points[1].y), { steps: 8 });
        await page.mouse.move(Math.round(points[2].x), Math.round(points[2].y), { steps: 8 });
        await page.mouse.up();
        expect((await state(page)).containers).toBe(2);

        // Stopped, the spout lets out nothing more.
        await page.click('#pour');
        // The frame in flight at the click may still pour; the one after it may not.
        const clicked = await state(page);
        const stopped = await stepsDone(page, clicked.steps + 2);
        const after = await stepsDone(page, stopped.steps + 3);
        expect(after.grains).toBe(stopped.grains);
        await page.screenshot({ path: path.join(artifacts, `${prefix}sand.png`) });
        expect(errors).toEqual([]);
      } finally {
        await page.close();
      }
    }, 300_000);
  });
}
