/*
 * The testbed (demos/, `npm start`) in headless Chromium and headless Firefox: every scene loads without console
 * errors, runs 120 steps and draws; the mouse drags bodies through a b2MouseJoint and launches
 * bombs; keys reach the tests; the panel's controls, the camera, high-DPI rendering and b2dJson
 * file drops work. One page serves all scenes (window.testbed.select switches), and a screenshot
 * of each scene is saved under test-artifacts/browser/ (Firefox's named firefox-*). Firefox has no
 * WebGPU here, so its page must say so and run on JavaScript.
 */

import { readFileSync } from 'node:fs';
import path from 'node:path';
import type { Page } from 'puppeteer-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { benchEntries } from '../../demos/scenes/bench';
import { g_testEntries } from '../../demos/tests/index';
import { goldenDir } from '../support/golden';
import { ensureArtifactsDir, launchChromium, openTestbed, serveTestbed, slug } from './chromium';
import { launchFirefox } from './firefox';
import type { LaunchedBrowser, Testbed } from './chromium';

const kSteps = 120;
/**
 * Scenes whose last frame may be empty, and why: for these the first frame must show the scene.
 * Everything else must still be drawn after the 120 steps.
 */
const kLeavesTheView: Record<string, string> = {
  'Add Pair Stress Test': 'the 150 m/s bullet box blows the 400 light circles out of view within 2 s, as in the C++ Testbed',
};
/** Canvas pixels (outside the text) that make a frame "not blank": a few short lines' worth. */
const kMinPixels = 60;
const sceneNames = [...g_testEntries, ...benchEntries()].map((e) => e.name);

