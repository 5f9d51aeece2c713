/*
 * Node only: Dawn (the `webgpu` package) and its software fallback.
 *
 * Node has no navigator.gpu. The optional peer dependency `webgpu` is Dawn built for Node; its
 * Vulkan backend finds the GPU's Vulkan driver through the Vulkan loader (libvulkan.so.1). On a
 * machine with no GPU, Dawn can run on SwiftShader, the CPU Vulkan driver that Chromium and
 * Chrome ship beside their binary (vk_swiftshader_icd.json): pointing VK_ICD_FILENAMES (and the
 * newer VK_DRIVER_FILES) at that file in process.env before a Dawn instance is created makes the
 * loader offer it, from inside the running process.
 *
 * The Node modules themselves are loaded in ./nodeImports.ts, which the browser build of
 * webphysics/gpu replaces (scripts/build.mjs), so a bundler never meets them on a browser's path.
 */

import { importPackage, nodeSearchEnv } from './nodeImports';

/** What `import('webgpu')` gives: Dawn's `create(toggles)` and the WebGPU globals. */
export interface DawnModule {
  create(options: string[]): GPU;
  globals: object;
}

/** Thrown when no WebGPU adapter or implementation can be had; the message says what to install. */
export class GpuUnavailableError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'GpuUnavailableError';
  }
}

export const WEBGPU_PACKAGE_HINT = "The WebGPU backend in Node needs the optional peer dependency 'webgpu' (Dawn for Node): npm install webgpu@0.6.2";

export const SOFTWARE_ADAPTER_HINT =
  'For a software adapter (SwiftShader), install Chromium or Chrome and the Vulkan loader ' +
  '(Debian/Ubuntu: apt-get install chromium libvulkan1, which `npm run setup` does), or set ' +
  'WEBPHYSICS_VK_ICD to a vk_swiftshader_icd.json.';

export function isNode(): boolean {
  return typeof process !== 'undefined' && typeof process.versions === 'object' && !!process.versions.node;
}

/** Loads the `webgpu` package, or throws GpuUnavailableError saying how to install it. */
export async function loadDawn(name = 'webgpu'): Promise<DawnModule> {
  try {
    const mod = (await importPackage(name)) as DawnModule & { default?: DawnModule };
    const dawn = typeof mod.create === 'function' ? mod : mod.default;
    if (!dawn || typeof dawn.create !== 'function') {
      throw new Error("the module has no 'create' export");
    }
    return dawn;
  } catch (err) {
    const why = err instanceof Error ? err.message : String(err);
    throw new GpuUnavailableError(`${WEBGPU_PACKAGE_HINT} (loading it failed: ${why})`);
  }
}

/** Where Chromium, Chrome and the browser-test caches put SwiftShader's Vulkan ICD file. */
export const SWIFTSHADER_ICD_PATHS: readonly string[] = [
  '/usr/lib/chromium/vk_swiftshader_icd.json', // Debian's chromium
  '/usr/lib/chromium-browser/vk_swiftshader_icd.json', // Ubuntu, Fedora
  '/usr/lib64/chromium-browser/vk_swiftshader_icd.json',
  '/snap/chromium/current/usr/lib/chromium-browser/vk_swiftshader_icd.json',
  '/opt/google/chrome/vk_swiftshader_icd.json',
  '/opt/google/chrome-beta/vk_swiftshader_icd.json',
  '/opt/google/chrome-unstable/vk_swiftshader_icd.json',
];

/** Folders (relative to the home directory) whose subfolders may hold a downloaded Chromium. */
const SWIFTSHADER_CACHE_GLOBS: readonly string[][] = [
  ['.cache/ms-playwright', 'chrome-linux'],
  ['.cache/ms-playwright', 'chrome-linux64'],
  ['.cache/puppeteer/chrome', 'chrome-linux64'],
];

export interface IcdSearchEnv {
  env: Record<string, string | undefined>;
  exists(path: string): boolean;
  /** Subfolder names of a folder ([] when it does not exist). */
  list(path: string): string[];
  home: string;
}

/**
 * The SwiftShader Vulkan ICD file to use: $WEBPHYSICS_VK_ICD when set (an error if that file is
 * missing), else the first of SWIFTSHADER_ICD_PATHS and the Playwright/Puppeteer caches that
 * exists, else null.
 */
export function findSwiftShaderIcd(search: IcdSearchEnv): string | null {
  const override = search.env.WEBPHYSICS_VK_ICD;
  if (override) {
    if (!search.exists(override)) {
      throw new GpuUnavailableError(`WEBPHYSICS_VK_ICD is ${override}, which does not exist.`);
    }
    return override;
  }
  for (const p of SWIFTSHADER_ICD_PATHS) {
    if (search.exists(p)) return p;
  }
  for (const [dir, leaf] of SWIFTSHADER_CACHE_GLOBS) {
    const root = `${search.home}/${dir}`;
    for (const sub of search.list(root).sort().reverse()) {
      const p = `${root}/${sub}/${leaf}/vk_swiftshader_icd.json`;
      if (search.exists(p)) return p;
    }
  }
  return null;
}

/** Folders the Vulkan loader reads driver manifests from on Linux. */
function icdFolders(search: IcdSearchEnv): string[] {
  const dataDirs = (search.env.XDG_DATA_DIRS || '/usr/local/share:/usr/share').split(':');
  return [...dataDirs.map((d) => `${d}/vulkan/icd.d`), '/etc/vulkan/icd.d', `${search.home}/.local/share/vulkan/icd.d`];
}

