/*
 * Headless Chromium for the browser tests, through puppeteer-core (which never downloads a
 * browser): the executable and its flags are scripts/chromium.mjs's (shared with
 * bench/compare-browser.mjs). A missing browser is an error that says how to install one: the
 * tests never skip silently.
 */

import { mkdirSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import puppeteer from 'puppeteer-core';
import type { Browser, Page } from 'puppeteer-core';
import { afterAll, beforeAll } from 'vitest';
import { buildDemos } from '../../scripts/build-demos.mjs';
import { chromiumArgs, chromiumPath } from '../../scripts/chromium.mjs';

export { chromiumArgs, chromiumPath };
import { startServer } from '../../scripts/serve.mjs';

export const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
/** Screenshots and other files the browser tests leave for people to look at (gitignored). */
export const artifactsDir = path.join(repoRoot, 'test-artifacts', 'browser');

export interface LaunchedBrowser {
  browser: Browser;
  close(): Promise<void>;
}

export async function launchChromium({ webgpu = false } = {}): Promise<LaunchedBrowser> {
  const userDataDir = mkdtempSync(path.join(tmpdir(), 'webphysics-chromium-'));
  const browser = await puppeteer.launch({
    executablePath: chromiumPath(),
    headless: true,
    args: chromiumArgs({ webgpu }),
    userDataDir,
    defaultViewport: { width: 1000, height: 700, deviceScaleFactor: 1 },
    protocolTimeout: 300_000,
  });
  return {
    browser,
    async close() {
      await browser.close();
      rmSync(userDataDir, { recursive: true, force: true });
    },
  };
}

export interface Testbed {
  url: string;
  close(): Promise<void>;
}

/** Build the testbed into a temporary folder and serve it on localhost (a free port). */
export async function serveTestbed(): Promise<Testbed> {
  const dir = mkdtempSync(path.join(tmpdir(), 'webphysics-testbed-'));
  await buildDemos(dir);
  const server = await startServer({ root: dir, port: 0 });
  return {
    url: server.url,
    async close() {
      await server.close();
      rmSync(dir, { recursive: true, force: true });
    },
  };
}

/** Serves the demos for the tests of the file or describe block that calls it; the getter gives the server. */
export function useTestbed(): () => Testbed {
  let testbed: Testbed | null = null;
  beforeAll(async () => {
    testbed = await serveTestbed();
  }, 120_000);
  afterAll(async () => {
    await testbed?.close();
  });
  return () => {
    if (testbed === null) throw new Error('the testbed is served from beforeAll on');
    return testbed;
  };
}

/** Launches a browser for the tests of the describe block that calls it; the getter gives it. */
export function useBrowser(launch: () => Promise<LaunchedBrowser>): () => LaunchedBrowser {
  let browser: LaunchedBrowser | null = null;
  beforeAll(async () => {
    browser = await launch();
  }, 120_000);
  afterAll(async () => {
    await browser?.close();
  });
  return () => {
    if (browser === null) throw new Error('the browser is launched from beforeAll on');
    return browser;
  };
}

/** Console errors and uncaught exceptions of a page, as they come. */
export function collectErrors(page: Page): string[] {
  const errors: string[] = [];
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(`console.error: ${message.text()}`);
  });
  page.on('pageerror', (error) => errors.push(`uncaught: ${error instanceof Error ? error.message : String(error)}`));
  page.on('requestfailed', (request) => errors.push(`request failed: ${request.url()} ${request.failure()?.errorText ?? ''}`));
  return errors;
}

/** Open the testbed in a new page and wait for its hooks; the frame timer is stopped. */
export async function openTestbed(browser: Browser, url: string, hash = ''): Promise<{ page: Page; errors: string[] }> {
  const page = await browser.newPage();
  const errors = collectErrors(page);
  await page.goto(url + hash, { waitUntil: 'load' });
  await page.waitForFunction(() => window.testbed !== undefined);
  await page.evaluate(() => window.testbed.setAutoRun(false));
  return { page, errors };
}

export function ensureArtifactsDir(): string {
  mkdirSync(artifactsDir, { recursive: true });
  return artifactsDir;
}

/** A file name for a scene: 'Theo Jansen's Walker' -> 'theo-jansen-s-walker'. */
export function slug(name: string): string {
  return name
    .toLowerCase()
    .replace(/[^a-z0-9]+/g, '-')
    .replace(/^-|-$/g, '');
}

/**
 * Pixels of the element `selector` that are not the black background, counted in a screenshot
 * (a WebGPU canvas cannot be read back from the page once presented).
 */
export async function screenshotPixels(page: Page, selector: string): Promise<number> {
  const element = await page.$(selector);
  if (element === null) throw new Error(`screenshotPixels: no element ${selector}`);
  const png = Buffer.from(await element.screenshot({ type: 'png' })).toString('base64');
  return page.evaluate(async (data) => {
    const image = new Image();
    image.src = `data:image/png;base64,${data}`;
    await image.decode();
    const copy = document.createElement('canvas');
    copy.width = image.width;
    copy.height = image.height;
    const ctx = copy.getContext('2d')!;
    ctx.drawImage(image, 0, 0);
    const pixels = ctx.getImageData(0, 0, copy.width, copy.height).data;
    let n = 0;
    for (let i = 0; i < pixels.length; i += 4) if (pixels[i] + pixels[i + 1] + pixels[i + 2] > 30) n++;
    return n;
  }, png);
}
