/*
 * WebGPU in headless Chromium: with --enable-unsafe-webgpu --enable-features=Vulkan
 * --use-webgpu-adapter=swiftshader (SwiftShader is the CPU Vulkan driver Chromium ships), a
 * localhost page gets an adapter, and the testbed says that this browser has WebGPU. This is the
 * browser the WebGPU backend's tests will run in; a machine without it fails here rather than
 * skipping.
 */

import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { launchChromium, openTestbed, serveTestbed } from './chromium';
import type { LaunchedBrowser, Testbed } from './chromium';

let testbed: Testbed;
let chromium: LaunchedBrowser;

beforeAll(async () => {
  testbed = await serveTestbed();
  chromium = await launchChromium({ webgpu: true });
}, 120_000);

afterAll(async () => {
  await chromium?.close();
  await testbed?.close();
});

describe('WebGPU in headless Chromium on SwiftShader', () => {
  it('requestAdapter() gives an adapter on a localhost page, and the testbed reports it', async () => {
    const { page, errors } = await openTestbed(chromium.browser, testbed.url);
    const result = await page.evaluate(async () => {
      const gpu = (navigator as unknown as { gpu?: { requestAdapter(): Promise<{ info?: { vendor?: string; architecture?: string } } | null> } }).gpu;
      const adapter = gpu === undefined ? null : await gpu.requestAdapter();
      const status = await window.testbed.webgpu;
      return {
        secure: window.isSecureContext,
        hasGpu: gpu !== undefined,
        adapter: adapter !== null,
        vendor: adapter?.info?.vendor ?? '',
        status,
        text: document.getElementById('webgpu-status')!.textContent,
      };
    });
    expect(result.secure).toBe(true); // localhost is a secure context: WebGPU is exposed there
    expect(result.hasGpu).toBe(true);
    expect(result.adapter, 'requestAdapter() returned null: is SwiftShader (libvk_swiftshader) missing?').toBe(true);
    expect(result.status.adapter).toBe(true);
    expect(result.text).toMatch(/^This browser has WebGPU/);
    expect(errors).toEqual([]);
  });
});
