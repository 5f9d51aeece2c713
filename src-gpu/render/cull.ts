/*
 * GpuCull: the compute pass GpuRenderer records before its render pass (shaders/render/cull.wgsl).
 * Drawing every proxy slot with the vertices of the largest shape spent most vertex invocations
 * on degenerate primitives and on bodies off screen or smaller than a pixel; instead this pass
 * lists the visible proxies by the geometry they need, and the render pass draws each list with
 * drawIndirect, so the vertex work follows what is on screen and no count comes back to the host.
 *
 * In:  the attached world's mirror: proxyRef, fixtureShape, shapePool, bodyXf, bodyCell,
 *      bodyFlags, bodyAwake; the renderer's view uniform, written for this frame with
 *      listStride = `stride`; the application's colour table (rgba8 per body slot).
 * Out: `visible`: RENDER_LIST_COUNT lists of proxy slots, list L at [L * stride, (L + 1) * stride);
 *      `args`: a drawIndirect record per list (RENDER_DRAW_ARGS_WORDS words at
 *      RENDER_DRAW_ARGS_WORDS * L), its vertex count the list's and its instance count the list's
 *      length; `bodyRgba`: each body slot's colour, for the render pass recorded after this pass
 *      in the same command encoder.
 * Invariants: reads the world and never writes it; `args` is reset from a template with
 *      queue.writeBuffer before each pass (first vertex and first instance stay 0: a nonzero
 *      first instance needs the optional indirect-first-instance feature); the lists hold the
 *      proxy capacity each, so no proxy count can overflow them.
 */

import type { GpuContext } from '../device/device';
import { Kernel, Recorder } from '../device/kernel';
import { RENDER_DRAW_ARGS_WORDS, RENDER_LIST_COUNT, USAGE, WORKGROUP_SIZE } from '../device/layout';
import type { GpuWorld } from '../world/world';

/** Body slots of the smallest colour buffer. */
const MIN_BODY_SLOTS = 64;

export class GpuCull {
  /** The draw lists, `stride` proxy slots each. */
  visible: GPUBuffer;
  /** One drawIndirect record per list (also COPY_SRC, for tests and tools to read the counts). */
  readonly args: GPUBuffer;
  /** Each body slot's colour (rgba8), written by the pass. */
  bodyRgba: GPUBuffer;
  /** Entries per list: the proxy capacity the lists were sized for. */
  stride = 0;
  private bodySlots = 0;
  private readonly ctx: GpuContext;
  private readonly lists: Kernel;
  private readonly colours: Kernel;
  private readonly template = new Uint32Array(RENDER_LIST_COUNT * RENDER_DRAW_ARGS_WORDS);

  /** `vertices[L]`: the vertices list L's draw gives each of its proxies. */
  constructor(ctx: GpuContext, vertices: readonly number[]) {
    this.ctx = ctx;
    this.lists = new Kernel(ctx, 'cull', 'main');
    this.colours = new Kernel(ctx, 'cull', 'colours');
    for (let list = 0; list < RENDER_LIST_COUNT; ++list) this.template[RENDER_DRAW_ARGS_WORDS * list] = vertices[list];
    this.args = ctx.createBuffer('render.drawArgs', this.template.byteLength, USAGE.STORAGE | USAGE.INDIRECT | USAGE.COPY_DST | USAGE.COPY_SRC);
    this.visible = this.createLists(1);
    this.bodyRgba = this.createColours(MIN_BODY_SLOTS);
  }

  /** Sizes the lists for `proxyCapacity` proxy slots and the colours for `bodySlots` body slots. */
  reserve(proxyCapacity: number, bodySlots: number): void {
    if (proxyCapacity > this.stride) {
      this.visible.destroy();
      this.visible = this.createLists(proxyCapacity);
    }
    if (bodySlots > this.bodySlots) {
      this.bodyRgba.destroy();
      this.bodyRgba = this.createColours(2 ** Math.ceil(Math.log2(bodySlots)));
    }
  }

  /**
   * Records the pass over `mirror`'s body and proxy slots into `encoder`, after resetting the
   * draw arguments on the queue. `view` is the renderer's uniform; `appColours` the
   * application's colour table.
   */
  record(encoder: GPUCommandEncoder, view: GPUBuffer, mirror: GpuWorld, appColours: GPUBuffer): void {
    this.ctx.device.queue.writeBuffer(this.args, 0, this.template);
    const pass = encoder.beginComputePass({ label: 'render.cull' });
    const rec = new Recorder(pass, this.ctx.maxWorkgroupsPerDimension);
    const colours = this.colours.bind({ 0: view, 8: mirror.bodyFlags.buffer, 9: mirror.bodyAwake.buffer, 10: appColours, 11: this.bodyRgba });
    rec.dispatch(this.colours, colours, Math.ceil(mirror.bodySlotCount / WORKGROUP_SIZE));
    const lists = this.lists.bind({
      0: view,
      1: mirror.proxyRef.buffer,
      2: mirror.fixtureShape.buffer,
      3: mirror.shapePool.buffer,
      4: mirror.bodyXf.buffer,
      5: mirror.bodyCell.buffer,
      6: this.visible,
      7: this.args,
    });
    rec.dispatch(this.lists, lists, Math.ceil(mirror.proxySlotCount / WORKGROUP_SIZE));
    pass.end();
  }

  destroy(): void {
    this.visible.destroy();
    this.args.destroy();
    this.bodyRgba.destroy();
  }

  private createLists(stride: number): GPUBuffer {
    this.stride = stride;
    return this.ctx.createBuffer('render.visible', 4 * RENDER_LIST_COUNT * stride, USAGE.STORAGE);
  }

  private createColours(slots: number): GPUBuffer {
    this.bodySlots = slots;
    return this.ctx.createBuffer('render.bodyRgba', 4 * slots, USAGE.STORAGE);
  }
}
