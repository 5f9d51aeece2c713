/*
 * The accuracy page (accuracy.html) in headless Chromium: it draws the study's points of the
 * chosen scene and measure with the Pareto front, names the method under the pointer, replays a
 * method's run in the page to the study's numbers bit for bit (a trajectory scene with its
 * converged reference too) and a WebGPU method's on the WebGPU backend, and says so when the
 * results cannot be loaded. Screenshots go to
 * test-artifacts/browser/.
 */

import { readFileSync } from 'node:fs';
import path from 'node:path';
import type { Page } from 'puppeteer-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { AccuracyRun } from '../../bench/accuracy/run.mjs';
import type { AccuracyPageState } from '../../demos/accuracy/main';
import { collectErrors, ensureArtifactsDir, launchChromium, repoRoot, serveTestbed } from './chromium';
import type { LaunchedBrowser, Testbed } from './chromium';

const readStudy = (file: string) => JSON.parse(readFileSync(path.join(repoRoot, 'bench', 'results', 'accuracy', file), 'utf8')) as AccuracyRun;
const study = readStudy('accuracy.json');
const h100 = readStudy('accuracy-h100.json');

let testbed: Testbed;
let chromium: LaunchedBrowser;
let artifacts: string;

beforeAll(async () => {
  artifacts = ensureArtifactsDir();
  testbed = await serveTestbed();
  chromium = await launchChromium();
}, 120_000);

afterAll(async () => {
  await chromium?.close();
  await testbed?.close();
});

const pageState = (page: Page): Promise<AccuracyPageState> => page.evaluate(() => JSON.parse(JSON.stringify(window.webphysicsAccuracy)) as AccuracyPageState);

async function open(query: string): Promise<{ page: Page; errors: string[] }> {
  const page = await chromium.browser.newPage();
  await page.setViewport({ width: 1280, height: 720 });
  const errors = collectErrors(page);
  await page.goto(`${testbed.url}accuracy.html${query}`, { waitUntil: 'load' });
  await page.waitForFunction(() => window.webphysicsAccuracy.ready || window.webphysicsAccuracy.error !== null, { timeout: 60_000 });
  return { page, errors };
}

/** Replays the selected scene and method and waits for the measures. */
async function replayed(page: Page): Promise<AccuracyPageState> {
  await page.click('#replay');
  await page.waitForFunction(() => window.webphysicsAccuracy.replay?.done === true, { timeout: 240_000, polling: 250 });
  return pageState(page);
}

