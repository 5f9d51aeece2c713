/*
 * A canvas context for b2DebugDraw that batches its paths: b2DebugDraw strokes (and fills) every
 * shape, joint and segment as its own path, which costs one canvas call per primitive; here the
 * path commands are replayed into one Path2D per colour (and line width), and each Path2D is
 * filled or stroked once when the frame is flushed (fills first, then outlines, in the order the
 * colours first appeared), or sooner when it holds `chunk` primitives. The engine's debug draw
 * makes every drawing decision; only the canvas calls are grouped.
 */

import type { b2DebugDrawContext } from '../../src/index';

type Command =
  | { op: 'moveTo' | 'lineTo'; x: number; y: number }
  | { op: 'arc'; x: number; y: number; r: number; a0: number; a1: number; ccw: boolean }
  | { op: 'closePath' };

export class BatchingContext implements b2DebugDrawContext {
  strokeStyle: unknown = '#000';
  fillStyle: unknown = '#000';
  lineWidth = 1;

  private readonly m_commands: Command[] = [];
  private readonly m_fills = new Map<string, { path: Path2D; count: number }>();
  private readonly m_strokes = new Map<string, { path: Path2D; style: string; width: number; count: number }>();
  /**
   * Primitives per Path2D. One canvas call per primitive is slow, and so is one huge path (software
   * rasterizers slow down on paths of thousands of subpaths): groups are drawn in chunks of this
   * many (64 drew Box2D v3's 100 x 100 joint grid about 4 times faster than either extreme).
   */
  static chunk = 64;

  constructor(readonly ctx: CanvasRenderingContext2D) {}

  get canvas(): HTMLCanvasElement {
    return this.ctx.canvas;
  }

  beginPath(): void {
    this.m_commands.length = 0;
  }

  closePath(): void {
    this.m_commands.push({ op: 'closePath' });
  }

  moveTo(x: number, y: number): void {
    this.m_commands.push({ op: 'moveTo', x, y });
  }

  lineTo(x: number, y: number): void {
    this.m_commands.push({ op: 'lineTo', x, y });
  }

  arc(x: number, y: number, radius: number, startAngle: number, endAngle: number, counterclockwise = false): void {
    this.m_commands.push({ op: 'arc', x, y, r: radius, a0: startAngle, a1: endAngle, ccw: counterclockwise });
  }

  stroke(): void {
    const style = String(this.strokeStyle);
    const key = `${style}|${this.lineWidth}`;
    let group = this.m_strokes.get(key);
    if (group === undefined) {
      group = { path: new Path2D(), style, width: this.lineWidth, count: 0 };
      this.m_strokes.set(key, group);
    }
    this.replay(group.path);
    if (++group.count >= BatchingContext.chunk) {
      this.ctx.strokeStyle = group.style;
      this.ctx.lineWidth = group.width;
      this.ctx.stroke(group.path);
      group.path = new Path2D();
      group.count = 0;
    }
  }

  fill(): void {
    const style = String(this.fillStyle);
    let group = this.m_fills.get(style);
    if (group === undefined) {
      group = { path: new Path2D(), count: 0 };
      this.m_fills.set(style, group);
    }
    this.replay(group.path);
    if (++group.count >= BatchingContext.chunk) {
      this.ctx.fillStyle = style;
      this.ctx.fill(group.path);
      group.path = new Path2D();
      group.count = 0;
    }
  }

  clearRect(x: number, y: number, width: number, height: number): void {
    this.flush();
    this.ctx.clearRect(x, y, width, height);
  }

  /** Draw what was batched on the real context (with its current transform), then start over. */
  flush(): void {
    const ctx = this.ctx;
    for (const [style, group] of this.m_fills) {
      ctx.fillStyle = style;
      ctx.fill(group.path);
    }
    for (const group of this.m_strokes.values()) {
      ctx.strokeStyle = group.style;
      ctx.lineWidth = group.width;
      ctx.stroke(group.path);
    }
    this.m_fills.clear();
    this.m_strokes.clear();
  }

  private replay(path: Path2D): void {
    // A path starts where its first command puts it: no line from the previous primitive.
    for (const c of this.m_commands) {
      switch (c.op) {
        case 'moveTo':
          path.moveTo(c.x, c.y);
          break;
        case 'lineTo':
          path.lineTo(c.x, c.y);
          break;
        case 'arc':
          path.moveTo(c.x + c.r * Math.cos(c.a0), c.y + c.r * Math.sin(c.a0));
          path.arc(c.x, c.y, c.r, c.a0, c.a1, c.ccw);
          break;
        case 'closePath':
          path.closePath();
          break;
      }
    }
  }
}
