/*
 * Box2DWeb's b2DebugDraw: the engine's b2Draw drawing on a canvas 2D context.
 *
 * Set it up as in Box2DWeb:
 *   const debugDraw = new b2DebugDraw();
 *   debugDraw.SetSprite(canvas.getContext('2d'));
 *   debugDraw.SetDrawScale(30);           // pixels per world unit
 *   debugDraw.SetFillAlpha(0.3);
 *   debugDraw.SetLineThickness(1);
 *   debugDraw.SetFlags(b2DebugDraw.e_shapeBit | b2DebugDraw.e_jointBit);
 *   world.SetDebugDraw(debugDraw);
 *   ... world.DrawDebugData();            // clears the canvas, then draws the world
 *
 * World coordinates are multiplied by the draw scale and passed to the context as they are, as
 * Box2DWeb draws: y grows downwards on a canvas, so Box2DWeb scenes use a positive gravity y.
 * Colors come from b2World.DrawDebugData (Box2D 2.2.1's palette); outlines are drawn with the
 * alpha of SetAlpha, solid shapes filled with the alpha of SetFillAlpha.
 */

import { b2Color, b2Draw } from '../common/b2Draw';
import type { b2Transform, b2Vec2 } from '../common/b2Math';
import { defineRemovedProperty } from './patch';

/**
 * The parts of CanvasRenderingContext2D the debug draw uses, so any object with these members
 * (a canvas context, a recording stub in tests) can be drawn on.
 */
export interface b2DebugDrawContext {
  readonly canvas?: { readonly width: number; readonly height: number } | null;
  strokeStyle: unknown;
  fillStyle: unknown;
  lineWidth: number;
  beginPath(): void;
  closePath(): void;
  moveTo(x: number, y: number): void;
  lineTo(x: number, y: number): void;
  arc(x: number, y: number, radius: number, startAngle: number, endAngle: number, counterclockwise?: boolean): void;
  stroke(): void;
  fill(): void;
  clearRect(x: number, y: number, width: number, height: number): void;
}

const s_xAxisColor = new b2Color(1.0, 0.0, 0.0);
const s_yAxisColor = new b2Color(0.0, 1.0, 0.0);

/** Debug drawing on a canvas 2D context, with Box2DWeb's setup calls. */
export class b2DebugDraw extends b2Draw {
  m_ctx: b2DebugDrawContext | null = null;
  m_drawScale = 1.0;
  m_lineThickness = 1.0;
  m_alpha = 1.0;
  m_fillAlpha = 1.0;
  m_xformScale = 1.0;

  /** Set the canvas 2D context to draw on (Box2DWeb calls it the sprite). */
  SetSprite(context: b2DebugDrawContext | null): void {
    this.m_ctx = context;
  }

  /** The canvas 2D context drawn on. */
  GetSprite(): b2DebugDrawContext | null {
    return this.m_ctx;
  }

  /** Set the pixels per world unit. */
  SetDrawScale(drawScale: number): void {
    this.m_drawScale = drawScale;
  }

  GetDrawScale(): number {
    return this.m_drawScale;
  }

  /** Set the line width in pixels. */
  SetLineThickness(lineThickness: number): void {
    this.m_lineThickness = lineThickness;
  }

  GetLineThickness(): number {
    return this.m_lineThickness;
  }

  /** Set the alpha of outlines, in [0, 1]. */
  SetAlpha(alpha: number): void {
    this.m_alpha = alpha;
  }

  GetAlpha(): number {
    return this.m_alpha;
  }

  /** Set the alpha of the fill of solid shapes, in [0, 1]. */
  SetFillAlpha(alpha: number): void {
    this.m_fillAlpha = alpha;
  }

  GetFillAlpha(): number {
    return this.m_fillAlpha;
  }

  /** Set the length, in world units, of the axes DrawTransform draws. */
  SetXFormScale(xformScale: number): void {
    this.m_xformScale = xformScale;
  }

  GetXFormScale(): number {
    return this.m_xformScale;
  }

  /**
   * Clear the whole canvas. b2World.DrawDebugData calls it before drawing, as Box2DWeb's did;
   * replace it on the instance to keep what is already drawn.
   */
  Clear(): void {
    const ctx = this.m_ctx;
    if (ctx !== null && ctx.canvas) {
      ctx.clearRect(0, 0, ctx.canvas.width, ctx.canvas.height);
    }
  }