/** The whole suite in one browser, whose user agent matches `agent`; `prefix` starts the names of its screenshots. */
function testbedSuite(launch: () => Promise<LaunchedBrowser>, agent: RegExp, prefix: string): void {
  let testbed: Testbed;
  let browser: LaunchedBrowser;
  let page: Page;
  let errors: string[];
  let artifacts: string;

  beforeAll(async () => {
    artifacts = ensureArtifactsDir();
    testbed = await serveTestbed();
    browser = await launch();
    ({ page, errors } = await openTestbed(browser.browser, testbed.url));
  }, 120_000);

  afterAll(async () => {
    await browser?.close();
    await testbed?.close();
  });

  /** Errors logged since `from`, and the testbed's own list of what tests threw. */
  async function newErrors(from: number): Promise<string[]> {
    const own = await page.evaluate(() => window.testbed.errors.slice());
    return [...errors.slice(from), ...own];
  }

  describe('the testbed page', () => {
    it('loads with no console errors and lists every scene', async () => {
      expect(await page.evaluate(() => navigator.userAgent)).toMatch(agent);
      expect(await newErrors(0)).toEqual([]);
      const listed = await page.evaluate(() => window.testbed.entries().map((e) => e.name));
      expect(listed).toEqual(sceneNames);
      expect(listed.filter((n) => !n.startsWith('Benchmark: '))).toHaveLength(45);
    });

    it('says whether the browser has WebGPU and offers the WebGPU backend only where it has an adapter', async () => {
      const status = await page.evaluate(async () => {
        const s = await window.testbed.webgpu;
        const option = document.querySelector<HTMLOptionElement>('#backend option[value="webgpu"]')!;
        return { ...s, text: document.getElementById('webgpu-status')!.textContent, disabled: option.disabled, label: option.textContent };
      });
      // This browser runs with --disable-gpu: navigator.gpu may exist, but normally there is no
      // adapter (testbedWebgpu.test.ts checks the browser that has one). The page says which it found.
      if (!status.api) expect(status.text).toMatch(/^This browser lacks WebGPU/);
      else if (!status.adapter) expect(status.text).toMatch(/^This browser has WebGPU but no adapter/);
      else expect(status.text).toMatch(/^This browser has WebGPU \(adapter/);
      expect(status.disabled).toBe(!status.adapter);
      expect(status.label).toBe('WebGPU');
    });

    it('?backend=webgpu without an adapter says so and runs the test on JavaScript', async () => {
      const opened = await openTestbed(browser.browser, testbed.url, '?test=Pyramid&backend=webgpu');
      try {
        const state = await opened.page.evaluate(async () => {
          const status = await window.testbed.webgpu;
          const before = window.testbed.state().stepCount;
          window.testbed.frame(3);
          return {
            status,
            backend: window.testbed.backend(),
            steps: window.testbed.state().stepCount - before,
            message: document.getElementById('message')!.textContent,
          };
        });
        // Launched with --disable-gpu: no adapter (testbedWebgpu.test.ts runs the browser that has one).
        expect(state.status.adapter).toBe(false);
        expect(state.backend.active).toBe('js');
        expect(state.message).toMatch(/^WebGPU is not available here \(.*\); the JavaScript engine runs\.$/);
        expect(state.steps).toBe(3);
        expect(opened.errors).toEqual([]);
      } finally {
        await opened.page.close();
      }
    });
  });

  describe(`every scene runs ${kSteps} steps and draws`, () => {
    for (const name of sceneNames) {
      it(
        name,
        async () => {
          const from = errors.length;
          const result = await page.evaluate(
            (sceneName: string, steps: number) => {
              const tb = window.testbed;
              if (!tb.select(sceneName)) return null;
              tb.frame(1);
              const firstPixels = tb.drawnPixels();
              tb.frame(steps - 1);
              return { state: tb.state(), firstPixels, pixels: tb.drawnPixels(), text: tb.text() };
            },
            name,
            kSteps,
          );
          await page.screenshot({ path: path.join(artifacts, `${prefix}${slug(name)}.png`) });
          expect(result, `select(${name})`).not.toBeNull();
          expect(await newErrors(from)).toEqual([]);
          expect(result!.state.name).toBe(name);
          expect(result!.state.frames).toBeGreaterThan(0);
          // Pixels other than the background, outside the text: the scene itself was drawn.
          expect(result!.firstPixels).toBeGreaterThan(kMinPixels);
          if (!(name in kLeavesTheView)) expect(result!.pixels).toBeGreaterThan(kMinPixels);
          expect(result!.text[result!.text.length - 1]).toBe(name); // the title, drawn last
        },
        180_000,
      );
    }
  });

  describe('mouse and keyboard', () => {
    it('a drag on a body creates a mouse joint that moves it, released on mouse up', async () => {
      await page.evaluate(() => {
        window.testbed.select('Varying Restitution');
        window.testbed.frame(1);
      });
      // The ball of restitution 0.5, at (-1, 20) when the test starts.
      const bodies = await page.evaluate(() => window.testbed.bodies());
      const index = bodies.findIndex((b) => b.type === 'dynamic' && Math.abs(b.x + 1) < 1e-9);
      expect(index).toBeGreaterThanOrEqual(0);
      const start = bodies[index];
      const at = await page.evaluate((x: number, y: number) => window.testbed.worldToClient(x, y), start.x, start.y);

      await page.mouse.move(at.x, at.y);
      await page.mouse.down();
      expect((await page.evaluate(() => window.testbed.state())).mouseJoint).toBe(true);
      // Drag 5 m to the right and 5 m up (the view shows 50 m in its height).
      const target = await page.evaluate((x: number, y: number) => window.testbed.worldToClient(x, y), start.x + 5, start.y + 5);
      await page.mouse.move(target.x, target.y, { steps: 5 });
      await page.evaluate(() => window.testbed.frame(90));
      const held = (await page.evaluate(() => window.testbed.bodies()))[index];
      expect(held.x - start.x).toBeGreaterThan(4);
      expect(held.y - start.y).toBeGreaterThan(3);
      await page.mouse.up();
      expect((await page.evaluate(() => window.testbed.state())).mouseJoint).toBe(false);
      expect(await newErrors(0)).toEqual([]);
    });

    it('shift + drag launches a bomb, and space a random one', async () => {
      await page.evaluate(() => {
        window.testbed.select('Pyramid');
        window.testbed.frame(1);
      });
      // Whole pixels: Firefox's pointer events (WebDriver BiDi) carry integer coordinates.
      const near = await page.evaluate(() => window.testbed.worldToClient(-20, 30));
      const from = { x: Math.round(near.x), y: Math.round(near.y) };
      await page.keyboard.down('Shift');
      await page.mouse.move(from.x, from.y);
      await page.mouse.down();
      await page.mouse.move(from.x - 40, from.y + 40, { steps: 4 });
      await page.mouse.up();
      await page.keyboard.up('Shift');
      const afterDrag = await page.evaluate(() => ({ state: window.testbed.state(), bodies: window.testbed.bodies() }));
      expect(afterDrag.state.bomb).toBe(true);
      // The bomb (first in the body list: the newest) starts where the drag started and flies back
      // along it (the drag went left and down), at 30 times its length per second.
      const bomb = afterDrag.bodies[0];
      expect(bomb.bullet).toBe(true);
      const at = await page.evaluate((x: number, y: number) => window.testbed.worldToClient(x, y), bomb.x, bomb.y);
      expect(at.x).toBeCloseTo(from.x, 6);
      expect(at.y).toBeCloseTo(from.y, 6);
      expect(bomb.vx).toBeGreaterThan(50);
      expect(bomb.vy).toBeCloseTo(bomb.vx, 6);

      const before = afterDrag.state.bodyCount;
      await page.keyboard.press(' ');
      const afterSpace = await page.evaluate(() => ({ state: window.testbed.state(), bodies: window.testbed.bodies() }));
      // LaunchBomb destroys the previous bomb: the count stays, the new one starts at y = 30.
      expect(afterSpace.state.bodyCount).toBe(before);
      expect(afterSpace.bodies[0].y).toBe(30);
      expect(await newErrors(0)).toEqual([]);
    });

    it("a key reaches the test's Keyboard: ',' fires Vertical Stack's bullet; 'm' changes Ray-Cast's mode", async () => {
      await page.evaluate(() => {
        window.testbed.select('Vertical Stack');
        window.testbed.frame(1);
      });
      const before = await page.evaluate(() => window.testbed.state().bodyCount);
      await page.keyboard.press(',');
      const after = await page.evaluate(() => ({ count: window.testbed.state().bodyCount, bullet: window.testbed.bodies()[0] }));
      expect(after.count).toBe(before + 1);
      expect(after.bullet).toMatchObject({ x: -31, y: 5, vx: 400, bullet: true });
      await page.evaluate(() => window.testbed.frame(30));
      // It went through the stacks' column at x = 10 and hit the wall at x = 20 within half a second.
      expect((await page.evaluate(() => window.testbed.bodies()[0])).x).toBeGreaterThan(0);

      await page.evaluate(() => {
        window.testbed.select('Ray-Cast');
        window.testbed.frame(1);
      });
      expect(await page.evaluate(() => window.testbed.text())).toContain('Mode = 0');
      await page.keyboard.press('m');
      await page.evaluate(() => window.testbed.frame(1));
      expect(await page.evaluate(() => window.testbed.text())).toContain('Mode = 1');
      expect(await newErrors(0)).toEqual([]);
    });

    it('key down and key up reach Pinball (the flippers go up while a is held)', async () => {
      await page.evaluate(() => {
        window.testbed.select('Pinball');
        window.testbed.frame(30);
      });
      // The left flipper turns about (-2, 0).
      const angle = () => page.evaluate(() => window.testbed.bodies().find((b) => b.type === 'dynamic' && Math.hypot(b.x + 2, b.y) < 0.05)!.angle);
      const down = await angle();
      await page.keyboard.down('a');
      await page.evaluate(() => window.testbed.frame(20));
      const up = await angle();
      await page.keyboard.up('a');
      await page.evaluate(() => window.testbed.frame(20));
      const back = await angle();
      expect(up).toBeGreaterThan(down + 0.3);
      expect(back).toBeLessThan(up - 0.3);
    });
  });

  describe('panel and camera', () => {
    it('Pause, Single Step and p pause and step the world', async () => {
      await page.evaluate(() => window.testbed.select('SphereStack'));
      await page.click('#pause');
      const paused = await page.evaluate(() => {
        const tb = window.testbed;
        const before = tb.state().stepCount;
        tb.frame(5);
        return { pause: tb.settings.pause, moved: tb.state().stepCount - before, text: tb.text() };
      });
      expect(paused.pause).toBe(1);
      expect(paused.moved).toBe(0);
      expect(paused.text).toContain('****PAUSED****');
      await page.click('#single-step');
      const stepped = await page.evaluate(() => {
        const tb = window.testbed;
        const before = tb.state().stepCount;
        tb.frame(3);
        return tb.state().stepCount - before;
      });
      expect(stepped).toBe(1);
      await page.keyboard.press('p');
      expect(await page.evaluate(() => window.testbed.settings.pause)).toBe(0);
    });

    it('the iteration, Hertz and flag controls set the settings the test steps with', async () => {
      await page.evaluate(() => window.testbed.select('Pyramid'));
      const set = async (selector: string, value: string) => {
        await page.$eval(
          selector,
          (input, v) => {
            (input as HTMLInputElement).value = v;
            input.dispatchEvent(new Event('change'));
          },
          value,
        );
      };
      await set('#velocityIterations', '20');
      await set('#positionIterations', '5');
      await set('#hz', '30');
      await page.click('input[data-setting="drawStats"]');
      await page.click('input[data-setting="drawProfile"]');
      await page.click('input[data-setting="drawAABBs"]');
      await page.click('input[data-setting="enableWarmStarting"]');
      const result = await page.evaluate(() => {
        const tb = window.testbed;
        tb.frame(2);
        return { settings: { ...tb.settings }, text: tb.text() };
      });
      expect(result.settings).toMatchObject({
        velocityIterations: 20,
        positionIterations: 5,
        hz: 30,
        drawStats: 1,
        drawProfile: 1,
        drawAABBs: 1,
        enableWarmStarting: 0,
      });
      expect(result.text.some((t) => t.startsWith('bodies/contacts/joints = 212/'))).toBe(true);
      expect(result.text.some((t) => t.startsWith('proxies/height/balance/quality = 211/'))).toBe(true);
      expect(result.text.some((t) => /^step \[ave\] \(max\) = +\d+\.\d\d \[ +\d+\.\d\d\] \( +\d+\.\d\d\)$/.test(t))).toBe(true);
      expect(result.text.some((t) => t.startsWith('broad-phase [ave] (max) = '))).toBe(true);
      // Back to the defaults for the tests that follow.
      await set('#velocityIterations', '8');
      await set('#positionIterations', '3');
      await set('#hz', '60');
      for (const flag of ['drawStats', 'drawProfile', 'drawAABBs', 'enableWarmStarting']) await page.click(`input[data-setting="${flag}"]`);
    });

    it('the wheel zooms, a right drag and the arrows pan, Home resets the view', async () => {
      await page.evaluate(() => {
        window.testbed.select('Bridge');
        window.testbed.frame(1);
      });
      const view = () => page.evaluate(() => window.testbed.state());
      const centre = await page.evaluate(() => window.testbed.worldToClient(0, 20));
      await page.mouse.move(centre.x, centre.y);
      await page.mouse.wheel({ deltaY: -100 });
      expect((await view()).viewZoom).toBeCloseTo(1 / 1.1, 12);
      await page.mouse.wheel({ deltaY: 100 });
      expect((await view()).viewZoom).toBeCloseTo(1, 12);

      await page.mouse.down({ button: 'right' });
      await page.mouse.move(centre.x + 70, centre.y - 70, { steps: 3 });
      await page.mouse.up({ button: 'right' });
      const panned = (await view()).viewCenter;
      // 70 px at 700 px per 50 m: the world follows the mouse, so the centre moves 5 m left and down.
      expect(panned.x).toBeCloseTo(-5, 6);
      expect(panned.y).toBeCloseTo(15, 6);

      await page.keyboard.press('ArrowRight');
      await page.keyboard.press('ArrowUp');
      expect((await view()).viewCenter).toEqual({ x: panned.x + 0.5, y: panned.y + 0.5 });
      await page.keyboard.press('z');
      expect((await view()).viewZoom).toBeCloseTo(1.1, 12);
      await page.keyboard.press('Home');
      expect(await view()).toMatchObject({ viewCenter: { x: 0, y: 20 }, viewZoom: 1 });
    });

    it('draws at devicePixelRatio: the canvas backing store is the CSS size times the ratio', async () => {
      await page.setViewport({ width: 1000, height: 700, deviceScaleFactor: 2 });
      const sizes = await page.evaluate(() => {
        window.testbed.frame(1);
        const canvas = document.getElementById('canvas') as HTMLCanvasElement;
        return {
          width: canvas.width,
          height: canvas.height,
          cssWidth: canvas.clientWidth,
          cssHeight: canvas.clientHeight,
          pixels: window.testbed.drawnPixels(),
        };
      });
      await page.setViewport({ width: 1000, height: 700, deviceScaleFactor: 1 });
      expect(sizes.width).toBe(2 * sizes.cssWidth);
      expect(sizes.height).toBe(2 * sizes.cssHeight);
      expect(sizes.pixels).toBeGreaterThan(800);
    });

    it('takes the README screenshot (Tumbler with the statistics and profile overlay)', async () => {
      await page.setViewport({ width: 900, height: 540, deviceScaleFactor: 1 });
      await page.click('input[data-setting="drawStats"]');
      await page.click('input[data-setting="drawProfile"]');
      const text = await page.evaluate(() => {
        window.testbed.select('Tumbler');
        window.testbed.frame(240);
        return window.testbed.text();
      });
      await page.$eval('#panel', (panel) => (panel.scrollTop = 0));
      await page.screenshot({ path: path.join(artifacts, `${prefix}readme-testbed.png`) });
      await page.click('input[data-setting="drawStats"]');
      await page.click('input[data-setting="drawProfile"]');
      await page.setViewport({ width: 1000, height: 700, deviceScaleFactor: 1 });
      // Tumbler adds a box after each Step, and prints the counts within it: at the 240th frame the
      // framework's ground body, the test's two bodies and 239 boxes.
      expect(text.some((t) => /^bodies\/contacts\/joints = 242\/\d+\/1$/.test(t))).toBe(true);
      expect(await newErrors(0)).toEqual([]);
    });

    it('a b2dJson file dropped on the page becomes a scene', async () => {
      const text = readFileSync(path.join(goldenDir, 'scenes', 'joint-zoo.scene.json'), 'utf8');
      const expectedBodies = JSON.parse(text).body.length;
      await page.evaluate((json: string) => {
        const data = new DataTransfer();
        data.items.add(new File([json], 'joint-zoo.scene.json', { type: 'application/json' }));
        window.dispatchEvent(new DragEvent('drop', { dataTransfer: data, bubbles: true, cancelable: true }));
      }, text);
      await page.waitForFunction(() => window.testbed.state().name === 'File: joint-zoo.scene.json');
      const result = await page.evaluate(() => {
        window.testbed.frame(60);
        return { state: window.testbed.state(), pixels: window.testbed.drawnPixels() };
      });
      await page.screenshot({ path: path.join(artifacts, `${prefix}file-joint-zoo.png`) });
      // The file's bodies and the framework's ground body.
      expect(result.state.bodyCount).toBe(expectedBodies + 1);
      expect(result.pixels).toBeGreaterThan(200);

      // A file that is not b2dJson is refused with a message, and the scene stays.
      await page.evaluate(() => window.testbed.loadJson('{"body": 3}', 'bad.json'));
      expect(await page.$eval('#message', (e) => e.textContent)).toMatch(/^bad\.json is not a b2dJson scene/);
      expect((await page.evaluate(() => window.testbed.state())).name).toBe('File: joint-zoo.scene.json');
      expect(await newErrors(0)).toEqual([]);
    });
  });
}

describe('in Chromium', () => testbedSuite(launchChromium, /Chrome\//, ''));
describe('in Firefox', () => testbedSuite(launchFirefox, /Firefox\//, 'firefox-'));
