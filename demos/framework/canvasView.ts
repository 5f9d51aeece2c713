/*
 * What the demo pages use on the JavaScript engine, where there is no WebGPU: a world drawn by the
 * package's canvas b2DebugDraw with y up at a camera, and the body under a point found as the
 * Testbed finds it (GpuPointQuery's answer, on the CPU).
 */

import { b2DebugDraw } from '../../src/api/b2DebugDraw';
import { b2AABB } from '../../src/collision/b2Collision';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2_dynamicBody } from '../../src/dynamics/b2Body';
import type { b2Body } from '../../src/dynamics/b2Body';
import type { b2Fixture } from '../../src/dynamics/b2Fixture';
import type { b2World } from '../../src/dynamics/b2World';
import type { GpuPointHit } from '../../src-gpu/query/pointQuery';
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

  /** Nothing to free: the world stays on the engine (a page closes whichever view it holds). */
  async close(): Promise<void> {}
}

/** The Testbed's MouseDown: a tiny box queried, the first dynamic fixture that holds the point. */
export function bodyAtPoint(world: b2World, x: number, y: number): GpuPointHit | null {
  const p = new b2Vec2(x, y);
  const aabb = new b2AABB();
  aabb.lowerBound.Set(x - 0.001, y - 0.001);
  aabb.upperBound.Set(x + 0.001, y + 0.001);
  let found: b2Body | null = null;
  world.QueryAABB(
    {
      ReportFixture(fixture: b2Fixture): boolean {
        const body = fixture.GetBody();
        if (body.GetType() !== b2_dynamicBody || !fixture.TestPoint(p)) return true;
        found = body;
        return false;
      },
    },
    aabb,
  );
  if (found === null) return null;
  const local = (found as b2Body).GetLocalPoint(p);
  return { body: found, localPoint: { x: local.x, y: local.y } };
}
