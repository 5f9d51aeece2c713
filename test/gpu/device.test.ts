/*
 * Devices: adapter selection and the SwiftShader fallback in Node, the error that says what to
 * install when there is no adapter, device loss (simulated with device.destroy()) and the other
 * errors the backend surfaces instead of failing silently.
 */

import { expect, it } from 'vitest';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2BodyDef, b2_dynamicBody } from '../../src/dynamics/b2Body';
import { b2World } from '../../src/dynamics/b2World';
import { GpuBroadPhase } from '../../src-gpu/broadphase/broadPhase';
import { GpuCapacityError, GpuDeviceLostError, GpuError, GpuOutOfMemoryError, GpuUnavailableError, requestGpu } from '../../src-gpu/device/device';
import type { GpuLossInfo } from '../../src-gpu/device/device';
import { USAGE } from '../../src-gpu/device/layout';
import { findSwiftShaderIcd, loadDawn, mayHaveHardwareAdapter, SWIFTSHADER_ICD_PATHS, withToggle } from '../../src-gpu/device/node';
import type { DawnModule, IcdSearchEnv } from '../../src-gpu/device/node';
import { GpuWorld } from '../../src-gpu/world/world';
import { describeGpu } from './support';

function fakeSearch(files: string[], env: Record<string, string | undefined> = {}, dirs: Record<string, string[]> = {}): IcdSearchEnv {
  return { env: { ...env }, exists: (p) => files.includes(p), list: (p) => dirs[p] ?? [], home: '/home/u' };
}

/** A Dawn whose adapters never appear. */
const noAdapterDawn: DawnModule = {
  create: () => ({ requestAdapter: async () => null }) as unknown as GPU,
  globals: {},
};

it('finds the SwiftShader ICD: $WEBPHYSICS_VK_ICD first, then Chromium/Chrome, then browser-test caches', () => {
  const chromium = SWIFTSHADER_ICD_PATHS[0];
  const chrome = '/opt/google/chrome/vk_swiftshader_icd.json';
  expect(findSwiftShaderIcd(fakeSearch([chromium, chrome]))).toBe(chromium);
  expect(findSwiftShaderIcd(fakeSearch([chrome]))).toBe(chrome);
  expect(findSwiftShaderIcd(fakeSearch(['/x/icd.json', chromium], { WEBPHYSICS_VK_ICD: '/x/icd.json' }))).toBe('/x/icd.json');
  expect(() => findSwiftShaderIcd(fakeSearch([chromium], { WEBPHYSICS_VK_ICD: '/missing.json' }))).toThrow(/WEBPHYSICS_VK_ICD is \/missing.json/);
  const cached = '/home/u/.cache/ms-playwright/chromium-1200/chrome-linux/vk_swiftshader_icd.json';
  expect(findSwiftShaderIcd(fakeSearch([cached], {}, { '/home/u/.cache/ms-playwright': ['chromium-1100', 'chromium-1200'] }))).toBe(cached);
  expect(findSwiftShaderIcd(fakeSearch([]))).toBe(null);
});

it('asks for a hardware adapter only when a Vulkan driver could answer (Linux), always elsewhere', () => {
  expect(mayHaveHardwareAdapter(fakeSearch([]), 'linux')).toBe(false);
  expect(mayHaveHardwareAdapter(fakeSearch([], { VK_DRIVER_FILES: '/nv.json' }), 'linux')).toBe(true);
  expect(mayHaveHardwareAdapter(fakeSearch([], {}, { '/usr/share/vulkan/icd.d': ['nvidia_icd.json'] }), 'linux')).toBe(true);
  expect(mayHaveHardwareAdapter(fakeSearch([]), 'darwin')).toBe(true);
  expect(mayHaveHardwareAdapter(fakeSearch([]), 'win32')).toBe(true);
});

