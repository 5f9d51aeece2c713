/*
 * The Brownian motion page (brownian.html), after the original Web Physics work's "glBrownian": a
 * gas of small frictionless, perfectly elastic discs in a box without gravity, started with
 * Maxwell-Boltzmann velocities, jostles a few large discs. Twice a second the page reads the world
 * back and histograms the speeds of a sample of the gas against the two-dimensional
 * Maxwell-Boltzmann (Rayleigh) distribution at the gas's temperature. On WebGPU the gas has
 * GPU_PARTICLES discs, stepped and drawn on the GPU (GpuWorldView); without WebGPU the JavaScript
 * engine steps JS_PARTICLES, drawn by CanvasWorldView, and the page says so; `?particles=N` asks
 * for fewer.
 * window.webphysicsDemo and window.brownianDemo tell tests and scripts what runs.
 */

import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2BodyDef, b2_dynamicBody } from '../../src/dynamics/b2Body';
import type { b2Body } from '../../src/dynamics/b2Body';
import { b2FixtureDef } from '../../src/dynamics/b2Fixture';
import { b2World } from '../../src/dynamics/b2World';
import type { GpuContext } from '../../src-gpu/device/device';
import { fitCanvas } from '../canvas';
import { rng } from '../../bench/gpu-support';
import { DT, POSITION_ITERATIONS, VELOCITY_ITERATIONS } from '../compare/config';
import { Camera } from '../compare/view';
import { $, fmtCount, fmtMs, showNote } from '../framework/demo';
import { FrameLoop, GpuWorldView, openGpu, openWorldView } from '../framework/gpuView';
import type { WorldView } from '../framework/gpuView';

const GPU_PARTICLES = 100_000;
const JS_PARTICLES = 3_000;
const PARTICLE_RADIUS = 0.06;
/** Area of the box per particle (m^2): a dilute gas. */
const AREA_PER_PARTICLE = 0.16;
/** Standard deviation of each velocity component at the start (m/s): most collisions above the restitution threshold. */
const SIGMA = 6;
const HEAVY = [
  { x: -0.25, y: -0.2, r: 1.6 },
  { x: 0.25, y: 0.25, r: 1.2 },
  { x: 0.2, y: -0.25, r: 2.0 },
];
/** Particles whose speeds make the histogram, and how often (frames). */
const SAMPLE = 5_000;
const SAMPLE_EVERY = 30;
const BINS = 32;

const canvas = $<HTMLCanvasElement>('world');
const histogramCanvas = $<HTMLCanvasElement>('histogram');
const adapterNote = $<HTMLParagraphElement>('adapter');
const statsLine = $<HTMLParagraphElement>('stats');
const showMessage = (text: string) => showNote($<HTMLParagraphElement>('message'), text);
const camera = new Camera();

/** Speeds of a sample of the gas in bins, and the Rayleigh distribution at its temperature. */
interface Histogram {
  /** Upper edge of the last bin (m/s). */
  maxSpeed: number;
  counts: number[];
  /** Expected counts per bin from f(v) = (v / s^2) exp(-v^2 / 2 s^2), s^2 = <v^2> / 2. */
  expected: number[];
  samples: number;
  meanSpeed: number;
  /** The mean speed the distribution predicts: s sqrt(pi / 2). */
  expectedMeanSpeed: number;
}

class Gas {
  readonly world = new b2World(new b2Vec2(0, 0));
  readonly particles: b2Body[] = [];
  readonly heavy: b2Body[] = [];
  readonly halfSide: number;

