/*
 * GpuRenderer: draws a world stepped by a WebGPUBackend straight from the solver's buffers, with
 * instanced geometry (shaders/render/render.wgsl): no body's position ever comes back to
 * JavaScript to be drawn. A frame is one command encoder submitted to the backend's queue after
 * the steps called so far, so it shows the latest step without waiting for it to finish: the cull
 * pass (src-gpu/render/cull.ts) lists the proxies on screen by the geometry they need, then the
 * render pass draws each list with drawIndirect, so a frame's vertex work follows what is
 * visible, not the world's size.
 *
 * In:  the attached world's mirror (src-gpu/world/world.ts): bodyXf, bodyCell, bodyFlags,
 *      bodyAwake, proxyRef, fixtureShape, shapePool, joints, jointParams; the camera; the
 *      application's body colours (setBodyColour).
 * Out: a compute pass and a render pass into the canvas's current texture (draw) or a given
 *      texture (drawTo): filled circles and polygons and outlines of every shape at least
 *      RENDER_POINT_PIXELS across on screen, one pixel in the outline colour for each smaller
 *      one, joints as lines.
 * Invariants: only reads the world's buffers; shapes outside the view cost no vertex work; bind
 *      groups follow the tables when they grow; a body's colour stays with its slot until set
 *      again.
 */

import type { b2Body } from '../../src/dynamics/b2Body';
import type { WebGPUBackend } from '../backend/backend';
import type { GpuContext } from '../device/device';
import { bufferId } from '../device/device';
import { b2_maxPolygonVertices } from '../../src/common/b2Settings';
import {
  RENDER_CIRCLE_SEGMENTS,
  RENDER_COLOUR_MODE,
  RENDER_DRAW_ARGS_WORDS,
  RENDER_LIST,
  RENDER_LIST_COUNT,
  RENDER_SMALL_POLYGON_VERTICES,
  SHADER_STAGE,
  USAGE,
} from '../device/layout';
import { SHADERS } from '../device/shaders';
import type { GpuWorld } from '../world/world';
import { GpuCull } from './cull';

/** Where the view is centred (metres) and how many pixels a metre covers. */
export interface GpuCamera {
  x: number;
  y: number;
  scale: number;
}

export interface GpuRendererOptions {
  /** The colour target's format (default: the canvas's preferred format, or rgba8unorm). */
  format?: GPUTextureFormat;
  /** The background, RGBA in [0, 1] (default black). */
  background?: readonly [number, number, number, number];
}

/** What the last frame drew. */
export interface GpuFrameStats {
  /** Proxy slots the cull pass examined (a chain contributes one per edge), live or dead. */
  readonly proxies: number;
  /** Joint slots drawn. */
  readonly joints: number;
  /** Host milliseconds spent recording and submitting the frame. */
  readonly recordMs: number;
}

const VIEW_WORDS = 12;
/** A circle's fill: a quad as two triangles. */
const QUAD_VERTICES = 6;
type ListName = keyof typeof RENDER_LIST;
/**
 * How each draw list is drawn: its vertex entry point, its topology, and its vertices per
 * instance: the fan of the largest polygon it holds (or a circle's quad), a line list of its
 * sides (a circle's with its radius line), one point.
 */
const LISTS: Readonly<Record<ListName, { entryPoint: string; topology: GPUPrimitiveTopology; vertices: number }>> = {
  FILL_SMALL: { entryPoint: 'fill_vertex', topology: 'triangle-list', vertices: Math.max(QUAD_VERTICES, 3 * (RENDER_SMALL_POLYGON_VERTICES - 2)) },
  FILL: { entryPoint: 'fill_vertex', topology: 'triangle-list', vertices: 3 * (b2_maxPolygonVertices - 2) },
  OUTLINE_SMALL: { entryPoint: 'outline_vertex', topology: 'line-list', vertices: 2 * RENDER_SMALL_POLYGON_VERTICES },
  OUTLINE: { entryPoint: 'outline_vertex', topology: 'line-list', vertices: 2 * Math.max(RENDER_CIRCLE_SEGMENTS + 1, b2_maxPolygonVertices) },
  POINT: { entryPoint: 'point_vertex', topology: 'point-list', vertices: 1 },
};
/** A joint's three lines. */
const JOINT_VERTICES = 6;

