/// <reference types="@webgpu/types" />
/*
 * Devices: getting a WebGPU device in a browser or in Node, its limits, and what happens when it
 * is lost or runs out of memory.
 *
 * - Browsers: navigator.gpu.
 * - Node: the optional peer dependency `webgpu` (Dawn). When Dawn finds no hardware adapter it
 *   falls back to SwiftShader (src-gpu/device/node.ts says how it is found). No adapter at all is a
 *   GpuUnavailableError whose message says what to install.
 * - Limits: the device is requested with the adapter's own maxStorageBufferBindingSize and
 *   maxBufferSize (a million proxies and their pairs then fit in one binding), and with
 *   'timestamp-query' when the adapter has it. maxStorageBuffersPerShaderStage stays at the
 *   default 8, which every browser's adapter gives: every stage fits it, and a kernel that does
 *   not fails here too, not only in a browser.
 * - Loss: `GpuContext.lost` resolves and `onLost` is called once when the device is lost
 *   (device.destroy(), a driver reset, the browser reclaiming it). Afterwards every GPU call of
 *   the backend rejects with GpuDeviceLostError. The b2World itself is untouched, because the
 *   GPU backend only mirrors it: the application goes on stepping it with the JavaScript engine.
 * - Errors: buffer creation runs inside an 'out-of-memory' error scope; a failure surfaces as
 *   GpuOutOfMemoryError from the next `checkErrors()` (every broad-phase update calls it). Other
 *   uncaptured errors (validation) surface the same way as GpuError, instead of a silent no-op.
 */

import { USAGE } from './layout';
import { GpuUnavailableError, isNode, requestNodeAdapter } from './node';
import type { DawnModule, IcdSearchEnv } from './node';

export { GpuUnavailableError } from './node';

/** The device was lost; `reason` is WebGPU's ('destroyed' or 'unknown'). */
export class GpuDeviceLostError extends Error {
  readonly reason: string;
  constructor(reason: string, message: string) {
    super(`The WebGPU device was lost (${reason}): ${message}`);
    this.name = 'GpuDeviceLostError';
    this.reason = reason;
  }
}

/** A buffer could not be allocated. */
export class GpuOutOfMemoryError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'GpuOutOfMemoryError';
  }
}

/** A WebGPU error the backend did not expect (validation, internal). */
export class GpuError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'GpuError';
  }
}

/** A request larger than the device allows (maxBufferSize or maxStorageBufferBindingSize). */
export class GpuCapacityError extends RangeError {
  constructor(message: string) {
    super(message);
    this.name = 'GpuCapacityError';
  }
}

export interface GpuLossInfo {
  reason: string;
  message: string;
}

export interface GpuAdapterSummary {
  vendor: string;
  architecture: string;
  device: string;
  description: string;
  /** A CPU implementation (SwiftShader, WARP, a fallback adapter). */
  software: boolean;
  /** Where the adapter came from. */
  source: 'navigator' | 'dawn' | 'dawn-swiftshader' | 'custom';
  /** The SwiftShader ICD file, for 'dawn-swiftshader'. */
  icd?: string;
}

export interface GpuContextOptions {
  powerPreference?: GPUPowerPreference;
  /** Node: fall back to SwiftShader when no hardware adapter answers (default true). */
  softwareFallback?: boolean;
  /** Node: use SwiftShader even when a hardware adapter exists. */
  forceSoftware?: boolean;
  /** Called once when the device is lost. */
  onLost?: (info: GpuLossInfo) => void;
  /** Use this GPU object instead of navigator.gpu or Dawn. */
  gpu?: GPU;
  /** Node: Dawn toggles passed to webgpu's create(). */
  dawnOptions?: string[];
  /**
   * Node: keep Dawn's zero-initialisation of workgroup memory (default false; see node.ts: the
   * stages never read workgroup memory before writing it, and the zeroing dominates on SwiftShader).
   */
  zeroInitWorkgroupMemory?: boolean;
  /**
   * Node: turn off Dawn's WebGPU validation (its skip_validation toggle; default false). On the
   * H100 it cut the host time of a broad + narrow phase step from about 25 ms of recording to
   * about 1 ms (bench/results/gpu-narrowphase.md): Dawn validated every command, and every
   * indirect dispatch with a dispatch of its own. Invalid use is then undefined behaviour instead
   * of an error, so turn it on only for a pipeline whose use is tested with validation on (ours is,
   * in CI).
   */
  skipValidation?: boolean;
  /** Node: replaces `import('webgpu')` (tests). */
  loadDawn?: () => Promise<DawnModule>;
  /** Node: replaces the file-system probes for drivers (tests). */
  search?: IcdSearchEnv;
  /** Ask for 'timestamp-query' when the adapter has it (default true). */
  timestamps?: boolean;
}

