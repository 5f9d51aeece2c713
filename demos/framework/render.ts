/*
 * The Testbed's DebugDraw (Render.h/.cpp): the engine's canvas b2DebugDraw (src/api/b2DebugDraw.ts),
 * extended by composition with what the Testbed draws beyond b2Draw (DrawPoint, DrawString,
 * DrawAABB) and with the Testbed's camera (Main.cpp): a view centre, a zoom, 25 m from the centre
 * to the top of the view at zoom 1, y up. High-DPI aware: the canvas backing store is the element's
 * CSS size times devicePixelRatio, and lines, points and text are sized in CSS pixels.
 */

import { b2AABB, b2Color, b2DebugDraw, b2Vec2 } from '../../src/index';
import { BatchingContext } from './batch';
import { sprintf } from './printf';

/** A rectangle in CSS pixels (where text was drawn this frame). */
export interface Rect {
  x: number;
  y: number;
  w: number;
  h: number;
}

const kTextColor = 'rgb(230,153,153)'; // b2Color(0.9, 0.6, 0.6), as Render.cpp's DrawString
const kBackground = 'rgb(0,0,0)'; // glClear's default clear colour
const kFont = '13px monospace'; // GLUT_BITMAP_8_BY_13

export class TestbedDraw extends b2DebugDraw {
  /** The view (Main.cpp's settings.viewCenter and viewZoom). */
  readonly viewCenter = new b2Vec2(0.0, 20.0);
  viewZoom = 1.0;
  /** CSS size of the canvas and the device pixel ratio, as of the last BeginFrame. */
  width = 640;
  height = 480;
  dpr = 1;
  /** Clear frames to transparent, not to the background: GpuRenderer draws the world underneath. */
  transparent = false;
  /** Where text was drawn since the last BeginFrame, in CSS pixels. */
  readonly textRects: Rect[] = [];
  /** The text drawn since the last BeginFrame. */
  readonly texts: string[] = [];

  private m_canvas: HTMLCanvasElement | null = null;
  private m_context: CanvasRenderingContext2D | null = null;
  private m_batch: BatchingContext | null = null;
  private readonly m_aabbVertices = [new b2Vec2(), new b2Vec2(), new b2Vec2(), new b2Vec2()];

  constructor() {
    super();
    this.SetFillAlpha(0.25); // Render.cpp fills with 0.5 * colour at alpha 0.5: the same on black
    this.SetAlpha(1.0);
    this.SetXFormScale(0.4); // Render.cpp's DrawTransform k_axisScale
  }

  /** Draw on this canvas. */
  SetCanvas(canvas: HTMLCanvasElement): void {
    this.m_canvas = canvas;
    this.m_context = canvas.getContext('2d');
    this.m_batch = this.m_context === null ? null : new BatchingContext(this.m_context);
    this.SetSprite(this.m_batch);
  }

  GetCanvas(): HTMLCanvasElement | null {
    return this.m_canvas;
  }

  /** Main.cpp's Resize: half the view's height in metres is 25 * zoom; this is pixels per metre. */
  PixelsPerMetre(): number {
    return this.height / (50.0 * this.viewZoom);
  }

  /**
   * Start a frame: match the backing store to the element's size times devicePixelRatio, clear
   * it, and set the camera transform (world y up; DrawDebugData's coordinates times the draw
   * scale land in device pixels).
   */
  BeginFrame(): void {
    const canvas = this.m_canvas;
    const ctx = this.m_context;
    if (canvas === null || ctx === null) return;
    const dpr = typeof window !== 'undefined' && window.devicePixelRatio > 0 ? window.devicePixelRatio : 1;
    const w = Math.max(1, canvas.clientWidth || canvas.width);
    const h = Math.max(1, canvas.clientHeight || canvas.height);
    const bw = Math.round(w * dpr);
    const bh = Math.round(h * dpr);
    if (canvas.width !== bw || canvas.height !== bh) {
      canvas.width = bw;
      canvas.height = bh;
    }
    this.width = w;
    this.height = h;
    this.dpr = dpr;
    this.textRects.length = 0;
    this.texts.length = 0;

    this.m_batch?.flush();
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    if (this.transparent) {
      ctx.clearRect(0, 0, bw, bh);
    } else {
      ctx.fillStyle = kBackground;
      ctx.fillRect(0, 0, bw, bh);
    }

    const k = this.PixelsPerMetre() * dpr;
    this.SetDrawScale(k);
    this.SetLineThickness(dpr);
    ctx.setTransform(1, 0, 0, -1, (dpr * w) / 2 - this.viewCenter.x * k, (dpr * h) / 2 + this.viewCenter.y * k);
    ctx.lineJoin = 'round';
  }

