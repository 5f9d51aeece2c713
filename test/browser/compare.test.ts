/*
 * The comparison page (compare.html) in headless Chromium: with WebGPU on SwiftShader both panes
 * build the same scene and advance, the WebGPU pane draws, the adapter is named, the slider
 * rebuilds both panes at another body count and the URL selects scene and size; without an adapter
 * the page says so and runs the JavaScript pane alone, in Chromium and in Firefox (which has no
 * WebGPU here). Screenshots go to test-artifacts/browser/.
 */

import path from 'node:path';
import type { Page } from 'puppeteer-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { collectErrors, ensureArtifactsDir, launchChromium, serveTestbed, useBrowser } from './chromium';
import { launchFirefox } from './firefox';
import type { LaunchedBrowser, Testbed } from './chromium';
import type { WebPhysicsDemo } from '../../demos/framework/demo';

let testbed: Testbed;
let artifacts: string;

beforeAll(async () => {
  artifacts = ensureArtifactsDir();
  testbed = await serveTestbed();
}, 120_000);

afterAll(async () => {
  await testbed?.close();
});

async function open(chromium: LaunchedBrowser, query: string): Promise<{ page: Page; errors: string[] }> {
  const page = await chromium.browser.newPage();
  const errors = collectErrors(page);
  await page.goto(`${testbed.url}compare.html${query}`, { waitUntil: 'load' });
  return { page, errors };
}

const demo = (page: Page): Promise<WebPhysicsDemo> => page.evaluate(() => JSON.parse(JSON.stringify(window.webphysicsDemo)) as WebPhysicsDemo);

/** Waits until every pane running has taken at least `steps` steps. */
async function stepped(page: Page, steps: number): Promise<WebPhysicsDemo> {
  await page.waitForFunction(
    (n) => window.webphysicsDemo.ready && window.webphysicsDemo.panes.every((p) => p.steps >= n),
    { timeout: 240_000, polling: 200 },
    steps,
  );
  return demo(page);
}

/** Canvas pixels of a pane that are not the black background. */
function drawnPixels(page: Page, pane: 'js' | 'webgpu'): Promise<number> {
  return page.evaluate((id) => {
    const canvas = document.querySelector<HTMLCanvasElement>(`#pane-${id} canvas`)!;
    const data = canvas.getContext('2d')!.getImageData(0, 0, canvas.width, canvas.height).data;
    let n = 0;
    for (let i = 0; i < data.length; i += 4) if (data[i] + data[i + 1] + data[i + 2] > 30) n++;
    return n;
  }, pane);
}

