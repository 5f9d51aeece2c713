/*
 * The testbed's WebGPU backend in headless Chromium (WebGPU on SwiftShader): tests switched to
 * WebGPU mid-run and back end where the JavaScript engine puts them, within the GPU solver's
 * stated tolerances; a test with its own PreSolve stays on JavaScript and says why; the URL selects
 * test and backend; the mouse joint, bombs and keys work on the GPU; the overlay and the panel name
 * the backend, its step time, the adapter and the read-back's cost. Screenshots go to
 * test-artifacts/browser/.
 */

import path from 'node:path';
import type { Page } from 'puppeteer-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { ensureArtifactsDir, launchChromium, openTestbed, screenshotPixels, serveTestbed } from './chromium';
import type { LaunchedBrowser, Testbed } from './chromium';

/**
 * Tests compared with the engine, and the tolerances the GPU solver states for such scenes:
 * stacks and pyramids as test/gpu/solverScenes.test.ts (golden vertical-stack and pyramid), a
 * jointed chain as test/gpu/solverJoints.test.ts (60 steps), free flight and a first landing as
 * test/gpu/backend.test.ts (five boxes dropped).
 */
const kCompared: { name: string; maxPosition: number; meanPosition: number; angle: number; source: string }[] = [
  { name: 'Pyramid', maxPosition: 0.1, meanPosition: 0.02, angle: 0.01, source: 'solverScenes: golden pyramid' },
  { name: 'Vertical Stack', maxPosition: 0.02, meanPosition: 0.01, angle: 0.01, source: 'solverScenes: golden vertical-stack' },
  { name: 'Chain', maxPosition: 6e-3, meanPosition: 6e-3, angle: 6e-3, source: 'solverJoints: 60 steps' },
  { name: 'Varying Restitution', maxPosition: 1e-4, meanPosition: 1e-4, angle: 1e-4, source: 'backend: boxes dropped' },
  { name: 'Breakable', maxPosition: 1e-4, meanPosition: 1e-4, angle: 1e-4, source: 'backend: boxes dropped' },
];
/** Frames on JavaScript, then on WebGPU, then on JavaScript again. */
const kBefore = 20;
const kOnGpu = 40;
const kAfter = 20;

let testbed: Testbed;
let chromium: LaunchedBrowser;
let page: Page;
let errors: string[];
let artifacts: string;

beforeAll(async () => {
  artifacts = ensureArtifactsDir();
  testbed = await serveTestbed();
  chromium = await launchChromium({ webgpu: true });
  ({ page, errors } = await openTestbed(chromium.browser, testbed.url));
  expect((await page.evaluate(() => window.testbed.webgpu)).adapter, 'no WebGPU adapter in this Chromium').toBe(true);
}, 120_000);

afterAll(async () => {
  await chromium?.close();
  await testbed?.close();
});

async function allErrors(): Promise<string[]> {
  return [...errors, ...(await page.evaluate(() => window.testbed.errors.slice()))];
}

interface Difference {
  max: number;
  mean: number;
  angle: number;
  bodies: number;
  onGpu: string;
  back: string;
}

/** The test run kBefore + kOnGpu + kAfter frames on JavaScript, and again with the middle frames on WebGPU. */
async function switchedRun(name: string): Promise<Difference> {
  return page.evaluate(
    async (name, before, onGpu, after) => {
      const tb = window.testbed;
      tb.select(name);
      await tb.setBackend('js');
      tb.frame(before + onGpu + after);
      const engine = tb.bodies();
      tb.select(name);
      tb.frame(before);
      const gpuActive = await tb.setBackend('webgpu');
      await tb.frameAsync(onGpu);
      const back = await tb.setBackend('js');
      tb.frame(after);
      const switched = tb.bodies();
      let max = 0;
      let sum = 0;
      let angle = 0;
      let n = 0;
      for (let i = 0; i < engine.length; ++i) {
        if (engine[i].type !== 'dynamic') continue;
        const d = Math.hypot(engine[i].x - switched[i].x, engine[i].y - switched[i].y);
        max = Math.max(max, d);
        sum += d;
        angle = Math.max(angle, Math.abs(engine[i].angle - switched[i].angle));
        ++n;
      }
      return { max, mean: sum / n, angle, bodies: n, onGpu: gpuActive, back };
    },
    name,
    kBefore,
    kOnGpu,
    kAfter,
  );
}