let s_nextBufferId = 1;
const s_bufferIds = new WeakMap<GPUBuffer, number>();

/** A small integer naming a GPUBuffer, for bind-group cache keys. */
export function bufferId(buffer: GPUBuffer): number {
  let id = s_bufferIds.get(buffer);
  if (id === undefined) {
    id = s_nextBufferId++;
    s_bufferIds.set(buffer, id);
  }
  return id;
}

/** A device and what the backend needs to know about it. */
export class GpuContext {
  readonly device: GPUDevice;
  readonly adapter: GPUAdapter;
  readonly adapterInfo: GpuAdapterSummary;
  /** 'timestamp-query' is enabled. */
  readonly timestamps: boolean;
  /** Resolves when the device is lost. */
  readonly lost: Promise<GpuLossInfo>;
  /**
   * Rejects (with GpuDeviceLostError) when the device is lost, never settles otherwise: race a
   * GPU promise against it. One promise for the context's life, so that racing it every step adds
   * nothing (a `lost.then(...)` per read would pile reactions onto a promise that never settles).
   */
  readonly lostRejection: Promise<never>;
  /** Set when the device is lost. */
  lossInfo: GpuLossInfo | null = null;
  /**
   * Workgroups per dispatch dimension the backend uses (the device's
   * maxComputeWorkgroupsPerDimension; tests lower it to exercise 2D dispatches). Read when
   * pipelines are created.
   */
  maxWorkgroupsPerDimension: number;

  private readonly pendingScopes: Promise<GPUError | null>[] = [];
  private firstError: Error | null = null;
  private readonly modules = new Map<string, GPUShaderModule>();
  /** The GPU object (keeps a Dawn instance alive as long as the context). */
  readonly gpu: GPU | null;

  constructor(gpu: GPU | null, adapter: GPUAdapter, device: GPUDevice, adapterInfo: GpuAdapterSummary, onLost?: (info: GpuLossInfo) => void) {
    this.gpu = gpu;
    this.adapter = adapter;
    this.device = device;
    this.adapterInfo = adapterInfo;
    this.timestamps = device.features.has('timestamp-query');
    this.maxWorkgroupsPerDimension = device.limits.maxComputeWorkgroupsPerDimension;
    this.lost = device.lost.then((info) => {
      const loss = { reason: String(info.reason), message: info.message };
      this.lossInfo = loss;
      onLost?.(loss);
      return loss;
    });
    this.lostRejection = this.lost.then((info) => {
      throw new GpuDeviceLostError(info.reason, info.message);
    });
    this.lostRejection.catch(() => undefined);
    device.addEventListener('uncapturederror', (event: Event) => {
      const error = (event as GPUUncapturedErrorEvent).error;
      if (this.firstError === null) {
        this.firstError =
          typeof GPUOutOfMemoryError !== 'undefined' && error instanceof GPUOutOfMemoryError
            ? new GpuOutOfMemoryError(`WebGPU out of memory: ${error.message}`)
            : new GpuError(`WebGPU error: ${error.message}`);
      }
    });
  }

  get isLost(): boolean {
    return this.lossInfo !== null;
  }

  get limits(): GPUSupportedLimits {
    return this.device.limits;
  }

  /** Throws GpuDeviceLostError when the device is lost. */
  assertAlive(): void {
    if (this.lossInfo) throw new GpuDeviceLostError(this.lossInfo.reason, this.lossInfo.message);
  }

  /** A storage/copy buffer of `size` bytes (a multiple of 4), its allocation checked for memory. */
  createBuffer(label: string, size: number, usage: GPUBufferUsageFlags): GPUBuffer {
    this.assertAlive();
    const limits = this.device.limits;
    const bytes = Math.max(16, Math.ceil(size / 16) * 16);
    if (bytes > limits.maxBufferSize) {
      throw new GpuCapacityError(`${label}: ${bytes} bytes is more than this device's maxBufferSize (${limits.maxBufferSize})`);
    }
    if (usage & USAGE.STORAGE && bytes > limits.maxStorageBufferBindingSize) {
      throw new GpuCapacityError(`${label}: ${bytes} bytes is more than this device's maxStorageBufferBindingSize (${limits.maxStorageBufferBindingSize})`);
    }
    this.device.pushErrorScope('out-of-memory');
    const buffer = this.device.createBuffer({ label, size: bytes, usage });
    this.pendingScopes.push(this.device.popErrorScope());
    return buffer;
  }