function preferredFormat(): GPUTextureFormat {
  const gpu = (globalThis.navigator as { gpu?: GPU } | undefined)?.gpu;
  return gpu !== undefined ? gpu.getPreferredCanvasFormat() : 'rgba8unorm';
}

export class GpuRenderer {
  readonly backend: WebGPUBackend;
  readonly format: GPUTextureFormat;
  /** Where the view is centred and its scale; change it between frames. */
  readonly camera: GpuCamera = { x: 0, y: 0, scale: 10 };
  /** Colours per body state (b2World::DrawDebugData's) or per body (setBodyColour). */
  colourBy: 'state' | 'body' = 'state';
  drawJoints = true;
  background: readonly [number, number, number, number];
  private readonly canvas: GPUCanvasContext | null;
  private readonly ctx: GpuContext;
  private readonly view: GPUBuffer;
  private readonly viewWords = new ArrayBuffer(VIEW_WORDS * 4);
  private readonly viewI32 = new Int32Array(this.viewWords);
  private readonly viewF32 = new Float32Array(this.viewWords);
  private readonly viewU32 = new Uint32Array(this.viewWords);
  /** The pipeline drawing each list (RENDER_LIST). */
  private readonly lists: GPURenderPipeline[];
  private readonly jointLines: GPURenderPipeline;
  private readonly cull: GpuCull;
  private readonly bodyLayout: GPUBindGroupLayout;
  private readonly shapeLayout: GPUBindGroupLayout;
  private readonly jointLayout: GPUBindGroupLayout;
  private readonly groups = new Map<string, GPUBindGroup>();
  private colours = new Uint32Array(0);
  private colourBuffer: GPUBuffer;
  private coloursDirty = false;
  private stats: GpuFrameStats | null = null;

  /**
   * A renderer of `backend`'s world into `canvas` (configured here for the backend's device), or,
   * given null, into the textures passed to drawTo (Node, offscreen).
   */
  constructor(backend: WebGPUBackend, canvas: GPUCanvasContext | null, options: GpuRendererOptions = {}) {
    this.backend = backend;
    this.ctx = backend.ctx;
    this.canvas = canvas;
    this.format = options.format ?? (canvas !== null ? preferredFormat() : 'rgba8unorm');
    this.background = options.background ?? [0, 0, 0, 1];
    const device = this.ctx.device;
    canvas?.configure({ device, format: this.format, alphaMode: 'opaque' });
    this.view = this.ctx.createBuffer('render.view', VIEW_WORDS * 4, USAGE.UNIFORM | USAGE.COPY_DST);
    this.colourBuffer = this.ctx.createBuffer('render.bodyColour', 16, USAGE.STORAGE | USAGE.COPY_DST);

    const vertex = SHADER_STAGE.VERTEX;
    const storage = (binding: number): GPUBindGroupLayoutEntry => ({ binding, visibility: vertex, buffer: { type: 'read-only-storage' } });
    this.bodyLayout = device.createBindGroupLayout({
      label: 'render.bodies',
      entries: [{ binding: 0, visibility: vertex, buffer: { type: 'uniform' } }, storage(1), storage(2), storage(3)],
    });
    this.shapeLayout = device.createBindGroupLayout({ label: 'render.shapes', entries: [storage(0), storage(1), storage(2), storage(3)] });
    this.jointLayout = device.createBindGroupLayout({ label: 'render.joints', entries: [storage(0), storage(1)] });
    const empty = device.createBindGroupLayout({ label: 'render.none', entries: [] });
    const module = this.ctx.shaderModule('render', SHADERS.render);
    const blend: GPUBlendState = {
      color: { srcFactor: 'src-alpha', dstFactor: 'one-minus-src-alpha', operation: 'add' },
      alpha: { srcFactor: 'one', dstFactor: 'one-minus-src-alpha', operation: 'add' },
    };
    const shapes = device.createPipelineLayout({ bindGroupLayouts: [this.bodyLayout, this.shapeLayout] });
    const pipeline = (label: string, entryPoint: string, topology: GPUPrimitiveTopology, layout: GPUPipelineLayout, constants?: Record<string, number>) =>
      device.createRenderPipeline({
        label: `render.${label}`,
        layout,
        vertex: { module, entryPoint, constants },
        fragment: { module, entryPoint: 'shade', targets: [{ format: this.format, blend }] },
        primitive: { topology },
      });
    this.lists = new Array<GPURenderPipeline>(RENDER_LIST_COUNT);
    const vertices = new Array<number>(RENDER_LIST_COUNT);
    for (const [name, list] of Object.entries(RENDER_LIST) as [ListName, number][]) {
      const { entryPoint, topology } = LISTS[name];
      this.lists[list] = pipeline(`list.${name}`, entryPoint, topology, shapes, { LIST: list });
      vertices[list] = LISTS[name].vertices;
    }
    const joints = device.createPipelineLayout({ bindGroupLayouts: [this.bodyLayout, empty, this.jointLayout] });
    this.jointLines = pipeline('joints', 'joint_vertex', 'line-list', joints);
    this.cull = new GpuCull(this.ctx, vertices);
  }

