/*
 * The Brownian motion page (brownian.html) in headless Chromium with WebGPU on SwiftShader, and
 * without WebGPU in Firefox: the gas steps and is drawn, its speeds are histogrammed against the
 * two-dimensional Maxwell-Boltzmann distribution (their mean speeds agree), the large discs move,
 * and the page says what steps it. Screenshots go to test-artifacts/browser/.
 */

import path from 'node:path';
import type { Page } from 'puppeteer-core';
import { describe, expect, it } from 'vitest';
import { collectErrors, ensureArtifactsDir, launchChromium, useBrowser, useTestbed } from './chromium';
import { launchFirefox } from './firefox';

const testbed = useTestbed();
const artifacts = ensureArtifactsDir();

type Demo = Window['brownianDemo'];
const state = (page: Page): Promise<Demo> => page.evaluate(() => JSON.parse(JSON.stringify(window.brownianDemo)) as Demo);

// SwiftShader steps 100,000 discs at seconds a frame: the WebGPU page is asked for 5,000.
for (const [name, launch, backend, query, particles, prefix] of [
  ['Chromium, WebGPU on SwiftShader', () => launchChromium({ webgpu: true }), 'webgpu', '?particles=5000', 5_000, ''],
  ['Firefox, no WebGPU', launchFirefox, 'js', '', 3_000, 'firefox-'],
] as const) {
  describe(`the Brownian motion page (${name})`, () => {
    const browser = useBrowser(launch);

    it("steps the gas, histograms its speeds against Maxwell-Boltzmann's, and the large discs move", async () => {
      const page = await browser().browser.newPage();
      await page.setViewport({ width: 1000, height: 700 });
      const errors = collectErrors(page);
      try {
        await page.goto(`${testbed().url}brownian.html${query}`, { waitUntil: 'load' });
        // The first sample comes after the first step; the next one SAMPLE_EVERY steps later.
        await page.waitForFunction(() => window.brownianDemo.histogram !== null && window.brownianDemo.steps > 31, { timeout: 280_000, polling: 250 });
        const s = await state(page);
        expect(s.backend).toBe(backend);
        expect(s.particles).toBe(particles);
        const h = s.histogram!;
        expect(h.samples).toBe(Math.min(5_000, s.particles));
        expect(h.counts.reduce((a, b) => a + b, 0)).toBe(h.samples);
        // A gas started with normal velocity components: its mean speed is the distribution's.
        expect(Math.abs(h.meanSpeed / h.expectedMeanSpeed - 1)).toBeLessThan(0.05);
        expect(s.heavyMoved).toBeGreaterThan(0);
        expect(await page.$eval('#adapter', (e) => e.textContent)).toMatch(
          backend === 'webgpu'
            ? /^WebGPU adapter: /
            : /^This browser (lacks WebGPU|has WebGPU but no adapter).*: the JavaScript engine steps up to 3,000 discs/,
        );
        await page.screenshot({ path: path.join(artifacts, `${prefix}brownian.png`) });
        expect(await page.$eval('#message', (e) => (e as HTMLElement).hidden)).toBe(true);
        expect(errors).toEqual([]);
      } finally {
        await page.close();
      }
    }, 300_000);
  });
}
