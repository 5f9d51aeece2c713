/*
 * Drawing a pane from its transforms: every fixture of the scene's geometry placed by its body's
 * (x, y, cos, sin), batched into one path per colour and a few hundred shapes (one canvas call per
 * shape is slow past 10^4 bodies, and one huge path is slow in software rasterizers). Both panes
 * share one Camera. Colours are the Testbed's: static green, awake pink, asleep grey.
 */

import { GEOMETRY_CIRCLE, TRANSFORM_STRIDE } from './config';
import type { SceneGeometry, SceneView } from './config';

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
}

const STYLES = [
  { fill: 'rgba(64,115,64,1)', stroke: 'rgb(128,230,128)' }, // static: b2Color(0.5, 0.9, 0.5)
  { fill: 'rgba(115,89,89,1)', stroke: 'rgb(230,179,179)' }, // awake: b2Color(0.9, 0.7, 0.7)
  { fill: 'rgba(77,77,77,1)', stroke: 'rgb(153,153,153)' }, // asleep: b2Color(0.6, 0.6, 0.6)
];
/** Shapes per path. */
const CHUNK = 256;
/** Above this many fixtures in view, shapes are filled only (outlines would cover them anyway). */
const OUTLINE_LIMIT = 20000;

export class PaneView {
  readonly canvas: HTMLCanvasElement;
  private readonly ctx: CanvasRenderingContext2D;
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
    const rect = this.canvas.getBoundingClientRect();
    const dpr = window.devicePixelRatio || 1;
    this.width = Math.max(1, rect.width);
    this.height = Math.max(1, rect.height);
    const w = Math.round(this.width * dpr);
    const h = Math.round(this.height * dpr);
    if (this.canvas.width !== w || this.canvas.height !== h) {
      this.canvas.width = w;
      this.canvas.height = h;
    }
  }

  clear(): void {
    const ctx = this.ctx;
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.fillStyle = '#000';
    ctx.fillRect(0, 0, this.canvas.width, this.canvas.height);
  }

  /** Clears and draws every fixture of `geometry` in view at the bodies' transforms. */
  draw(geometry: SceneGeometry, transforms: Float32Array, awake: Uint8Array, camera: Camera): void {
    this.clear();
    const ctx = this.ctx;
    const dpr = this.canvas.width / this.width;
    const s = camera.scale * dpr;
    // World to device pixels: x' = s (x - cx) + W/2, y' = -s (y - cy) + H/2.
    const ox = this.canvas.width / 2 - s * camera.x;
    const oy = this.canvas.height / 2 + s * camera.y;
    const halfW = this.width / 2 / camera.scale;
    const halfH = this.height / 2 / camera.scale;
    const { fixtureBody, fixtureKind, fixtureStart, fixtureCount, points, bodyStatic } = geometry;
    const n = fixtureBody.length;
    const outline = n <= OUTLINE_LIMIT;
    ctx.lineWidth = 1;
    for (let style = 0; style < STYLES.length; ++style) {
      ctx.fillStyle = STYLES[style].fill;
      ctx.strokeStyle = STYLES[style].stroke;
      let inPath = 0;
      ctx.beginPath();
      for (let f = 0; f < n; ++f) {
        const body = fixtureBody[f];
        const mine = bodyStatic[body] === 1 ? 0 : awake[body] === 1 ? 1 : 2;
        if (mine !== style) continue;
        const t = TRANSFORM_STRIDE * body;
        const x = transforms[t];
        const y = transforms[t + 1];
        const c = transforms[t + 2];
        const sn = transforms[t + 3];
        if (!(x === x)) continue; // NaN: no body there
        const at = fixtureStart[f];
        if (fixtureKind[f] === GEOMETRY_CIRCLE) {
          const px = x + c * points[at] - sn * points[at + 1];
          const py = y + sn * points[at] + c * points[at + 1];
          const r = points[at + 2];
          if (Math.abs(px - camera.x) > halfW + r || Math.abs(py - camera.y) > halfH + r) continue;
          const sx = ox + s * px;
          const sy = oy - s * py;
          ctx.moveTo(sx + s * r, sy);
          ctx.arc(sx, sy, s * r, 0, 2 * Math.PI);
          if (outline) {
            // The radius line shows the rotation, as b2Draw::DrawSolidCircle's axis does.
            ctx.moveTo(sx, sy);
            ctx.lineTo(sx + s * r * c, sy - s * r * sn);
          }
        } else {
          const count = fixtureCount[f];
          let minX = Infinity;
          let maxX = -Infinity;
          let minY = Infinity;
          let maxY = -Infinity;
          for (let i = 0; i < count; ++i) {
            const lx = points[at + 2 * i];
            const ly = points[at + 2 * i + 1];
            const px = x + c * lx - sn * ly;
            const py = y + sn * lx + c * ly;
            minX = Math.min(minX, px);
            maxX = Math.max(maxX, px);
            minY = Math.min(minY, py);
            maxY = Math.max(maxY, py);
          }
          if (maxX < camera.x - halfW || minX > camera.x + halfW || maxY < camera.y - halfH || minY > camera.y + halfH) continue;
          for (let i = 0; i < count; ++i) {
            const lx = points[at + 2 * i];
            const ly = points[at + 2 * i + 1];
            const sx = ox + s * (x + c * lx - sn * ly);
            const sy = oy - s * (y + sn * lx + c * ly);
            if (i === 0) ctx.moveTo(sx, sy);
            else ctx.lineTo(sx, sy);
          }
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