describe('the accuracy page (Chromium)', () => {
  it('draws every timed point of the chosen scene and measure, marks the front, and names the method under the pointer', async () => {
    const { page, errors } = await open('?scene=pyramid&measure=drift');
    const state = await pageState(page);
    expect(state.error).toBeNull();
    expect([state.scene, state.measure]).toEqual(['pyramid', 'drift']);
    const scene = study.scenes.find((s) => s.id === 'pyramid')!;
    const timed = scene.results.filter((r) => r.msPerSecond !== null && Number.isFinite(r.measures.drift));
    expect(state.points.map((p) => p.key).sort()).toEqual(timed.map((r) => r.key).sort());
    expect(
      state.points
        .filter((p) => p.front)
        .map((p) => p.key)
        .sort(),
    ).toEqual([...scene.fronts.drift].sort());
    const target = state.points.find((p) => p.key === 'iter-8-3')!;
    const box = (await page.$('#chart'))!.boundingBox();
    const rect = (await box)!;
    await page.mouse.move(rect.x + target.x, rect.y + target.y);
    await page.waitForFunction(() => window.webphysicsAccuracy.tip !== '');
    expect((await pageState(page)).tip).toMatch(/^8\/3 iterations \(Box2D default\): [0-9.]+ ms per simulated second, drift /);
    expect(await page.$eval('#tip', (e) => (e as HTMLElement).hidden)).toBe(false);
    await page.screenshot({ path: path.join(artifacts, 'accuracy-pyramid-drift.png') });
    expect(errors).toEqual([]);
    await page.close();
  }, 120_000);

  it("switches to the H100 study, where the GPU's points are timed and drawn beside the engine's; the URL keeps the choice", async () => {
    const { page, errors } = await open('?scene=stack&measure=drift');
    expect((await pageState(page)).points.some((p) => p.key.startsWith('webgpu '))).toBe(false);
    await page.select('#study', 'accuracy-h100.json');
    await page.waitForFunction(() => window.webphysicsAccuracy.ready && window.webphysicsAccuracy.study === 'accuracy-h100.json');
    const state = await pageState(page);
    expect([state.scene, state.measure]).toEqual(['stack', 'drift']);
    const scene = h100.scenes.find((s) => s.id === 'stack')!;
    const gpuKeys = scene.results.filter((r) => r.backend === 'webgpu').map((r) => r.key);
    expect(gpuKeys.length).toBeGreaterThan(0);
    expect(state.points.map((p) => p.key).sort()).toEqual(scene.results.map((r) => r.key).sort());
    expect(await page.$eval('#about', (e) => e.textContent)).toMatch(/WebGPU on NVIDIA.* \(timed\)\.$/);
    expect(new URL(page.url()).searchParams.get('study')).toBe('accuracy-h100.json');
    await page.screenshot({ path: path.join(artifacts, 'accuracy-stack-drift-h100.png') });
    expect(errors).toEqual([]);
    await page.close();
  }, 120_000);

  it("replays a method's run of a scene in the page to the study's numbers, bit for bit", async () => {
    const { page, errors } = await open('?scene=pendulum&measure=period%20error&method=substeps-2');
    const state = await replayed(page);
    expect(state.replay!.method).toBe('substeps-2');
    const expected = study.scenes.find((s) => s.id === 'pendulum')!.results.find((r) => r.backend === 'js' && r.method === 'substeps-2')!.measures;
    expect(state.expected).toEqual(expected);
    expect(state.replay!.measures).toEqual(expected);
    expect(await page.$eval('#replay-result', (e) => e.textContent)).toMatch(/the same as the study, bit for bit$/);
    await page.screenshot({ path: path.join(artifacts, 'accuracy-pendulum-replay.png') });
    // A trajectory scene: the page runs the converged reference first, then the method.
    await page.select('#scene', 'drop');
    await page.select('#method', 'iter-4-2');
    const drop = await replayed(page);
    const dropExpected = study.scenes.find((s) => s.id === 'drop')!.results.find((r) => r.backend === 'js' && r.method === 'iter-4-2')!.measures;
    expect(drop.replay!.measures).toEqual(dropExpected);
    expect(dropExpected['trajectory error']).toBeGreaterThan(0);
    await page.screenshot({ path: path.join(artifacts, 'accuracy-drop-replay.png') });
    // Every joint kind of the mechanisms scene, and the projectile's whole flight in view.
    for (const [scene, method] of [
      ['mechanisms', 'iter-8-3'],
      ['projectile', 'substeps-2'],
    ]) {
      await page.select('#scene', scene);
      await page.select('#method', method);
      const replay = await replayed(page);
      expect(replay.replay!.measures, scene).toEqual(
        study.scenes.find((s) => s.id === scene)!.results.find((r) => r.backend === 'js' && r.method === method)!.measures,
      );
      await page.screenshot({ path: path.join(artifacts, `accuracy-${scene}-replay.png`) });
    }
    expect(errors).toEqual([]);
    await page.close();
  }, 300_000);

  it("replays a WebGPU method's run on the WebGPU backend where the browser has WebGPU (Chromium, SwiftShader), to the study's numbers", async () => {
    const gpuChromium = await launchChromium({ webgpu: true });
    try {
      const page = await gpuChromium.browser.newPage();
      await page.setViewport({ width: 1280, height: 720 });
      const errors = collectErrors(page);
      await page.goto(`${testbed.url}accuracy.html?scene=pendulum&measure=period%20error&method=webgpu%20iter-8-3`, { waitUntil: 'load' });
      await page.waitForFunction(() => window.webphysicsAccuracy.ready, { timeout: 60_000 });
      expect(await page.$eval('#method', (e) => (e as HTMLSelectElement).value)).toBe('webgpu iter-8-3');
      const state = await replayed(page);
      expect(state.replay!.gpu).toBe(true);
      const expected = study.scenes.find((s) => s.id === 'pendulum')!.results.find((r) => r.key === 'webgpu iter-8-3')!.measures;
      // The study measured it with Dawn's SwiftShader in Node; this is Chromium's.
      expect(state.replay!.measures!['period error']).toBeCloseTo(expected['period error'], 5);
      await page.screenshot({ path: path.join(artifacts, 'accuracy-pendulum-webgpu-replay.png') });
      expect(errors).toEqual([]);
    } finally {
      await gpuChromium.close();
    }
  }, 300_000);

  it('says what is missing when the results cannot be loaded', async () => {
    const page = await chromium.browser.newPage();
    await page.setRequestInterception(true);
    page.on('request', (request) => (request.url().endsWith('/accuracy.json') ? request.respond({ status: 404, body: 'not here' }) : request.continue()));
    await page.goto(`${testbed.url}accuracy.html`, { waitUntil: 'load' });
    await page.waitForFunction(() => window.webphysicsAccuracy.error !== null);
    expect(await page.$eval('#about', (e) => e.textContent)).toBe('Could not load the study: accuracy.json: 404 Not Found (npm run bench:accuracy writes it)');
    await page.close();
  }, 60_000);
});