  /**
   * Colours `body` (0xRRGGBB) when colourBy is 'body'; bodies never coloured keep their state's
   * colour. The colour belongs to the body's slot, which a body created after this one was
   * destroyed reuses.
   */
  setBodyColour(body: b2Body, rgb: number): void {
    if (!Number.isInteger(rgb) || rgb < 0 || rgb > 0xffffff)
      throw new RangeError(`GpuRenderer.setBodyColour: rgb must be an integer 0xRRGGBB in [0, 0xffffff], got ${rgb}`);
    const slot = this.backend.bodySlot(body);
    if (slot < 0) throw new RangeError('GpuRenderer.setBodyColour: the body is not on the GPU yet (it gets a slot at the next world.Step)');
    this.growColours(slot + 1);
    // unpack4x8unorm reads red from the lowest byte.
    this.colours[slot] = ((rgb >> 16) & 0xff) | (rgb & 0xff00) | ((rgb & 0xff) << 16) | 0xff000000;
    this.coloursDirty = true;
  }

  /** What the last frame drew; null before the first. */
  get lastFrame(): GpuFrameStats | null {
    return this.stats;
  }

  /** Draws the world into the canvas's next texture, after the steps called so far. */
  async draw(): Promise<void> {
    if (this.canvas === null) throw new Error('GpuRenderer.draw: this renderer has no canvas; use drawTo(texture)');
    await this.backend.submitted();
    const texture = this.canvas.getCurrentTexture();
    this.record(texture.createView(), texture.width, texture.height);
  }

  /** Draws the world into `texture` (RENDER_ATTACHMENT usage, this renderer's format), after the steps called so far. */
  async drawTo(texture: GPUTexture): Promise<void> {
    if (texture.format !== this.format) throw new TypeError(`GpuRenderer.drawTo: texture's format is ${texture.format}, this renderer draws ${this.format}`);
    await this.backend.submitted();
    this.record(texture.createView(), texture.width, texture.height);
  }

  destroy(): void {
    this.view.destroy();
    this.colourBuffer.destroy();
    this.cull.destroy();
    this.groups.clear();
  }

  private record(target: GPUTextureView, width: number, height: number): void {
    const t0 = performance.now();
    const stepper = this.backend.stepper;
    if (stepper === null) throw new Error('GpuRenderer: the backend is not attached to a world (world.SetBackend(backend) attaches it)');
    const mirror = stepper.mirror;
    const proxies = mirror.proxySlotCount;
    const joints = this.drawJoints ? mirror.jointSlotCount : 0;
    this.cull.reserve(mirror.proxyRef.capacity, mirror.bodySlotCount);
    this.writeView(mirror, width, height);
    if (this.colourBy === 'body') this.uploadColours(mirror.bodySlotCount);