  /** A compiled shader module, one per source text. */
  shaderModule(label: string, code: string): GPUShaderModule {
    let module = this.modules.get(code);
    if (!module) {
      module = this.device.createShaderModule({ label, code });
      this.modules.set(code, module);
    }
    return module;
  }

  /**
   * Rejects with GpuDeviceLostError, GpuOutOfMemoryError (a buffer allocation failed) or GpuError
   * (an uncaptured WebGPU error) when one happened since the context was made.
   */
  async checkErrors(): Promise<void> {
    this.assertAlive();
    while (this.pendingScopes.length > 0) {
      const scopes = this.pendingScopes.splice(0);
      for (const error of await Promise.all(scopes)) {
        if (error && this.firstError === null) {
          this.firstError = new GpuOutOfMemoryError(`WebGPU out of memory: ${error.message}`);
        }
      }
    }
    if (this.firstError) throw this.firstError;
  }

  /** Destroys the device: `lost` resolves with reason 'destroyed' and onLost is called. */
  destroy(): void {
    this.device.destroy();
  }
}

function summarize(adapter: GPUAdapter, source: GpuAdapterSummary['source'], icd?: string): GpuAdapterSummary {
  const info = adapter.info ?? ({} as GPUAdapterInfo);
  const vendor = info.vendor ?? '';
  const architecture = info.architecture ?? '';
  const device = info.device ?? '';
  const description = info.description ?? '';
  const text = `${vendor} ${architecture} ${device} ${description}`.toLowerCase();
  const software =
    source === 'dawn-swiftshader' ||
    (info as { isFallbackAdapter?: boolean }).isFallbackAdapter === true ||
    /swiftshader|llvmpipe|lavapipe|warp|software/.test(text);
  const summary: GpuAdapterSummary = { vendor, architecture, device, description, software, source };
  if (icd) summary.icd = icd;
  return summary;
}

/**
 * A WebGPU device for the GPU backend: navigator.gpu in a browser, Dawn in Node (SwiftShader when
 * no hardware adapter answers), or options.gpu. Throws GpuUnavailableError saying what to install.
 */
export async function requestGpu(options: GpuContextOptions = {}): Promise<GpuContext> {
  let gpu: GPU | null = options.gpu ?? null;
  let adapter: GPUAdapter | null = null;
  let source: GpuAdapterSummary['source'] = 'custom';
  let icd: string | undefined;
  const request: GPURequestAdapterOptions = {};
  if (options.powerPreference) request.powerPreference = options.powerPreference;

  if (gpu) {
    adapter = await gpu.requestAdapter(request);
    if (!adapter) throw new GpuUnavailableError('No WebGPU adapter: the GPU object given in options.gpu returned none.');
  } else {
    const nav = (globalThis as { navigator?: { gpu?: GPU } }).navigator;
    if (nav?.gpu) {
      gpu = nav.gpu;
      source = 'navigator';
      adapter = await gpu.requestAdapter(request);
      if (!adapter && !isNode()) {
        throw new GpuUnavailableError(
          'No WebGPU adapter: navigator.gpu.requestAdapter() returned none (WebGPU may be disabled or the GPU blocklisted in this browser).',
        );
      }
    }
    if (!adapter) {
      if (!isNode()) {
        throw new GpuUnavailableError(
          'This browser has no WebGPU (navigator.gpu is missing): use a browser with WebGPU enabled (Chrome or Edge 113+, Safari 26+, Firefox 141+ on Windows), or the JavaScript engine.',
        );
      }
      const found = await requestNodeAdapter({
        powerPreference: options.powerPreference,
        softwareFallback: options.softwareFallback,
        forceSoftware: options.forceSoftware,
        dawnOptions: options.dawnOptions,
        zeroInitWorkgroupMemory: options.zeroInitWorkgroupMemory,
        skipValidation: options.skipValidation,
        loadDawn: options.loadDawn,
        search: options.search,
      });
      gpu = found.gpu;
      adapter = found.adapter;
      source = found.source;
      icd = found.icd;
    }
  }

  const limits = adapter.limits;
  const requiredLimits: Record<string, number> = {
    maxStorageBufferBindingSize: limits.maxStorageBufferBindingSize,
    maxBufferSize: limits.maxBufferSize,
    maxComputeWorkgroupStorageSize: limits.maxComputeWorkgroupStorageSize,
  };
  const requiredFeatures: GPUFeatureName[] = [];
  if (options.timestamps !== false && adapter.features.has('timestamp-query')) requiredFeatures.push('timestamp-query');
  const device = await adapter.requestDevice({ requiredLimits, requiredFeatures, label: 'webphysics' });
  return new GpuContext(gpu, adapter, device, summarize(adapter, source, icd), options.onLost);
}
