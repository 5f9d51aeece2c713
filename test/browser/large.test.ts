/*
 * The large-world page (large.html) in headless Chromium with WebGPU on SwiftShader: 10^4 bodies
 * stepped and drawn on the GPU with no buffer mapped for drawing (every map the page makes is
 * counted), the mouse joint drags a body picked on the GPU; without WebGPU (Chromium without a
 * GPU, Firefox) the page says so and runs the JavaScript engine with fewer bodies. Screenshots go
 * to test-artifacts/browser/.
 */

import path from 'node:path';
import type { Page } from 'puppeteer-core';
import { describe, expect, it } from 'vitest';
import { collectErrors, ensureArtifactsDir, launchChromium, screenshotPixels, useBrowser, useTestbed } from './chromium';
import type { LaunchedBrowser } from './chromium';
import { launchFirefox } from './firefox';

const testbed = useTestbed();
const artifacts = ensureArtifactsDir();

interface Mapped {
  label: string;
  size: number;
}

/** Opens large.html with `query`, every GPUBuffer.mapAsync the page makes recorded in window.maps. */
async function open(browser: LaunchedBrowser, query: string): Promise<{ page: Page; errors: string[] }> {
  const page = await browser.browser.newPage();
  await page.setViewport({ width: 1000, height: 700 });
  const errors = collectErrors(page);
  await page.evaluateOnNewDocument(() => {
    const w = window as unknown as { maps: { label: string; size: number }[]; GPUBuffer?: { prototype: { mapAsync: (...args: unknown[]) => Promise<void> } } };
    w.maps = [];
    const proto = w.GPUBuffer?.prototype;
    if (proto === undefined) return;
    const mapAsync = proto.mapAsync;
    proto.mapAsync = function (this: GPUBuffer, ...args: unknown[]) {
      w.maps.push({ label: this.label, size: this.size });
      return mapAsync.apply(this, args);
    };
  });
  await page.goto(`${testbed().url}large.html${query}`, { waitUntil: 'load' });
  return { page, errors };
}

type Demo = Omit<Window['largeDemo'], 'worldToClient' | 'bodyPosition' | 'lookAt'>;
const state = (page: Page): Promise<Demo> => page.evaluate(() => JSON.parse(JSON.stringify(window.largeDemo)) as Demo);

async function framesDone(page: Page, frames: number): Promise<Demo> {
  await page.waitForFunction((n) => window.largeDemo.ready && window.largeDemo.frames >= n, { timeout: 240_000, polling: 200 }, frames);
  return state(page);
}