    const encoder = this.ctx.device.createCommandEncoder({ label: 'render' });
    const cull = this.cull;
    if (proxies > 0) cull.record(encoder, this.view, mirror, this.colourBuffer);
    const [r, g, b, a] = this.background;
    const pass = encoder.beginRenderPass({
      label: 'render',
      colorAttachments: [{ view: target, loadOp: 'clear', storeOp: 'store', clearValue: { r, g, b, a } }],
    });
    if (proxies > 0 || joints > 0) {
      pass.setBindGroup(0, this.group(this.bodyLayout, 'bodies', [this.view, mirror.bodyXf.buffer, mirror.bodyCell.buffer, cull.bodyRgba]));
    }
    if (proxies > 0) {
      pass.setBindGroup(1, this.group(this.shapeLayout, 'shapes', [mirror.proxyRef.buffer, mirror.fixtureShape.buffer, mirror.shapePool.buffer, cull.visible]));
      for (let list = 0; list < RENDER_LIST_COUNT; ++list) {
        pass.setPipeline(this.lists[list]);
        pass.drawIndirect(cull.args, 4 * RENDER_DRAW_ARGS_WORDS * list);
      }
    }
    if (joints > 0) {
      pass.setBindGroup(2, this.group(this.jointLayout, 'joints', [mirror.joints.buffer, mirror.jointParams.buffer]));
      pass.setPipeline(this.jointLines);
      pass.draw(JOINT_VERTICES, joints);
    }
    pass.end();
    this.ctx.device.queue.submit([encoder.finish()]);
    this.stats = { proxies, joints, recordMs: performance.now() - t0 };
  }

  /**
   * The view uniform (shaders/shared/renderView.wgsl View): the camera as a cell and an offset in
   * it (as the bodies are stored), the clip and pixel scales, the lists' stride and the slot counts.
   */
  private writeView(mirror: GpuWorld, width: number, height: number): void {
    const { x, y, scale } = this.camera;
    if (!(scale > 0) || !Number.isFinite(scale)) throw new RangeError(`GpuRenderer.camera.scale must be a positive number of pixels per metre, got ${scale}`);
    if (!Number.isFinite(x) || !Number.isFinite(y)) throw new RangeError(`GpuRenderer.camera: x and y must be finite, got (${x}, ${y})`);
    const cellSize = mirror.cellSize;
    const cx = Math.round(x / cellSize);
    const cy = Math.round(y / cellSize);
    const { viewI32: i32, viewF32: f32, viewU32: u32 } = this;
    i32[0] = cx;
    i32[1] = cy;
    f32[2] = x - cx * cellSize;
    f32[3] = y - cy * cellSize;
    f32[4] = (2 * scale) / width;
    f32[5] = (2 * scale) / height;
    f32[6] = cellSize;
    u32[7] = this.colourBy === 'body' ? RENDER_COLOUR_MODE.BODY : RENDER_COLOUR_MODE.STATE;
    f32[8] = scale;
    u32[9] = this.cull.stride;
    u32[10] = mirror.proxySlotCount;
    u32[11] = mirror.bodySlotCount;
    this.ctx.device.queue.writeBuffer(this.view, 0, this.viewWords);
  }

  /** Makes the colour table hold at least `slots` bodies (doubling). */
  private growColours(slots: number): void {
    if (slots <= this.colours.length) return;
    const grown = new Uint32Array(Math.max(64, 2 ** Math.ceil(Math.log2(slots))));
    grown.set(this.colours);
    this.colours = grown;
  }

  /** The colour table on the GPU, covering every body slot the shaders may read. */
  private uploadColours(bodySlots: number): void {
    this.growColours(bodySlots);
    const needed = this.colours.byteLength;
    if (this.colourBuffer.size < needed) {
      this.colourBuffer.destroy();
      this.colourBuffer = this.ctx.createBuffer('render.bodyColour', needed, USAGE.STORAGE | USAGE.COPY_DST);
      this.coloursDirty = true;
    }
    if (this.coloursDirty) {
      this.ctx.device.queue.writeBuffer(this.colourBuffer, 0, this.colours);
      this.coloursDirty = false;
    }
  }

  /** The bind group of `layout` holding these buffers, cached by their identity. */
  private group(layout: GPUBindGroupLayout, label: string, buffers: GPUBuffer[]): GPUBindGroup {
    const key = `${label}:${buffers.map(bufferId).join(',')}`;
    let group = this.groups.get(key);
    if (group === undefined) {
      if (this.groups.size > 64) this.groups.clear();
      group = this.ctx.device.createBindGroup({
        label: `render.${label}`,
        layout,
        entries: buffers.map((buffer, binding) => ({ binding, resource: { buffer } })),
      });
      this.groups.set(key, group);
    }
    return group;
  }
}