it('merges its Dawn toggle with the caller’s', () => {
  expect(withToggle([], 'disable_workgroup_init')).toEqual(['enable-dawn-features=disable_workgroup_init']);
  expect(withToggle(['backend=vulkan', 'enable-dawn-features=dump_shaders'], 'disable_workgroup_init')).toEqual([
    'backend=vulkan',
    'enable-dawn-features=dump_shaders,disable_workgroup_init',
  ]);
  expect(withToggle(['x'], null)).toEqual(['x']);
});

it('says what to install when no adapter exists', async () => {
  const err = await requestGpu({ loadDawn: async () => noAdapterDawn, search: fakeSearch([]) }).catch((e) => e);
  expect(err).toBeInstanceOf(GpuUnavailableError);
  expect(err.message).toMatch(/No WebGPU adapter found/);
  expect(err.message).toMatch(/apt-get install chromium libvulkan1/);
  expect(err.message).toMatch(/npm run setup/);
  expect(err.message).toMatch(/WEBPHYSICS_VK_ICD/);
  expect(err.message).toMatch(/libvulkan\.so\.1\) is not installed/);

  const icd = SWIFTSHADER_ICD_PATHS[0];
  const refused = await requestGpu({ loadDawn: async () => noAdapterDawn, search: fakeSearch([icd]) }).catch((e) => e);
  expect(refused).toBeInstanceOf(GpuUnavailableError);
  expect(refused.message).toContain(`did not accept the SwiftShader driver ${icd}`);

  const off = await requestGpu({ loadDawn: async () => noAdapterDawn, search: fakeSearch([icd]), softwareFallback: false }).catch((e) => e);
  expect(off.message).toMatch(/software fallback is off/);
});

it('says how to install the webgpu package when Node cannot load it', async () => {
  const err = await loadDawn('webgpu-package-that-does-not-exist').catch((e) => e);
  expect(err).toBeInstanceOf(GpuUnavailableError);
  expect(err.message).toMatch(/npm install webgpu@0\.6\.2/);
});

it('refuses a custom GPU object that gives no adapter', async () => {
  const err = await requestGpu({ gpu: noAdapterDawn.create([]) }).catch((e) => e);
  expect(err).toBeInstanceOf(GpuUnavailableError);
});

