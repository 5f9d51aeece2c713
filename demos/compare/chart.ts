/*
 * The live chart of both panes' step times over the run: time on x (the last CHART_SECONDS),
 * milliseconds per step on a log y axis, one series per pane, and a marker with the body count
 * wherever the scene was rebuilt.
 */

import { fitCanvas } from '../canvas';

export interface ChartSeries {
  label: string;
  colour: string;
  /** (seconds since the page started, ms) pairs. */
  points: number[];
}

const CHART_SECONDS = 120;
const MIN_MS = 0.01;
const MAX_MS = 10000;

export class StepChart {
  readonly series: ChartSeries[] = [];
  private readonly marks: { t: number; label: string }[] = [];
  private readonly ctx: CanvasRenderingContext2D;

  constructor(readonly canvas: HTMLCanvasElement) {
    const ctx = canvas.getContext('2d');
    if (ctx === null) throw new Error('this browser gives no 2D canvas context');
    this.ctx = ctx;
  }

  add(series: number, t: number, ms: number): void {
    const points = this.series[series].points;
    points.push(t, ms);
    // Keep what the window shows, and a little more.
    if (points.length > 4096 && points[0] < t - 2 * CHART_SECONDS) points.splice(0, 2048);
  }

  mark(t: number, label: string): void {
    this.marks.push({ t, label });
    while (this.marks.length > 0 && this.marks[0].t < t - 2 * CHART_SECONDS) this.marks.shift();
  }

  draw(now: number): void {
    const { width: w, height: h, dpr } = fitCanvas(this.canvas);
    const ctx = this.ctx;
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.fillStyle = '#161616';
    ctx.fillRect(0, 0, w, h);
    const left = 56;
    const right = w - 12;
    const top = 10;
    const bottom = h - 22;
    const t0 = Math.max(0, now - CHART_SECONDS);
    const t1 = Math.max(t0 + 10, now);
    const xOf = (t: number) => left + ((t - t0) / (t1 - t0)) * (right - left);
    const logMin = Math.log10(MIN_MS);
    const logMax = Math.log10(MAX_MS);
    const yOf = (ms: number) => bottom - ((Math.log10(Math.min(MAX_MS, Math.max(MIN_MS, ms))) - logMin) / (logMax - logMin)) * (bottom - top);
    ctx.font = '11px system-ui, sans-serif';
    ctx.lineWidth = 1;
    ctx.textAlign = 'right';
    ctx.textBaseline = 'middle';
    for (let e = logMin; e <= logMax; ++e) {
      const y = yOf(10 ** e);
      ctx.strokeStyle = '#2c2c2c';
      ctx.beginPath();
      ctx.moveTo(left, y);
      ctx.lineTo(right, y);
      ctx.stroke();
      ctx.fillStyle = '#888';
      ctx.fillText(e < 3 ? `${10 ** e} ms` : `${10 ** (e - 3)} s`, left - 6, y);
    }
    ctx.textAlign = 'center';
    ctx.textBaseline = 'top';
    ctx.fillStyle = '#888';
    for (let s = Math.ceil(t0 / 10) * 10; s <= t1; s += 10) ctx.fillText(`${s} s`, xOf(s), bottom + 5);
    ctx.textAlign = 'left';
    for (const m of this.marks) {
      if (m.t < t0) continue;
      const x = xOf(m.t);
      ctx.strokeStyle = '#555';
      ctx.setLineDash([3, 3]);
      ctx.beginPath();
      ctx.moveTo(x, top);
      ctx.lineTo(x, bottom);
      ctx.stroke();
      ctx.setLineDash([]);
      ctx.fillStyle = '#aaa';
      ctx.fillText(m.label, x + 3, top);
    }
    ctx.lineWidth = 1.5;
    for (const s of this.series) {
      ctx.strokeStyle = s.colour;
      ctx.beginPath();
      let started = false;
      for (let i = 0; i < s.points.length; i += 2) {
        const t = s.points[i];
        if (t < t0) continue;
        const x = xOf(t);
        const y = yOf(s.points[i + 1]);
        if (!started) ctx.moveTo(x, y);
        else ctx.lineTo(x, y);
        started = true;
      }
      ctx.stroke();
    }
    // The legend, top right: the title of the y axis and one entry per series.
    ctx.textBaseline = 'middle';
    ctx.textAlign = 'right';
    let lx = right - 8;
    for (let i = this.series.length - 1; i >= 0; --i) {
      const s = this.series[i];
      ctx.fillStyle = '#ddd';
      ctx.fillText(s.label, lx, top + 6);
      lx -= ctx.measureText(s.label).width + 6;
      ctx.fillStyle = s.colour;
      ctx.fillRect(lx - 14, top + 5, 14, 3);
      lx -= 32;
    }
    ctx.fillStyle = '#888';
    ctx.fillText('step time per pane (log scale):', lx, top + 6);
    ctx.textAlign = 'left';
  }
}