/**
 * Is a hardware adapter worth asking Dawn for? True when the environment names a Vulkan driver,
 * when a driver manifest is installed, or when the platform is not Linux (Metal, D3D12). False
 * skips an attempt that would only print the Vulkan loader's "Found no drivers!" warnings.
 */
export function mayHaveHardwareAdapter(search: IcdSearchEnv, platform: string): boolean {
  if (platform !== 'linux') return true;
  if (search.env.VK_ICD_FILENAMES || search.env.VK_DRIVER_FILES || search.env.VK_ADD_DRIVER_FILES) return true;
  return icdFolders(search).some((d) => search.list(d).some((f) => f.endsWith('.json')));
}

/** Is the Vulkan loader installed where Linux distributions put it? (For the error message.) */
function vulkanLoaderPresent(search: IcdSearchEnv): boolean {
  const dirs = ['/usr/lib/x86_64-linux-gnu', '/usr/lib/aarch64-linux-gnu', '/usr/lib64', '/usr/lib', '/usr/local/lib', '/lib/x86_64-linux-gnu'];
  return dirs.some((d) => search.exists(`${d}/libvulkan.so.1`));
}

/** Adds `feature` to the enable-dawn-features toggle of `options` (creating it when missing). */
export function withToggle(options: string[], feature: string | null): string[] {
  if (feature === null) return options;
  const prefix = 'enable-dawn-features=';
  const i = options.findIndex((o) => o.startsWith(prefix));
  if (i < 0) return [...options, prefix + feature];
  const features = options[i].slice(prefix.length).split(',').filter(Boolean);
  if (features.includes(feature)) return options;
  const out = options.slice();
  out[i] = prefix + [...features, feature].join(',');
  return out;
}

export interface NodeAdapterOptions {
  powerPreference?: GPUPowerPreference;
  /** Use SwiftShader when no hardware adapter is found (default true). */
  softwareFallback?: boolean;
  /** Use SwiftShader even when a hardware adapter exists. */
  forceSoftware?: boolean;
  /** Dawn toggles for webgpu's create(). */
  dawnOptions?: string[];
  /**
   * Keep Dawn's zero-initialisation of workgroup memory (default false: it is turned off with the
   * toggle disable_workgroup_init, since no stage reads workgroup memory before writing it; on
   * SwiftShader the zeroing made the radix sort four times slower).
   */
  zeroInitWorkgroupMemory?: boolean;
  /** Dawn's skip_validation toggle (see GpuContextOptions.skipValidation). */
  skipValidation?: boolean;
  /** Replaces `import('webgpu')` (tests). */
  loadDawn?: () => Promise<DawnModule>;
  /** Replaces the file system probes (tests). */
  search?: IcdSearchEnv;
  platform?: string;
}

export interface NodeAdapter {
  gpu: GPU;
  adapter: GPUAdapter;
  /** 'dawn' (the system's driver) or 'dawn-swiftshader' (the software fallback). */
  source: 'dawn' | 'dawn-swiftshader';
  /** The ICD file the fallback used. */
  icd?: string;
}

/**
 * A Dawn adapter: the system's (hardware) one first, then SwiftShader. Throws GpuUnavailableError
 * with what to install when there is none.
 */
export async function requestNodeAdapter(options: NodeAdapterOptions = {}): Promise<NodeAdapter> {
  const dawn = await (options.loadDawn ?? (() => loadDawn()))();
  // The WebGPU globals (GPUBufferUsage, GPUMapMode...) that code written for browsers uses.
  for (const [k, v] of Object.entries(dawn.globals)) {
    if (!(k in globalThis)) (globalThis as Record<string, unknown>)[k] = v;
  }
  const search = options.search ?? (await nodeSearchEnv());
  const platform = options.platform ?? process.platform;
  const request: GPURequestAdapterOptions = {};
  if (options.powerPreference) request.powerPreference = options.powerPreference;
  const toggles = withToggle(
    withToggle(options.dawnOptions ?? [], options.zeroInitWorkgroupMemory ? null : 'disable_workgroup_init'),
    options.skipValidation ? 'skip_validation' : null,
  );

  if (!options.forceSoftware && mayHaveHardwareAdapter(search, platform)) {
    const gpu = dawn.create(toggles);
    const adapter = await gpu.requestAdapter(request);
    if (adapter) return { gpu, adapter, source: 'dawn' };
  }
  if (options.softwareFallback === false && !options.forceSoftware) {
    throw new GpuUnavailableError(`No WebGPU adapter found (the software fallback is off). ${SOFTWARE_ADAPTER_HINT}`);
  }
  const icd = findSwiftShaderIcd(search);
  if (icd === null) {
    const loader = vulkanLoaderPresent(search) ? '' : ' The Vulkan loader (libvulkan.so.1) is not installed either.';
    throw new GpuUnavailableError(
      `No WebGPU adapter found: no GPU driver answered and no SwiftShader Vulkan driver was found.${loader} ${SOFTWARE_ADAPTER_HINT}`,
    );
  }
  search.env.VK_ICD_FILENAMES = icd;
  search.env.VK_DRIVER_FILES = icd;
  const gpu = dawn.create(toggles);
  const adapter = await gpu.requestAdapter(request);
  if (!adapter) {
    const loader = vulkanLoaderPresent(search) ? '' : ' The Vulkan loader (libvulkan.so.1) is not installed:';
    throw new GpuUnavailableError(`No WebGPU adapter found: Dawn did not accept the SwiftShader driver ${icd}.${loader} ${SOFTWARE_ADAPTER_HINT}`);
  }
  return { gpu, adapter, source: 'dawn-swiftshader', icd };
}
