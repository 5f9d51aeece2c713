/*
 * The touch and play page (touch.html) in headless Chromium with WebGPU on SwiftShader: two fingers
 * (emulated touch, through the DevTools protocol) drag two bodies at once, a tap on empty space
 * drops a body, a finger held still pins one; without WebGPU (Firefox) the page says so, and on
 * the JavaScript engine a click drops a body and the mouse drags one. Screenshots go to test-artifacts/browser/.
 */

import path from 'node:path';
import type { Page } from 'puppeteer-core';
import { describe, expect, it } from 'vitest';
import { collectErrors, ensureArtifactsDir, launchChromium, useBrowser, useTestbed } from './chromium';
import { launchFirefox } from './firefox';

const testbed = useTestbed();
const artifacts = ensureArtifactsDir();

type Demo = Omit<Window['touchDemo'], 'worldToClient' | 'bodyPosition'>;
const state = (page: Page): Promise<Demo> => page.evaluate(() => JSON.parse(JSON.stringify(window.touchDemo)) as Demo);
const until = (page: Page, fn: string) => page.waitForFunction(fn, { timeout: 120_000, polling: 100 });

async function open(page: Page): Promise<string[]> {
  const errors = collectErrors(page);
  await page.goto(`${testbed().url}touch.html`, { waitUntil: 'load' });
  await until(page, 'window.touchDemo.ready && window.touchDemo.steps >= 2');
  return errors;
}

describe('the touch and play page with WebGPU (Chromium, SwiftShader)', () => {
  const chromium = useBrowser(() => launchChromium({ webgpu: true }));

  it('two fingers drag two bodies at once, a tap drops a body, a held finger pins one', async () => {
    const page = await chromium().browser.newPage();
    await page.setViewport({ width: 800, height: 700, hasTouch: true });
    try {
      const errors = await open(page);
      expect((await state(page)).backend).toBe('webgpu');
      const cdp = await page.createCDPSession();
      const touch = (type: string, points: { x: number; y: number }[]) =>
        cdp.send('Input.dispatchTouchEvent', {
          type: type as 'touchStart',
          touchPoints: points.map((p, id) => ({ x: Math.round(p.x), y: Math.round(p.y), id })),
        });
      const client = (x: number, y: number) => page.evaluate((a, b) => window.touchDemo.worldToClient(a, b), x, y);
      const position = (i: number) => page.evaluate(async (k) => window.touchDemo.bodyPosition(k), i);

      // Two fingers on bodies 0 and 1, both moved up 3 m.
      const [a, b] = [await position(0), await position(1)];
      const fingers = [await client(a.x, a.y), await client(b.x, b.y)];
      await touch('touchStart', fingers);
      await until(page, 'window.touchDemo.dragging.length === 2');
      expect([...(await state(page)).dragging].sort()).toEqual([0, 1]);
      const up = await client(0, 3);
      const down = await client(0, 0);
      const lift = up.y - down.y;
      for (let k = 1; k <= 5; ++k)
        await touch(
          'touchMove',
          fingers.map((f) => ({ x: f.x, y: f.y + (lift * k) / 5 })),
        );
      const moved = (await state(page)).steps;
      await until(page, `window.touchDemo.steps >= ${moved + 20}`);
      const [a2, b2] = [await position(0), await position(1)];
      expect(a2.y - a.y).toBeGreaterThan(1);
      expect(b2.y - b.y).toBeGreaterThan(1);
      await touch('touchEnd', []);
      await until(page, 'window.touchDemo.dragging.length === 0');

      // A tap on empty space, high above the bodies, drops a new one.
      const before = await state(page);
      const empty = await client(5, 12);
      await touch('touchStart', [empty]);
      await touch('touchEnd', []);
      await until(page, `window.touchDemo.bodies === ${before.bodies + 1}`);
      expect((await state(page)).spawned).toBe(1);

      // A finger held still on body 2 pins it.
      const c = await position(2);
      await touch('touchStart', [await client(c.x, c.y)]);
      await until(page, 'window.touchDemo.pinned === 1');
      await touch('touchEnd', []);
      await page.screenshot({ path: path.join(artifacts, 'touch-webgpu.png') });
      expect(errors).toEqual([]);
    } finally {
      await page.close();
    }
  }, 300_000);
});

describe('the touch and play page without WebGPU (Firefox)', () => {
  const firefox = useBrowser(launchFirefox);

  it('says there is no WebGPU; on the JavaScript engine a click on empty space drops a body and the mouse drags one', async () => {
    const page = await firefox().browser.newPage();
    await page.setViewport({ width: 800, height: 700 });
    try {
      const errors = await open(page);
      const s = await state(page);
      expect(s.backend).toBe('js');
      expect(await page.$eval('#adapter', (e) => e.textContent)).toMatch(
        /^This browser (lacks WebGPU|has WebGPU but no adapter).*: the JavaScript engine runs/,
      );
      const empty = await page.evaluate(() => window.touchDemo.worldToClient(5, 12));
      await page.mouse.click(Math.round(empty.x), Math.round(empty.y));
      await until(page, `window.touchDemo.bodies === ${s.bodies + 1}`);
      // The mouse drags body 0 up, as one finger.
      const a = await page.evaluate(async () => window.touchDemo.bodyPosition(0));
      const at = await page.evaluate((x, y) => window.touchDemo.worldToClient(x, y), a.x, a.y);
      await page.mouse.move(Math.round(at.x), Math.round(at.y));
      await page.mouse.down();
      await until(page, 'window.touchDemo.dragging.length === 1');
      await page.mouse.move(Math.round(at.x), Math.round(at.y) - 100, { steps: 5 });
      const moved = (await state(page)).steps;
      await until(page, `window.touchDemo.steps >= ${moved + 20}`);
      expect((await page.evaluate(async () => window.touchDemo.bodyPosition(0))).y - a.y).toBeGreaterThan(1);
      await page.mouse.up();
      await page.screenshot({ path: path.join(artifacts, 'firefox-touch.png') });
      expect(errors).toEqual([]);
    } finally {
      await page.close();
    }
  }, 300_000);
});