describe('the large-world page with WebGPU (Chromium, SwiftShader)', () => {
  const chromium = useBrowser(() => launchChromium({ webgpu: true }));

  it('steps and draws 10^4 bodies on the GPU, mapping no buffer to draw them', async () => {
    const { page, errors } = await open(chromium(), '?scene=pyramids&bodies=10000');
    try {
      const before = await framesDone(page, 2);
      const after = await framesDone(page, before.frames + 4);
      expect(after.backend).toBe('webgpu');
      expect(after.bodies).toBe(10_001); // the pyramids' boxes and their ground; the mouse joint's body comes on top
      expect(after.drawn!.proxies).toBeGreaterThanOrEqual(10_000);
      expect(after.steps).toBeGreaterThan(before.steps);
      expect(await screenshotPixels(page, '#world')).toBeGreaterThan(5_000);
      // The step's own small read-backs (counts, overflow) are all there is: nothing the size of
      // the bodies' transforms (16 bytes or more a body) is ever mapped.
      const maps = await page.evaluate(() => (window as unknown as { maps: Mapped[] }).maps);
      expect(maps.length).toBeGreaterThan(0);
      expect(maps.filter((m) => m.size >= 16 * 10_000)).toEqual([]);
      expect(await page.$eval('#adapter', (e) => e.textContent)).toMatch(/^WebGPU adapter: .*stepped and drawn on the GPU\.$/);
      expect(await page.$eval('#stats', (e) => e.textContent)).toMatch(/^WebGPU: stepped and drawn on the GPU · 10,001 bodies · step \d+ · frame .* ms/);
      await page.screenshot({ path: path.join(artifacts, 'large-pyramids-webgpu.png') });
      expect(errors).toEqual([]);
    } finally {
      await page.close();
    }
  }, 300_000);

  it('drags a body picked on the GPU with a mouse joint', async () => {
    const { page, errors } = await open(chromium(), '?scene=pyramids&bodies=10000');
    try {
      await framesDone(page, 2);
      // The top box of the first pyramid: body 210 - 1 of the scene (the ground is body 0).
      const index = 210;
      const start = await page.evaluate(async (i) => window.largeDemo.bodyPosition(i), index);
      await page.evaluate((x, y) => window.largeDemo.lookAt(x, y, 20), start.x, start.y);
      const at = await page.evaluate((x, y) => window.largeDemo.worldToClient(x, y), start.x, start.y);
      await page.mouse.move(Math.round(at.x), Math.round(at.y));
      await page.mouse.down();
      await page.waitForFunction((i) => window.largeDemo.dragging === i, { timeout: 60_000, polling: 100 }, index);
      const held = await state(page);
      await page.mouse.move(Math.round(at.x), Math.round(at.y) - 100, { steps: 5 });
      await framesDone(page, held.frames + 20);
      const moved = await page.evaluate(async (i) => window.largeDemo.bodyPosition(i), index);
      // Pulled towards a target 5 m up (100 pixels at 20 pixels a metre) by the joint's spring, for a third of a second.
      expect(moved.y - start.y).toBeGreaterThan(1);
      await page.mouse.up();
      expect((await state(page)).dragging).toBeNull();
      await page.screenshot({ path: path.join(artifacts, 'large-drag-webgpu.png') });
      expect(errors).toEqual([]);
    } finally {
      await page.close();
    }
  }, 300_000);

  it('names a bad URL parameter and keeps its default', async () => {
    const { page, errors } = await open(chromium(), '?scene=volcano&bodies=12');
    try {
      const s = await framesDone(page, 1);
      expect(s.scene).toBe('pyramids');
      expect(s.bodies).toBe(10_001);
      expect(await page.$eval('#message', (e) => e.textContent)).toBe(
        'URL: scene must be one of pyramids, rain, sand (got "volcano"); bodies must be an integer from 10000 to 1000000 here (got "12"); the default is used for each.',
      );
      expect(errors).toEqual([]);
    } finally {
      await page.close();
    }
  }, 300_000);
});

for (const [name, launch, prefix] of [
  ['Chromium without a GPU', () => launchChromium({ webgpu: false }), ''],
  ['Firefox', launchFirefox, 'firefox-'],
] as const) {
  describe(`the large-world page without WebGPU (${name})`, () => {
    const browser = useBrowser(launch);

    it('says there is no WebGPU and runs the JavaScript engine with fewer bodies', async () => {
      const { page, errors } = await open(browser(), '?scene=sand&bodies=2000');
      try {
        const s = await framesDone(page, 3);
        expect(s.backend).toBe('js');
        expect(s.bodies).toBe(2_001);
        expect(await page.$eval('#adapter', (e) => e.textContent)).toMatch(
          /^This browser (lacks WebGPU|has WebGPU but no adapter).*: the JavaScript engine runs, with at most 10,000 bodies drawn on a 2D canvas\.$/,
        );
        expect(await page.$$eval('#bodies option', (o) => o.map((e) => e.textContent))).toEqual(['1,000', '2,000', '5,000', '10,000']);
        expect(await screenshotPixels(page, '#world')).toBeGreaterThan(1_000);
        await page.screenshot({ path: path.join(artifacts, `${prefix}large-no-webgpu.png`) });
        expect(errors).toEqual([]);
      } finally {
        await page.close();
      }
    }, 300_000);
  });
}
