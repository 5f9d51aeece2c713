/*
 * A world drawn by the package's canvas b2DebugDraw with y up at a camera: what the demo pages
 * draw with on the JavaScript engine, where there is no WebGPU.
 */

import { b2DebugDraw } from '../../src/api/b2DebugDraw';
import type { b2World } from '../../src/dynamics/b2World';
import { fitCanvas } from '../canvas';
import type { ViewCamera } from './gpuView';

export class CanvasWorldView {
  private readonly ctx: CanvasRenderingContext2D;
  private readonly draw = new b2DebugDraw();

  constructor(
    private readonly world: b2World,
    private readonly canvas: HTMLCanvasElement,
  ) {
    const ctx = canvas.getContext('2d');
    if (ctx === null) throw new Error('this browser gives no 2D canvas context');
    this.ctx = ctx;
    this.draw.SetSprite(ctx);
    this.draw.SetFlags(b2DebugDraw.e_shapeBit);
    // The view clears the canvas itself, under the identity transform.
    this.draw.Clear = () => undefined;
    world.SetDebugDraw(this.draw);
  }

  /** Runs `step` (the page's world.Step calls) and draws at `camera`. */
  async frame(step: () => void, camera: ViewCamera): Promise<void> {
    step();
    const { width, height, dpr } = fitCanvas(this.canvas);
    const ctx = this.ctx;
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.fillStyle = '#000';
    ctx.fillRect(0, 0, this.canvas.width, this.canvas.height);
    const s = camera.scale * dpr;
    ctx.setTransform(s, 0, 0, -s, (width / 2) * dpr - camera.x * s, (height / 2) * dpr + camera.y * s);
    this.draw.SetLineThickness(1 / s);
    this.world.DrawDebugData();
  }
}
