/*
 * Drawing a pane from its transforms: every fixture of the scene's geometry placed by its body's
 * (x, y, cos, sin), batched into one path per colour and a few hundred shapes (one canvas call per
 * shape is slow past 10^4 bodies, and one huge path is slow in software rasterizers); in large
 * scenes, shapes a few pixels across are written into the pixels directly. Both panes share one
 * Camera. Colours are the Testbed's: static green, awake pink, asleep grey.
 */

import { GEOMETRY_CIRCLE, TRANSFORM_STRIDE } from './config';
import type { SceneGeometry, SceneView } from './config';
import { fitCanvas } from '../canvas';
import { b2Vec2 } from '../../src/common/b2Math';

/** The view shared by both panes: a centre in metres and a scale in CSS pixels per metre. */
export class Camera {
  x = 0;
  y = 0;
  scale = 10;

  /** Frames `view` in a canvas of `width` x `height` CSS pixels. */
  fit(view: SceneView, width: number, height: number): void {
    this.x = view.x;
    this.y = view.y;
    this.scale = Math.min(width / (2 * view.halfWidth), height / (2 * view.halfHeight));
  }

  /** Zooms by `factor` about the CSS pixel (px, py) of a canvas of `width` x `height`. */
  zoomAt(factor: number, px: number, py: number, width: number, height: number): void {
    const wx = this.x + (px - width / 2) / this.scale;
    const wy = this.y - (py - height / 2) / this.scale;
    this.scale *= factor;
    this.x = wx - (px - width / 2) / this.scale;
    this.y = wy + (py - height / 2) / this.scale;
  }

  /** Moves the view by a drag of (dx, dy) CSS pixels. */
  pan(dx: number, dy: number): void {
    this.x -= dx / this.scale;
    this.y += dy / this.scale;
  }

  /** The world point under a pointer event's page point (clientX, clientY) in `canvas`. */
  toWorld(canvas: HTMLCanvasElement, event: { clientX: number; clientY: number }): b2Vec2 {
    const rect = canvas.getBoundingClientRect();
    return new b2Vec2(this.x + (event.clientX - rect.left - rect.width / 2) / this.scale, this.y - (event.clientY - rect.top - rect.height / 2) / this.scale);
  }

  /** The page point of a world point in `canvas`. */
  toClient(canvas: HTMLCanvasElement, x: number, y: number): { x: number; y: number } {
    const rect = canvas.getBoundingClientRect();
    return { x: rect.left + rect.width / 2 + (x - this.x) * this.scale, y: rect.top + rect.height / 2 - (y - this.y) * this.scale };
  }

  /** Zooms by 1.1 a wheel notch about the pointer in `canvas`, then calls `changed`. */
  zoomOnWheel(canvas: HTMLCanvasElement, changed: () => void = () => undefined): void {
    canvas.addEventListener(
      'wheel',
      (event) => {
        event.preventDefault();
        const rect = canvas.getBoundingClientRect();
        this.zoomAt(event.deltaY < 0 ? 1.1 : 1 / 1.1, event.clientX - rect.left, event.clientY - rect.top, rect.width, rect.height);
        changed();
      },
      { passive: false },
    );
  }
}

const STYLES = [
  { fill: 'rgba(64,115,64,1)', stroke: 'rgb(128,230,128)', splat: [128, 230, 128] }, // static: b2Color(0.5, 0.9, 0.5)
  { fill: 'rgba(115,89,89,1)', stroke: 'rgb(230,179,179)', splat: [230, 179, 179] }, // awake: b2Color(0.9, 0.7, 0.7)
  { fill: 'rgba(77,77,77,1)', stroke: 'rgb(153,153,153)', splat: [153, 153, 153] }, // asleep: b2Color(0.6, 0.6, 0.6)
];
/** Shapes per path. */
const CHUNK = 256;
/** Above this many fixtures, shapes are filled only (outlines would cover them anyway). */
const OUTLINE_LIMIT = 20000;
/**
 * Above this many fixtures, shapes smaller than SPLAT_PIXELS on screen are written straight into
 * the pixels as their bounding squares: 10^5 tiny paths take a software canvas most of a second,
 * and the page must stay responsive.
 */
