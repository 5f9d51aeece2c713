/*
 * The accuracy page's chart: one scene and measure of the study, error against milliseconds of
 * stepping per simulated second, both on log scales (decades), one point per method, the Pareto
 * front joined in orange. pointAt() finds the point under the pointer for the tooltip.
 */

import { COLOURS, LOG_FLOOR, decades, formatNumber, pointColour } from '../../bench/accuracy/report.mjs';
import type { AccuracyResult, AccuracyScene } from '../../bench/accuracy/run.mjs';
import { fitCanvas } from '../canvas';

/** A point as drawn, in CSS pixels of the canvas. */
export interface DrawnPoint {
  result: AccuracyResult;
  x: number;
  y: number;
  front: boolean;
}

export class ParetoChart {
  points: DrawnPoint[] = [];
  private readonly ctx: CanvasRenderingContext2D;

  constructor(readonly canvas: HTMLCanvasElement) {
    const ctx = canvas.getContext('2d');
    if (ctx === null) throw new Error('this browser gives no 2D canvas context');
    this.ctx = ctx;
  }

  /** Draws `measure` of `scene`; the GPU's untimed results are listed, not placed. */
  draw(scene: AccuracyScene, measure: string, unit: string): void {
    const { width: w, height: h, dpr } = fitCanvas(this.canvas);
    const ctx = this.ctx;
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.fillStyle = '#161616';
    ctx.fillRect(0, 0, w, h);
    const timed = scene.results.filter((r) => r.msPerSecond !== null && Number.isFinite(r.measures[measure]));
    const untimed = scene.results.filter((r) => r.msPerSecond === null);
    const left = 70;
    const right = w - 190;
    const top = 30;
    const bottom = h - 40;
    const xs = timed.map((r) => r.msPerSecond!);
    const ys = timed.map((r) => Math.max(LOG_FLOOR, r.measures[measure]));
    const [x0, x1] = decades(Math.min(...xs, 1), Math.max(...xs, 1));
    const [y0, y1] = decades(Math.min(...ys, 1), Math.max(...ys, 1e-3));
    const px = (v: number) => left + ((Math.log10(v) - x0) / (x1 - x0)) * (right - left);
    const py = (v: number) => bottom - ((Math.log10(Math.max(LOG_FLOOR, v)) - y0) / (y1 - y0)) * (bottom - top);
    ctx.font = '12px system-ui, sans-serif';
    ctx.strokeStyle = '#333';
    ctx.fillStyle = '#999';
    ctx.lineWidth = 1;
    ctx.textAlign = 'center';
    for (let d = x0; d <= x1; ++d) {
      const x = px(10 ** d);
      ctx.beginPath();
      ctx.moveTo(x, top);
      ctx.lineTo(x, bottom);
      ctx.stroke();
      ctx.fillText(formatNumber(10 ** d), x, bottom + 16);
    }
    ctx.fillText('ms of stepping per simulated second (log)', (left + right) / 2, bottom + 32);
    ctx.textAlign = 'right';
    for (let d = y0; d <= y1; ++d) {
      const y = py(10 ** d);
      ctx.beginPath();
      ctx.moveTo(left, y);
      ctx.lineTo(right, y);
      ctx.stroke();
      ctx.fillText(formatNumber(10 ** d), left - 6, y + 4);
    }
    ctx.textAlign = 'left';
    ctx.fillText(`${measure} (${unit}, log); lower left is better`, left, top - 12);
    const front = scene.fronts[measure] ?? [];
    this.points = timed.map((r) => ({ result: r, x: px(r.msPerSecond!), y: py(r.measures[measure]), front: front.includes(r.key) }));
    const onFront = front.map((key) => this.points.find((p) => p.result.key === key)).filter((p): p is DrawnPoint => p !== undefined);
    ctx.strokeStyle = COLOURS.front;
    ctx.lineWidth = 2;
    ctx.beginPath();
    onFront.forEach((p, i) => (i === 0 ? ctx.moveTo(p.x, p.y) : ctx.lineTo(p.x, p.y)));
    ctx.stroke();
    // Front points first, cheapest first, so that their labels win where labels would overlap (hover names the rest).
    const placed: { x: number; y: number; w: number; h: number }[] = [];
    ctx.font = '10px system-ui, sans-serif';
    const ordered = [...this.points].sort((a, b) => Number(b.front) - Number(a.front) || a.x - b.x);
    for (const p of ordered) {
      ctx.fillStyle = pointColour(p.result, p.front);
      ctx.beginPath();
      ctx.arc(p.x, p.y, p.front ? 5 : 4, 0, 2 * Math.PI);
      ctx.fill();
    }
    for (const p of ordered) {
      const box = { x: p.x + 7, y: p.y - 8, w: ctx.measureText(p.result.key).width, h: 11 };
      if (placed.some((b) => box.x < b.x + b.w && b.x < box.x + box.w && box.y < b.y + b.h && b.y < box.y + box.h)) continue;
      placed.push(box);
      ctx.fillStyle = '#bbb';
      ctx.fillText(p.result.key, p.x + 7, p.y + 3);
    }
    ctx.font = '11px system-ui, sans-serif';
    let noteY = top;
    const note = (text: string, colour: string) => {
      ctx.fillStyle = colour;
      ctx.fillText(text, right + 14, noteY);
      noteY += 15;
    };
    if (ys.some((v) => v === LOG_FLOOR)) note(`0 drawn at ${formatNumber(LOG_FLOOR)}`, '#999');
    if (untimed.length > 0) {
      note('WebGPU (untimed: software):', COLOURS.webgpu);
      for (const r of untimed) note(`${r.key}: ${formatNumber(r.measures[measure])}`, COLOURS.webgpu);
    }
  }

  /** The point within 8 px of (x, y) in CSS pixels, nearest first, or null. */
  pointAt(x: number, y: number): DrawnPoint | null {
    let best: DrawnPoint | null = null;
    let bestD = 64;
    for (const p of this.points) {
      const d = (p.x - x) ** 2 + (p.y - y) ** 2;
      if (d <= bestD) {
        best = p;
        bestD = d;
      }
    }
    return best;
  }
}