describe('the testbed on the WebGPU backend (Chromium, SwiftShader)', () => {
  it('the backend selector offers WebGPU where the browser has an adapter', async () => {
    const option = await page.evaluate(() => {
      const o = document.querySelector<HTMLOptionElement>('#backend option[value="webgpu"]')!;
      return { disabled: o.disabled, label: o.textContent };
    });
    expect(option).toEqual({ disabled: false, label: 'WebGPU' });
  });

  for (const c of kCompared) {
    it(`${c.name}: switched to WebGPU after ${kBefore} frames and back after ${kOnGpu} more, it ends where the engine puts it (${c.source}: ${c.maxPosition} m)`, async () => {
      const d = await switchedRun(c.name);
      console.log(`${c.name}: ${d.bodies} bodies, max ${d.max.toExponential(2)} m, mean ${d.mean.toExponential(2)} m, angle ${d.angle.toExponential(2)} rad`);
      expect(d.onGpu).toBe('webgpu');
      expect(d.back).toBe('js');
      expect(d.bodies).toBeGreaterThan(0);
      expect(d.max).toBeLessThan(c.maxPosition);
      expect(d.mean).toBeLessThan(c.meanPosition);
      expect(d.angle).toBeLessThan(c.angle);
      expect(await allErrors()).toEqual([]);
    }, 300_000);
  }

  it('tests with contact listeners run on WebGPU without errors: sensors (Begin/End), breaking (PostSolve), collision processing (contact points from PostSolve)', async () => {
    const frames = 150;
    const result = await page.evaluate(async (frames) => {
      const tb = window.testbed;
      const out: Record<string, { active: string; steps: number; bodies: number; engineBodies: number }> = {};
      for (const name of ['Sensor Test', 'Breakable', 'Collision Processing', 'Tumbler']) {
        tb.select(name);
        await tb.setBackend('js');
        tb.frame(frames);
        const engineBodies = tb.state().bodyCount;
        tb.select(name);
        await tb.setBackend('webgpu');
        await tb.frameAsync(frames);
        out[name] = { active: tb.backend().active, steps: tb.state().stepCount, bodies: tb.state().bodyCount, engineBodies };
      }
      await tb.setBackend('js');
      return out;
    }, frames);
    for (const [name, r] of Object.entries(result)) {
      expect(r.active, name).toBe('webgpu');
      expect(r.steps, name).toBe(frames);
    }
    // Collision Processing destroys the lighter body of each touching pair (7 bodies at the start,
    // ground included); the Tumbler adds a box a step: both as on the engine.
    const processing = result['Collision Processing'];
    console.log(`Collision Processing after ${frames} frames: ${processing.engineBodies} bodies on the engine, ${processing.bodies} on WebGPU`);
    expect(processing.engineBodies).toBeLessThan(7);
    expect(processing.bodies).toBeLessThan(7);
    expect(result.Tumbler.bodies).toBe(result.Tumbler.engineBodies);
    expect(await allErrors()).toEqual([]);
  }, 600_000);

  it('a test with its own PreSolve (One-Sided Platform) stays on JavaScript and the page says why', async () => {
    const state = await page.evaluate(async () => {
      const tb = window.testbed;
      tb.select('One-Sided Platform');
      const active = await tb.setBackend('webgpu');
      tb.frame(5);
      const note = document.getElementById('backend-note')!;
      const result = { active, backend: tb.backend(), note: note.textContent, hidden: note.hidden, steps: tb.state().stepCount };
      await tb.setBackend('js');
      return result;
    });
    expect(state.active).toBe('js');
    expect(state.backend.chosen).toBe('webgpu');
    expect(state.backend.refusal).toMatch(/PreSolve/);
    expect(state.hidden).toBe(false);
    expect(state.note).toMatch(/^One-Sided Platform runs on the JavaScript engine: its PreSolve/);
    expect(state.steps).toBe(5);
    expect(await allErrors()).toEqual([]);
  });

  it('the mouse joint drags a body, a bomb launches and keys reach the test on WebGPU', async () => {
    await page.evaluate(async () => {
      window.testbed.select('Vertical Stack');
      await window.testbed.setBackend('webgpu');
      await window.testbed.frameAsync(10);
    });
    const body = await page.evaluate(() => window.testbed.bodies().findIndex((b) => b.type === 'dynamic'));
    const before = await page.evaluate((i) => window.testbed.bodies()[i], body);
    const at = await page.evaluate((x, y) => window.testbed.worldToClient(x, y), before.x, before.y);
    await page.mouse.move(at.x, at.y);
    await page.mouse.down();
    await page.evaluate(() => window.testbed.frameAsync(2));
    expect(await page.evaluate(() => window.testbed.state().mouseJoint)).toBe(true);
    const to = await page.evaluate((x, y) => window.testbed.worldToClient(x, y), before.x, before.y + 4);
    await page.mouse.move(to.x, to.y, { steps: 4 });
    await page.evaluate(() => window.testbed.frameAsync(30));
    const dragged = await page.evaluate((i) => window.testbed.bodies()[i], body);
    await page.mouse.up();
    await page.evaluate(() => window.testbed.frameAsync(1));
    expect(dragged.y - before.y).toBeGreaterThan(2);
    expect(await page.evaluate(() => window.testbed.state().mouseJoint)).toBe(false);

    const bodies = await page.evaluate(() => window.testbed.state().bodyCount);
    await page.focus('#canvas');
    await page.keyboard.press('Space');
    await page.evaluate(() => window.testbed.frameAsync(10));
    const bombed = await page.evaluate(() => window.testbed.state());
    expect(bombed.bomb).toBe(true);
    expect(bombed.bodyCount).toBe(bodies + 1);
    // Vertical Stack's ',' fires a bullet (a new body) at the stacks.
    await page.keyboard.press(',');
    await page.evaluate(() => window.testbed.frameAsync(10));
    expect(await page.evaluate(() => window.testbed.state().bodyCount)).toBe(bodies + 2);
    expect(await page.evaluate(() => window.testbed.backend().active)).toBe('webgpu');
    expect(await allErrors()).toEqual([]);
  }, 300_000);

  it('the overlay names the backend and its step time; the panel names the adapter and what the read-back costs; window.webphysicsDemo says so', async () => {
    const shown = await page.evaluate(async () => {
      const tb = window.testbed;
      tb.select('Pyramid');
      tb.settings.drawStats = 1;
      await tb.setBackend('webgpu');
      await tb.frameAsync(30);
      const text = tb.text();
      const note = document.getElementById('backend-note')!.textContent;
      const demo = window.webphysicsDemo;
      return { text, note, demo: JSON.parse(JSON.stringify(demo)) };
    });
    await page.screenshot({ path: path.join(artifacts, 'testbed-webgpu.png') });
    expect(shown.text.some((line: string) => /^backend: WebGPU, step \+ read-back \d+\.\d\d ms \(median, last second\)$/.test(line))).toBe(true);
    expect(shown.text).toContain(`adapter: ${shown.demo.panes[0].adapter}`);
    expect(
      shown.text.some((line: string) => /^read-back per frame: [1-9]\d*\.\d KB, \d+\.\d\d ms to unpack, \d+\.\d\d ms to update the bodies$/.test(line)),
    ).toBe(true);
    expect(shown.text.some((line: string) => /^bodies\/contacts\/joints = 212\/[1-9]\d*\/0$/.test(line))).toBe(true);
    expect(shown.note).toMatch(
      /^Stepping on WebGPU \(google \/ swiftshader.*\)\. Each frame reads the world back once .*: [1-9]\d*\.\d KB, \d+\.\d\d ms on the host to unpack and \d+\.\d\d ms to update the bodies drawn/,
    );
    expect(shown.demo.ready).toBe(true);
    expect(shown.demo.panes).toHaveLength(1);
    const [pane] = shown.demo.panes;
    expect(pane.backend).toBe('webgpu');
    expect(pane.adapter).toMatch(/swiftshader/);
    expect(pane.bodies).toBe(212);
    expect(pane.steps).toBe(30);
    expect(pane.stepMs).toBeGreaterThan(0);
    await page.evaluate(async () => {
      window.testbed.settings.drawStats = 0;
      await window.testbed.setBackend('js');
    });
    expect(await allErrors()).toEqual([]);
  }, 300_000);

  it("draws a large world on WebGPU with GpuRenderer from the GPU's buffers under the 2D canvas's text: the bodies show and none is fetched to draw them; back on JavaScript the 2D canvas draws them again", async () => {
    const onGpu = await page.evaluate(async () => {
      const tb = window.testbed;
      tb.select('Benchmark: many pyramids');
      tb.settings.drawStats = 1;
      await tb.setBackend('webgpu');
      await tb.frameAsync(10);
      return {
        backend: tb.backend(),
        bodies: tb.state().bodyCount,
        fetched: tb.fetchedBodies(),
        drawn2d: tb.drawnPixels(),
        text: tb.text(),
        gpuCanvasHidden: document.querySelector<HTMLCanvasElement>('#gpu-canvas')!.hidden,
        note: document.getElementById('backend-note')!.textContent,
      };
    });
    expect(onGpu.bodies).toBeGreaterThanOrEqual(1000);
    expect(onGpu.backend.active).toBe('webgpu');
    expect(onGpu.backend.drawsOnGpu).toBe(true);
    expect(onGpu.gpuCanvasHidden).toBe(false);
    // Nothing but text on the 2D canvas, and no body has fetched the synchronised state to be drawn.
    expect(onGpu.drawn2d).toBe(0);
    expect(onGpu.fetched).toBe(0);
    expect(onGpu.text).toContain("drawn by GpuRenderer from the GPU's buffers (1000 bodies or more): no body read back to draw");
    expect(await screenshotPixels(page, '#gpu-canvas')).toBeGreaterThan(5_000);
    await page.screenshot({ path: path.join(artifacts, 'testbed-large-webgpu.png') });
    const onJs = await page.evaluate(async () => {
      const tb = window.testbed;
      await tb.setBackend('js');
      await tb.frameAsync(2);
      tb.settings.drawStats = 0;
      return { backend: tb.backend(), drawn2d: tb.drawnPixels(), gpuCanvasHidden: document.querySelector<HTMLCanvasElement>('#gpu-canvas')!.hidden };
    });
    expect(onJs.backend.drawsOnGpu).toBe(false);
    expect(onJs.gpuCanvasHidden).toBe(true);
    expect(onJs.drawn2d).toBeGreaterThan(5_000);
    expect(await allErrors()).toEqual([]);
  }, 300_000);

  it('?test=NAME&backend=webgpu opens that test on WebGPU, and the page keeps the URL current', async () => {
    const opened = await openTestbed(chromium.browser, testbed.url, '?test=SphereStack&backend=webgpu');
    try {
      const state = await opened.page.evaluate(async () => {
        await window.testbed.webgpu;
        await window.testbed.frameAsync(5);
        return { name: window.testbed.state().name, backend: window.testbed.backend(), search: location.search };
      });
      expect(state.name).toBe('SphereStack');
      expect(state.backend.active).toBe('webgpu');
      expect(new URLSearchParams(state.search).get('test')).toBe('SphereStack');
      expect(new URLSearchParams(state.search).get('backend')).toBe('webgpu');
      const back = await opened.page.evaluate(async () => {
        await window.testbed.setBackend('js');
        window.testbed.select('Chain');
        return location.search;
      });
      expect(Object.fromEntries(new URLSearchParams(back))).toEqual({ test: 'Chain', backend: 'js' });
      expect(opened.errors).toEqual([]);
    } finally {
      await opened.page.close();
    }
  }, 300_000);
});