const SPLAT_LIMIT = 5000;
const SPLAT_PIXELS = 4;

export class PaneView {
  readonly canvas: HTMLCanvasElement;
  private readonly ctx: CanvasRenderingContext2D;
  private image: ImageData | null = null;
  /** A polygon's vertices on screen (b2_maxPolygonVertices x, y pairs). */
  private readonly screen = new Float64Array(16);
  width = 0;
  height = 0;

  constructor(canvas: HTMLCanvasElement) {
    this.canvas = canvas;
    const ctx = canvas.getContext('2d');
    if (ctx === null) throw new Error('this browser gives no 2D canvas context');
    this.ctx = ctx;
  }

  /** Matches the backing store to the element's CSS size and the device pixel ratio. */
  resize(): void {
    const { width, height } = fitCanvas(this.canvas);
    this.width = width;
    this.height = height;
  }

  clear(): void {
    const ctx = this.ctx;
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.fillStyle = '#000';
    ctx.fillRect(0, 0, this.canvas.width, this.canvas.height);
  }

  /** Clears and draws every fixture of `geometry` in view at the bodies' transforms. */
  draw(geometry: SceneGeometry, transforms: Float32Array, awake: Uint8Array, camera: Camera): void {
    const ctx = this.ctx;
    const W = this.canvas.width;
    const H = this.canvas.height;
    const s = camera.scale * (W / this.width);
    // World to device pixels: x' = s x + ox, y' = oy - s y.
    const ox = W / 2 - s * camera.x;
    const oy = H / 2 + s * camera.y;
    const { fixtureBody, fixtureKind, fixtureStart, fixtureCount, points, bodyStatic } = geometry;
    const n = fixtureBody.length;
    const outline = n <= OUTLINE_LIMIT;
    const splat = n > SPLAT_LIMIT;
    let pixels: Uint8ClampedArray | null = null;
    if (splat) {
      if (this.image === null || this.image.width !== W || this.image.height !== H) this.image = ctx.createImageData(W, H);
      pixels = this.image.data;
      new Uint32Array(pixels.buffer).fill(0);
    }
    // The screen box of fixture f, in device pixels: [x0, y0, x1, y1]; a polygon's vertices on
    // screen in `screen` (x, y pairs), for its path.
    const box = [0, 0, 0, 0];
    const screen = this.screen;
    const screenBox = (f: number, x: number, y: number, c: number, sn: number): void => {
      const at = fixtureStart[f];
      if (fixtureKind[f] === GEOMETRY_CIRCLE) {
        const px = ox + s * (x + c * points[at] - sn * points[at + 1]);
        const py = oy - s * (y + sn * points[at] + c * points[at + 1]);
        const r = s * points[at + 2];
        box[0] = px - r;
        box[1] = py - r;
        box[2] = px + r;
        box[3] = py + r;
        return;
      }
      box[0] = box[1] = Infinity;
      box[2] = box[3] = -Infinity;
      for (let i = 0; i < fixtureCount[f]; ++i) {
        const lx = points[at + 2 * i];
        const ly = points[at + 2 * i + 1];
        const px = ox + s * (x + c * lx - sn * ly);
        const py = oy - s * (y + sn * lx + c * ly);
        screen[2 * i] = px;
        screen[2 * i + 1] = py;
        box[0] = Math.min(box[0], px);
        box[1] = Math.min(box[1], py);
        box[2] = Math.max(box[2], px);
        box[3] = Math.max(box[3], py);
      }
    };
    const small = () => box[2] - box[0] < SPLAT_PIXELS && box[3] - box[1] < SPLAT_PIXELS;
    const styleOf = (body: number) => (bodyStatic[body] === 1 ? 0 : awake[body] === 1 ? 1 : 2);

    if (pixels !== null) {
      for (let f = 0; f < n; ++f) {
        const body = fixtureBody[f];
        const t = TRANSFORM_STRIDE * body;
        if (!(transforms[t] === transforms[t])) continue; // NaN: no body there
        screenBox(f, transforms[t], transforms[t + 1], transforms[t + 2], transforms[t + 3]);
        if (!small() || box[2] < 0 || box[0] >= W || box[3] < 0 || box[1] >= H) continue;
        const [r, g, b] = STYLES[styleOf(body)].splat;
        const x0 = Math.max(0, Math.floor(box[0]));
        const x1 = Math.min(W - 1, Math.max(x0, Math.ceil(box[2]) - 1));
        const y0 = Math.max(0, Math.floor(box[1]));
        const y1 = Math.min(H - 1, Math.max(y0, Math.ceil(box[3]) - 1));
        for (let py = y0; py <= y1; ++py) {
          for (let px = x0; px <= x1; ++px) {
            const k = 4 * (py * W + px);
            pixels[k] = r;
            pixels[k + 1] = g;
            pixels[k + 2] = b;
            pixels[k + 3] = 255;
          }
        }
      }
      // Transparent pixels are the black background once on screen (putImageData writes them as they are).
      for (let k = 3; k < pixels.length; k += 4) if (pixels[k] === 0) pixels[k] = 255;
      ctx.putImageData(this.image!, 0, 0);
    } else {
      this.clear();
    }

    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.lineWidth = 1;
    for (let style = 0; style < STYLES.length; ++style) {
      ctx.fillStyle = STYLES[style].fill;
      ctx.strokeStyle = STYLES[style].stroke;
      let inPath = 0;
      ctx.beginPath();
      for (let f = 0; f < n; ++f) {
        const body = fixtureBody[f];
        if (styleOf(body) !== style) continue;
        const t = TRANSFORM_STRIDE * body;
        const x = transforms[t];
        const y = transforms[t + 1];
        const c = transforms[t + 2];
        const sn = transforms[t + 3];
        if (!(x === x)) continue;
        screenBox(f, x, y, c, sn);
        if (box[2] < 0 || box[0] >= W || box[3] < 0 || box[1] >= H) continue;
        if (pixels !== null && small()) continue;
        if (fixtureKind[f] === GEOMETRY_CIRCLE) {
          const sx = 0.5 * (box[0] + box[2]);
          const sy = 0.5 * (box[1] + box[3]);
          const r = 0.5 * (box[2] - box[0]);
          ctx.moveTo(sx + r, sy);
          ctx.arc(sx, sy, r, 0, 2 * Math.PI);
          if (outline) {
            // The radius line shows the rotation, as b2Draw::DrawSolidCircle's axis does.
            ctx.moveTo(sx, sy);
            ctx.lineTo(sx + r * c, sy - r * sn);
          }
        } else {
          ctx.moveTo(screen[0], screen[1]);
          for (let i = 1; i < fixtureCount[f]; ++i) ctx.lineTo(screen[2 * i], screen[2 * i + 1]);
          ctx.closePath();
        }
        if (++inPath === CHUNK) {
          ctx.fill();
          if (outline) ctx.stroke();
          ctx.beginPath();
          inPath = 0;
        }
      }
      if (inPath > 0) {
        ctx.fill();
        if (outline) ctx.stroke();
      }
    }
  }

  /** Clears and writes a message in the middle of the pane. */
  message(text: string): void {
    this.clear();
    const ctx = this.ctx;
    const dpr = this.canvas.width / this.width;
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.fillStyle = '#ccc';
    ctx.font = '14px system-ui, sans-serif';
    ctx.textAlign = 'center';
    const words = text.split(' ');
    const lines: string[] = [];
    let line = '';
    for (const word of words) {
      const next = line === '' ? word : `${line} ${word}`;
      if (ctx.measureText(next).width > this.width - 40 && line !== '') {
        lines.push(line);
        line = word;
      } else {
        line = next;
      }
    }
    lines.push(line);
    lines.forEach((l, i) => ctx.fillText(l, this.width / 2, this.height / 2 + (i - (lines.length - 1) / 2) * 20));
    ctx.textAlign = 'start';
  }
}