  DrawPolygon(vertices: readonly b2Vec2[], vertexCount: number, color: b2Color): void {
    const ctx = this.Context();
    if (vertexCount === 0) return;
    this.BeginStroke(ctx, color);
    this.TracePolygon(ctx, vertices, vertexCount);
    ctx.stroke();
  }

  DrawSolidPolygon(vertices: readonly b2Vec2[], vertexCount: number, color: b2Color): void {
    const ctx = this.Context();
    if (vertexCount === 0) return;
    this.BeginStroke(ctx, color);
    ctx.fillStyle = rgba(color, this.m_fillAlpha);
    this.TracePolygon(ctx, vertices, vertexCount);
    ctx.fill();
    ctx.stroke();
  }

  DrawCircle(center: b2Vec2, radius: number, color: b2Color): void {
    const ctx = this.Context();
    const scale = this.m_drawScale;
    this.BeginStroke(ctx, color);
    ctx.arc(center.x * scale, center.y * scale, radius * scale, 0, 2 * Math.PI);
    ctx.closePath();
    ctx.stroke();
  }

  DrawSolidCircle(center: b2Vec2, radius: number, axis: b2Vec2, color: b2Color): void {
    const ctx = this.Context();
    const scale = this.m_drawScale;
    const cx = center.x * scale;
    const cy = center.y * scale;
    this.BeginStroke(ctx, color);
    ctx.fillStyle = rgba(color, this.m_fillAlpha);
    ctx.arc(cx, cy, radius * scale, 0, 2 * Math.PI);
    ctx.closePath();
    ctx.fill();
    // The radius along the body's x axis shows the rotation.
    ctx.moveTo(cx, cy);
    ctx.lineTo((center.x + radius * axis.x) * scale, (center.y + radius * axis.y) * scale);
    ctx.stroke();
  }

  DrawSegment(p1: b2Vec2, p2: b2Vec2, color: b2Color): void {
    const ctx = this.Context();
    const scale = this.m_drawScale;
    this.BeginStroke(ctx, color);
    ctx.moveTo(p1.x * scale, p1.y * scale);
    ctx.lineTo(p2.x * scale, p2.y * scale);
    ctx.stroke();
  }

  /** Draw a frame: its x axis in red and its y axis in green, each SetXFormScale long. */
  DrawTransform(xf: b2Transform): void {
    const ctx = this.Context();
    const scale = this.m_drawScale;
    const k = this.m_xformScale;
    const px = xf.p.x;
    const py = xf.p.y;
    const c = xf.q.c;
    const s = xf.q.s;

    this.BeginStroke(ctx, s_xAxisColor);
    ctx.moveTo(px * scale, py * scale);
    ctx.lineTo((px + k * c) * scale, (py + k * s) * scale);
    ctx.stroke();

    this.BeginStroke(ctx, s_yAxisColor);
    ctx.moveTo(px * scale, py * scale);
    ctx.lineTo((px - k * s) * scale, (py + k * c) * scale);
    ctx.stroke();
  }

  private Context(): b2DebugDrawContext {
    if (this.m_ctx === null) {
      throw new Error('b2DebugDraw: no canvas context to draw on; call SetSprite(canvas.getContext("2d")) first');
    }
    return this.m_ctx;
  }

  private BeginStroke(ctx: b2DebugDrawContext, color: b2Color): void {
    ctx.beginPath();
    ctx.lineWidth = this.m_lineThickness;
    ctx.strokeStyle = rgba(color, this.m_alpha);
  }

  private TracePolygon(ctx: b2DebugDrawContext, vertices: readonly b2Vec2[], vertexCount: number): void {
    const scale = this.m_drawScale;
    ctx.moveTo(vertices[0].x * scale, vertices[0].y * scale);
    for (let i = 1; i < vertexCount; ++i) {
      ctx.lineTo(vertices[i].x * scale, vertices[i].y * scale);
    }
    ctx.closePath();
  }
}

/** The CSS color of a b2Color (channels in [0, 1]) with an alpha. */
function rgba(color: b2Color, alpha: number): string {
  return `rgba(${channel(color.r)},${channel(color.g)},${channel(color.b)},${alpha})`;
}

function channel(c: number): number {
  return Math.round(255 * (c < 0.0 ? 0.0 : c > 1.0 ? 1.0 : c));
}

defineRemovedProperty(
  b2DebugDraw,
  'e_controllerBit',
  'b2DebugDraw.e_controllerBit',
  'Controllers were removed with it; draw your own forces with the b2Draw methods.',
);