describeGpu('devices', (ctx) => {
  it('selects an adapter and asks for its storage limits (SwiftShader on a machine without a GPU)', () => {
    const info = ctx.adapterInfo;
    expect(['dawn', 'dawn-swiftshader', 'navigator']).toContain(info.source);
    if (info.source === 'dawn-swiftshader') {
      expect(info.software).toBe(true);
      expect(info.architecture).toBe('swiftshader');
      expect(info.icd).toMatch(/vk_swiftshader_icd\.json$/);
      expect(process.env.VK_ICD_FILENAMES).toBe(info.icd);
    }
    expect(ctx.limits.maxStorageBufferBindingSize).toBe(ctx.adapter.limits.maxStorageBufferBindingSize);
    expect(ctx.limits.maxBufferSize).toBe(ctx.adapter.limits.maxBufferSize);
    expect(ctx.timestamps).toBe(ctx.adapter.features.has('timestamp-query'));
  });

  it('falls back to SwiftShader on request, and accepts a GPU object from the caller', async () => {
    const software = await requestGpu({ forceSoftware: true }).catch((e) => e);
    if (software instanceof GpuUnavailableError) {
      expect(software.message).toMatch(/SwiftShader/);
      return;
    }
    expect(software.adapterInfo.source).toBe('dawn-swiftshader');
    expect(software.adapterInfo.software).toBe(true);
    const custom = await requestGpu({ gpu: software.gpu! });
    expect(custom.adapterInfo.source).toBe('custom');
    software.destroy();
    custom.destroy();
  });

  it('passes skip_validation to Dawn only when asked, and the broad phase finds the same pairs with it', async () => {
    const seen: string[][] = [];
    const recording = async (): Promise<DawnModule> => {
      const dawn = await loadDawn();
      return { ...dawn, create: (toggles: string[]) => (seen.push(toggles), dawn.create(toggles)) };
    };
    const pairsWith = async (skipValidation: boolean) => {
      const gpu = await requestGpu({ loadDawn: recording, forceSoftware: true, skipValidation });
      const world = new b2World(new b2Vec2(0, -10));
      const box = new b2PolygonShape();
      box.SetAsBox(0.5, 0.5);
      for (let i = 0; i < 20; ++i) {
        const bd = new b2BodyDef();
        bd.type = b2_dynamicBody;
        bd.position.Set((i % 5) * 0.9, Math.floor(i / 5) * 0.9);
        world.CreateBody(bd).CreateFixture(box, 1);
      }
      const mirror = new GpuWorld(gpu, world);
      mirror.sync();
      const broadPhase = new GpuBroadPhase(gpu);
      await broadPhase.update(mirror);
      const pairs = await broadPhase.readPairs();
      gpu.destroy();
      return pairs;
    };
    const validated = await pairsWith(false);
    const skipped = await pairsWith(true);
    expect(seen[0].join(' ')).not.toMatch(/skip_validation/);
    expect(seen[1].join(' ')).toMatch(/enable-dawn-features=[^ ]*skip_validation/);
    expect(validated.length).toBeGreaterThan(0);
    expect(skipped).toEqual(validated);
  });
  it('reports device loss through onLost and `lost`; the JavaScript world goes on', async () => {
    const losses: GpuLossInfo[] = [];
    const lossy = await requestGpu({ onLost: (info) => losses.push(info) });
    const world = new b2World(new b2Vec2(0, -10));
    const def = new b2BodyDef();
    def.type = b2_dynamicBody;
    def.position.Set(0, 10);
    const body = world.CreateBody(def);
    const shape = new b2PolygonShape();
    shape.SetAsBox(0.5, 0.5);
    body.CreateFixture(shape, 1);
    const mirror = new GpuWorld(lossy, world);
    const broadPhase = new GpuBroadPhase(lossy);
    mirror.sync();
    await broadPhase.update(mirror);

    lossy.destroy();
    const info = await lossy.lost;
    expect(info.reason).toBe('destroyed');
    expect(losses).toEqual([info]);
    expect(lossy.isLost).toBe(true);
    await expect(broadPhase.update(mirror)).rejects.toBeInstanceOf(GpuDeviceLostError);
    expect(() => mirror.sync()).toThrow(GpuDeviceLostError);

    for (let i = 0; i < 30; ++i) world.Step(1 / 60, 8, 3);
    expect(body.GetPosition().y).toBeLessThan(10);
  });

  it('refuses buffers larger than the device allows, with the limit in the message', () => {
    expect(() => ctx.createBuffer('huge', ctx.limits.maxBufferSize + 16, USAGE.STORAGE)).toThrow(GpuCapacityError);
    expect(() => ctx.createBuffer('huge', ctx.limits.maxBufferSize + 16, USAGE.STORAGE)).toThrow(/maxBufferSize/);
  });

  it('surfaces out-of-memory and validation errors instead of failing silently', async () => {
    const oom = await requestGpu();
    const device = oom.device;
    const pop = device.popErrorScope.bind(device);
    device.popErrorScope = async () => {
      await pop();
      return { message: 'simulated allocation failure' } as GPUError;
    };
    oom.createBuffer('victim', 1024, USAGE.STORAGE);
    await expect(oom.checkErrors()).rejects.toBeInstanceOf(GpuOutOfMemoryError);
    oom.destroy();

    const invalid = await requestGpu();
    const buffer = invalid.createBuffer('mapped and storage', 64, USAGE.STORAGE);
    invalid.device.queue.writeBuffer(buffer, 3, new Uint8Array(4)); // offset not a multiple of 4
    await new Promise((r) => setTimeout(r, 50));
    await expect(invalid.checkErrors()).rejects.toBeInstanceOf(GpuError);
    invalid.destroy();
  });
});