describe('the comparison page with WebGPU (Chromium, SwiftShader)', () => {
  let chromium: LaunchedBrowser;
  let page: Page;
  let errors: string[];

  beforeAll(async () => {
    chromium = await launchChromium({ webgpu: true });
    ({ page, errors } = await open(chromium, '?scene=pyramids&bodies=500'));
  }, 120_000);

  afterAll(async () => {
    await chromium?.close();
  });

  it('loads, names the adapter, and both panes step the same scene', async () => {
    const first = await stepped(page, 3);
    expect(first.panes.map((p) => p.backend)).toEqual(['js', 'webgpu']);
    expect(first.panes[0].adapter).toBeNull();
    expect(first.panes[1].adapter).toMatch(/^google \/ swiftshader.*\(software/);
    expect(await page.$eval('#adapter', (e) => e.textContent)).toMatch(/^WebGPU adapter: google \/ swiftshader/);
    // 500 boxes and the ground in both.
    expect(first.panes.map((p) => p.bodies)).toEqual([501, 501]);
    for (const pane of first.panes) expect(pane.stepMs).toBeGreaterThan(0);
    const later = await stepped(page, first.panes[1].steps + 3);
    for (let i = 0; i < 2; ++i) expect(later.panes[i].steps).toBeGreaterThan(first.panes[i].steps);
    expect(errors).toEqual([]);
  }, 300_000);

  it('draws both panes (the WebGPU pane from its read-back transforms) and the chart of both step times', async () => {
    await stepped(page, 5);
    await new Promise((resolve) => setTimeout(resolve, 500));
    expect(await drawnPixels(page, 'js')).toBeGreaterThan(2000);
    expect(await drawnPixels(page, 'webgpu')).toBeGreaterThan(2000);
    const stats = await page.$$eval('.pane .stats', (list) => list.map((e) => e.textContent ?? ''));
    for (const line of stats)
      expect(line).toMatch(
        /^step \d+(\.\d+)? ms \(median, last second\) · \d+ steps, \d+\.\d s simulated\n501 bodies \(\d+ awake\) · [\d,]+ contacts \([\d,]+ touching\)\n/,
      );
    await page.screenshot({ path: path.join(artifacts, 'compare.png') });
    expect(errors).toEqual([]);
  }, 300_000);

  it('the slider rebuilds both panes at another body count, and the URL follows', async () => {
    await page.evaluate(() => {
      const slider = document.querySelector<HTMLInputElement>('#bodies')!;
      slider.value = '1'; // 200 bodies
      slider.dispatchEvent(new Event('input'));
      slider.dispatchEvent(new Event('change'));
    });
    await page.waitForFunction(() => window.webphysicsDemo.panes.every((p) => p.bodies === 201 && p.steps >= 2), { timeout: 240_000, polling: 200 });
    expect(await page.$eval('#bodies-label', (e) => e.textContent)).toBe('200');
    expect(new URL(page.url()).searchParams.get('bodies')).toBe('200');
    expect(errors).toEqual([]);
  }, 300_000);

  it('?scene=rain&bodies=1000&seed=7 opens that scene; a bad parameter is named and its default kept', async () => {
    const rain = await open(chromium, '?scene=rain&bodies=1000&seed=7');
    try {
      const state = await stepped(rain.page, 2);
      expect(state.panes.map((p) => p.bodies)).toEqual([1001, 1001]);
      expect(await rain.page.$eval('#scene', (e) => (e as HTMLSelectElement).value)).toBe('rain');
      expect(await rain.page.$eval('#seed', (e) => (e as HTMLInputElement).value)).toBe('7');
      expect(rain.errors).toEqual([]);
    } finally {
      await rain.page.close();
    }
    const bad = await open(chromium, '?scene=pyramids&bodies=3');
    try {
      const state = await stepped(bad.page, 1);
      expect(await bad.page.$eval('#message', (e) => e.textContent)).toBe(
        'URL: bodies must be an integer from 100 to 200000; got 3. Using the default instead.',
      );
      expect(state.panes.map((p) => p.bodies)).toEqual([1001, 1001]);
      expect(bad.errors).toEqual([]);
    } finally {
      await bad.page.close();
    }
  }, 300_000);

  it('the page stays responsive while both panes step 10^5 bodies: the main thread answers at once', async () => {
    const big = await open(chromium, '?scene=rain&bodies=100000');
    try {
      await big.page.waitForFunction(() => window.webphysicsDemo.panes.every((p) => p.bodies > 0) && window.webphysicsDemo.panes.some((p) => p.steps >= 1), {
        timeout: 240_000,
        polling: 500,
      });
      // Both workers step (a JavaScript step takes about a second here); the page's own thread
      // answers timers and input within milliseconds. (Frames themselves can wait on SwiftShader:
      // the software adapter computes in the browser's GPU process, which also composites.)
      const latencies: number[] = [];
      for (let i = 0; i < 10; ++i) {
        latencies.push(
          await big.page.evaluate(
            () =>
              new Promise<number>((resolve) => {
                const t = performance.now();
                setTimeout(() => resolve(performance.now() - t), 0);
              }),
          ),
        );
        // Moving the slider (without letting go) relabels it at once: 50,000 and 100,000 in turn.
        const stop = i % 2 === 0 ? 8 : 9;
        const label = await big.page.evaluate((stop) => {
          const slider = document.querySelector<HTMLInputElement>('#bodies')!;
          slider.value = String(stop);
          slider.dispatchEvent(new Event('input'));
          return document.querySelector('#bodies-label')!.textContent;
        }, stop);
        expect(label).toBe(stop === 8 ? '50,000' : '100,000');
        await new Promise((resolve) => setTimeout(resolve, 300));
      }
      console.log(`main-thread timer latency while stepping 10^5 bodies: max ${Math.max(...latencies).toFixed(1)} ms`);
      expect(Math.max(...latencies)).toBeLessThan(100);
      const state = await demo(big.page);
      expect(state.panes.map((p) => p.bodies)).toEqual([100001, 100001]);
      expect(big.errors).toEqual([]);
    } finally {
      await big.page.close();
    }
  }, 300_000);
});

for (const [name, launch, prefix] of [
  ['Chromium without a GPU', () => launchChromium({ webgpu: false }), ''],
  ['Firefox', launchFirefox, 'firefox-'],
] as const) {
  describe(`the comparison page without WebGPU (${name})`, () => {
    const browser = useBrowser(launch);

    it('says there is no WebGPU and runs the JavaScript pane alone', async () => {
      const { page, errors } = await open(browser(), '?scene=tumbler&bodies=500');
      const state = await stepped(page, 3);
      expect(state.panes.map((p) => p.backend)).toEqual(['js']);
      expect(await page.$eval('#adapter', (e) => e.textContent)).toMatch(
        /^This browser (lacks WebGPU|has WebGPU but no adapter).*: the JavaScript engine runs alone\.$/,
      );
      expect(await drawnPixels(page, 'js')).toBeGreaterThan(1000);
      await page.screenshot({ path: path.join(artifacts, `${prefix}compare-no-webgpu.png`) });
      expect(errors).toEqual([]);
    }, 300_000);
  });
}