  constructor(count: number, seed: number) {
    this.world.SetAllowSleeping(false);
    this.halfSide = Math.sqrt(count * AREA_PER_PARTICLE) / 2;
    const h = this.halfSide;
    const walls = this.world.CreateBody(new b2BodyDef());
    const wall = new b2PolygonShape();
    const fd = new b2FixtureDef();
    fd.shape = wall;
    fd.friction = 0;
    fd.restitution = 1;
    for (const [x, y, hx, hy] of [
      [0, -h - 0.5, h + 1, 0.5],
      [0, h + 0.5, h + 1, 0.5],
      [-h - 0.5, 0, 0.5, h + 1],
      [h + 0.5, 0, 0.5, h + 1],
    ]) {
      wall.SetAsBox(hx, hy, new b2Vec2(x, y), 0);
      walls.CreateFixture(fd);
    }
    const bd = new b2BodyDef();
    bd.type = b2_dynamicBody;
    fd.density = 1;
    for (const { x, y, r } of HEAVY) {
      const disc = new b2CircleShape();
      disc.m_radius = r;
      fd.shape = disc;
      bd.position.Set(x * 2 * h, y * 2 * h);
      this.heavy.push(this.world.CreateBody(bd));
      this.heavy[this.heavy.length - 1].CreateFixture(fd);
    }
    const grain = new b2CircleShape();
    grain.m_radius = PARTICLE_RADIUS;
    fd.shape = grain;
    const random = rng(seed);
    // Normal velocity components (a 2D Maxwell-Boltzmann gas), as the sum of twelve uniforms less
    // six: exact arithmetic, so every JavaScript engine starts the same gas (Math.log and Math.cos
    // may round differently).
    const normal = () => {
      let sum = -6;
      for (let k = 0; k < 12; ++k) sum += random();
      return sum;
    };
    const side = Math.ceil(Math.sqrt(count));
    const pitch = (2 * h) / side;
    for (let i = 0; this.particles.length < count; ++i) {
      const x = -h + ((i % side) + 0.5) * pitch;
      const y = -h + (Math.floor(i / side) + 0.5) * pitch;
      if (HEAVY.some((b) => Math.hypot(x - b.x * 2 * h, y - b.y * 2 * h) < b.r + 2 * PARTICLE_RADIUS)) continue;
      bd.position.Set(x, y);
      bd.linearVelocity.Set(SIGMA * normal(), SIGMA * normal());
      const body = this.world.CreateBody(bd);
      body.CreateFixture(fd);
      this.particles.push(body);
    }
  }

  /** The speeds of the first SAMPLE particles, binned, with the distribution they should follow. */
  histogram(): Histogram {
    const n = Math.min(SAMPLE, this.particles.length);
    const speeds = new Float64Array(n);
    let sumSquares = 0;
    let sum = 0;
    for (let i = 0; i < n; ++i) {
      const v = this.particles[i].GetLinearVelocity();
      speeds[i] = Math.hypot(v.x, v.y);
      sumSquares += speeds[i] * speeds[i];
      sum += speeds[i];
    }
    const s2 = sumSquares / n / 2;
    const s = Math.sqrt(s2);
    const maxSpeed = 4 * s;
    const width = maxSpeed / BINS;
    const counts = new Array<number>(BINS).fill(0);
    for (const v of speeds) counts[Math.min(BINS - 1, Math.floor(v / width))]++;
    // The distribution's integral over each bin: exp(-a^2 / 2s^2) - exp(-b^2 / 2s^2).
    const cdf = (v: number) => 1 - Math.exp(-(v * v) / (2 * s2));
    const expected = counts.map((_, k) => n * (cdf((k + 1) * width) - cdf(k * width)));
    return { maxSpeed, counts, expected, samples: n, meanSpeed: sum / n, expectedMeanSpeed: s * Math.sqrt(Math.PI / 2) };
  }
}

/** The histogram as bars, the distribution as a curve. */
function drawHistogram(h: Histogram): void {
  const { width, height, dpr } = fitCanvas(histogramCanvas);
  const ctx = histogramCanvas.getContext('2d');
  if (ctx === null) return;
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  ctx.fillStyle = '#161616';
  ctx.fillRect(0, 0, width, height);
  const left = 40;
  const bottom = height - 18;
  const top = 8;
  const right = width - 10;
  const peak = Math.max(...h.counts, ...h.expected);
  const x = (k: number) => left + ((right - left) * k) / BINS;
  const y = (c: number) => bottom - ((bottom - top) * c) / peak;
  ctx.fillStyle = 'rgb(230,179,179)';
  h.counts.forEach((c, k) => ctx.fillRect(x(k) + 1, y(c), x(k + 1) - x(k) - 2, bottom - y(c)));
  ctx.strokeStyle = 'rgb(128,204,204)';
  ctx.lineWidth = 2;
  ctx.beginPath();
  h.expected.forEach((c, k) => (k === 0 ? ctx.moveTo(x(k + 0.5), y(c)) : ctx.lineTo(x(k + 0.5), y(c))));
  ctx.stroke();
  ctx.fillStyle = '#aaa';
  ctx.font = '11px system-ui, sans-serif';
  ctx.textBaseline = 'top';
  for (let v = 0; v <= h.maxSpeed; v += Math.max(1, Math.round(h.maxSpeed / 8))) ctx.fillText(`${v} m/s`, x((v / h.maxSpeed) * BINS) - 8, bottom + 4);
  ctx.textAlign = 'right';
  ctx.fillText(`speeds of ${fmtCount(h.samples)} discs (bars), Maxwell-Boltzmann in 2D (curve)`, right, top);
}

let gpuContext: GpuContext | null = null;
let gas: Gas | null = null;
let view: WorldView | null = null;
let steps = 0;
let histogram: Histogram | null = null;
let heavyStart: { x: number; y: number }[] = [];
let heavyMoved = 0;
let fitPending = true;