  /** Draw what is batched (the engine's debug draw batches its paths by colour). */
  Flush(): void {
    this.m_batch?.flush();
  }

  /** Finish the frame: draw what is still batched. */
  EndFrame(): void {
    this.Flush();
  }

  /** The canvas is cleared once per frame by BeginFrame, not by each DrawDebugData. */
  override Clear(): void {}

  /** Main.cpp's ConvertScreenToWorld, from CSS pixels relative to the canvas. */
  ConvertScreenToWorld(x: number, y: number, out = new b2Vec2()): b2Vec2 {
    const u = x / this.width;
    const v = (this.height - y) / this.height;
    const ratio = this.width / this.height;
    const ex = ratio * 25.0 * this.viewZoom;
    const ey = 25.0 * this.viewZoom;
    const lowerX = this.viewCenter.x - ex;
    const lowerY = this.viewCenter.y - ey;
    const upperX = this.viewCenter.x + ex;
    const upperY = this.viewCenter.y + ey;
    return out.Set((1.0 - u) * lowerX + u * upperX, (1.0 - v) * lowerY + v * upperY);
  }

  /** The inverse: CSS pixels relative to the canvas of a world point. */
  ConvertWorldToScreen(p: { x: number; y: number }): { x: number; y: number } {
    const s = this.PixelsPerMetre();
    return { x: this.width / 2 + (p.x - this.viewCenter.x) * s, y: this.height / 2 - (p.y - this.viewCenter.y) * s };
  }

  /** Render.cpp's DrawPoint: a square of `size` pixels. */
  DrawPoint(p: b2Vec2, size: number, color: b2Color): void {
    const ctx = this.m_context;
    if (ctx === null) return;
    this.Flush();
    const k = this.GetDrawScale();
    const s = size * this.dpr;
    ctx.fillStyle = css(color);
    ctx.fillRect(p.x * k - s / 2, p.y * k - s / 2, s, s);
  }

  /** Render.cpp's DrawString: printf-style text at (x, y) pixels from the top left. */
  DrawString(x: number, y: number, format: string, ...args: unknown[]): void {
    const ctx = this.m_context;
    if (ctx === null) return;
    const text = args.length > 0 ? sprintf(format, ...args) : format;
    this.Flush();
    ctx.save();
    ctx.setTransform(this.dpr, 0, 0, this.dpr, 0, 0);
    ctx.font = kFont;
    ctx.fillStyle = kTextColor;
    ctx.textBaseline = 'alphabetic';
    ctx.fillText(text, x, y);
    this.texts.push(text);
    this.textRects.push({ x, y: y - 13, w: ctx.measureText(text).width + 1, h: 17 });
    ctx.restore();
  }

  /** Render.cpp's DrawAABB. */
  DrawAABB(aabb: Readonly<b2AABB>, color: b2Color): void {
    const vs = this.m_aabbVertices;
    vs[0].Set(aabb.lowerBound.x, aabb.lowerBound.y);
    vs[1].Set(aabb.upperBound.x, aabb.lowerBound.y);
    vs[2].Set(aabb.upperBound.x, aabb.upperBound.y);
    vs[3].Set(aabb.lowerBound.x, aabb.upperBound.y);
    this.DrawPolygon(vs, 4, color);
  }

  /** Pixels of the canvas that differ from the background, outside the text drawn this frame. */
  CountDrawnPixels(): number {
    const canvas = this.m_canvas;
    const ctx = this.m_context;
    if (canvas === null || ctx === null) return 0;
    this.Flush();
    const { data, width, height } = ctx.getImageData(0, 0, canvas.width, canvas.height);
    const dpr = this.dpr;
    const inText = (px: number, py: number) =>
      this.textRects.some((r) => px >= r.x * dpr && px < (r.x + r.w) * dpr && py >= r.y * dpr && py < (r.y + r.h) * dpr);
    let count = 0;
    for (let py = 0; py < height; ++py) {
      for (let px = 0; px < width; ++px) {
        const i = 4 * (py * width + px);
        if (data[i] !== 0 || data[i + 1] !== 0 || data[i + 2] !== 0) {
          if (!inText(px, py)) ++count;
        }
      }
    }
    return count;
  }
}

function css(color: b2Color): string {
  const c = (v: number) => Math.round(255 * (v < 0 ? 0 : v > 1 ? 1 : v));
  return `rgb(${c(color.r)},${c(color.g)},${c(color.b)})`;
}

/** The one debug draw all tests draw with (Box2D 2.3's g_debugDraw). */
export const g_debugDraw = new TestbedDraw();