async function sample(current: Gas): Promise<void> {
  if (view instanceof GpuWorldView) await current.world.Synchronize();
  histogram = current.histogram();
  heavyMoved = Math.max(...current.heavy.map((b, i) => Math.hypot(b.GetPosition().x - heavyStart[i].x, b.GetPosition().y - heavyStart[i].y)));
  drawHistogram(histogram);
}

const loop = new FrameLoop(
  () => {
    const current = gas;
    if (current === null) return null;
    if (fitPending) {
      // Framed at the first frame, when the page's layout (the histogram's canvas) has settled.
      const rect = canvas.getBoundingClientRect();
      const h = current.halfSide + 1;
      camera.fit({ x: 0, y: 0, halfWidth: h, halfHeight: h }, rect.width, rect.height);
      fitPending = false;
    }
    const step = () => {
      current.world.Step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
      steps++;
    };
    const frame = view !== null ? view.frame(step, camera) : null;
    if (frame === null) return null;
    return frame.then(() => (steps % SAMPLE_EVERY === 1 ? sample(current) : undefined));
  },
  (now) => publish(now),
  showMessage,
);

/** `?particles=N` (100 up to the backend's maximum), else the maximum; a bad value is named. */
function particleCount(): number {
  const most = gpuContext !== null ? GPU_PARTICLES : JS_PARTICLES;
  const asked = new URLSearchParams(location.search).get('particles');
  if (asked === null) return most;
  const n = Number(asked);
  if (Number.isInteger(n) && n >= 100 && n <= most) return n;
  showMessage(`URL: particles must be an integer from 100 to ${most} here (got "${asked}"); ${most} are used.`);
  return most;
}

async function restart(): Promise<void> {
  gas = null;
  await loop.idle();
  await view?.close();
  view = null;
  const next = new Gas(particleCount(), 1);
  view = await openWorldView(next.world, gpuContext, canvas);
  fitPending = true;
  heavyStart = next.heavy.map((b) => ({ x: b.GetPosition().x, y: b.GetPosition().y }));
  heavyMoved = 0;
  histogram = null;
  steps = 0;
  loop.reset();
  gas = next;
}

camera.zoomOnWheel(canvas);
$<HTMLButtonElement>('restart').addEventListener('click', () => void restart());

// ---- What the page publishes ----

interface BrownianDemo {
  ready: boolean;
  backend: 'js' | 'webgpu' | null;
  particles: number;
  steps: number;
  /** The last histogram of the gas's speeds, null before the first sample. */
  histogram: Histogram | null;
  /** The largest distance a large disc has moved from its start (m), at the last sample. */
  heavyMoved: number;
}

declare global {
  interface Window {
    brownianDemo: BrownianDemo;
  }
}

window.webphysicsDemo = { ready: false, panes: [] };
window.brownianDemo = { ready: false, backend: null, particles: 0, steps: 0, histogram: null, heavyMoved: 0 };

function publish(now: number): void {
  if (gas === null) return;
  const backend = view instanceof GpuWorldView ? 'webgpu' : 'js';
  const workMs = loop.workTimes.median(now);
  Object.assign(window.brownianDemo, { ready: loop.frames > 0, backend, particles: gas.particles.length, steps, histogram, heavyMoved });
  window.webphysicsDemo.panes = [
    { backend, adapter: backend === 'webgpu' ? (adapterNote.dataset.adapter ?? null) : null, bodies: gas.world.GetBodyCount(), steps, stepMs: workMs },
  ];
  window.webphysicsDemo.ready = loop.frames > 0;
  statsLine.textContent =
    `${backend === 'webgpu' ? 'WebGPU: stepped and drawn on the GPU' : 'JavaScript engine, drawn on a 2D canvas'} · ` +
    `${fmtCount(gas.particles.length)} discs of gas, ${gas.heavy.length} large · step ${fmtCount(steps)} · ` +
    `frame ${fmtMs(loop.frameTimes.median(now))} ms · step + draw ${fmtMs(workMs)} ms` +
    (histogram === null
      ? ''
      : ` · mean speed ${histogram.meanSpeed.toFixed(2)} m/s (Maxwell-Boltzmann: ${histogram.expectedMeanSpeed.toFixed(2)}) · large discs moved up to ${heavyMoved.toFixed(2)} m`);
}

// ---- Start ----

async function start(): Promise<void> {
  gpuContext = await openGpu(
    adapterNote,
    `Up to ${fmtCount(GPU_PARTICLES)} discs of gas, stepped and drawn on the GPU.`,
    `the JavaScript engine steps up to ${fmtCount(JS_PARTICLES)} discs of gas, drawn on a 2D canvas.`,
  );
  await restart();
  loop.start();
}

void start();
