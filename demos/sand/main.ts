/*
 * The sand page (sand.html), after the original Web Physics work's "Magic Sands": grains (circles)
 * pour from a spout into containers the user draws with the pointer (each stroke a static body of
 * edges). Resting grains fall asleep, so a settled pile costs almost nothing. On WebGPU the grains
 * are stepped and drawn on the GPU (GpuWorldView), up to GPU_GRAINS; without WebGPU the JavaScript
 * engine pours up to JS_GRAINS, drawn by the package's canvas b2DebugDraw (CanvasWorldView), and
 * the page says so.
 * window.webphysicsDemo and window.sandDemo tell tests and scripts what runs.
 */

import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2EdgeShape } from '../../src/collision/shapes/b2EdgeShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2BodyDef, b2_dynamicBody } from '../../src/dynamics/b2Body';
import type { b2Body } from '../../src/dynamics/b2Body';
import { b2FixtureDef } from '../../src/dynamics/b2Fixture';
import { b2World } from '../../src/dynamics/b2World';
import type { GpuContext } from '../../src-gpu/device/device';
import { Camera } from '../compare/view';
import { DT, POSITION_ITERATIONS, VELOCITY_ITERATIONS } from '../compare/config';
import { $, fmtCount, fmtMs, showNote } from '../framework/demo';
import { FrameLoop, GpuWorldView, openGpu, openWorldView } from '../framework/gpuView';
import type { WorldView } from '../framework/gpuView';

const GPU_GRAINS = 200_000;
const JS_GRAINS = 5_000;
/** Grains the spout lets out per step: a row across its mouth. */
const GPU_POUR = 40;
const JS_POUR = 4;
const GRAIN_RADIUS = 0.1;
const SPOUT = { x: 0, y: 40 };
const SPOUT_SPEED = 15;
/** A stroke's points closer than this are merged: segments at least this long. */
const MIN_SEGMENT = 0.4;

const canvas = $<HTMLCanvasElement>('world');
const adapterNote = $<HTMLParagraphElement>('adapter');
const messageNote = $<HTMLParagraphElement>('message');
const statsLine = $<HTMLParagraphElement>('stats');
const pourButton = $<HTMLButtonElement>('pour');
const camera = new Camera();
const showMessage = (text: string) => showNote(messageNote, text);

/** The world: a floor, a first container under the spout, the grains, the containers drawn. */
class Sandbox {
  readonly world = new b2World(new b2Vec2(0, -10));
  readonly containers: b2Body[] = [];
  grains = 0;
  private readonly grainDef = new b2BodyDef();
  private readonly grainFixture = new b2FixtureDef();
  private readonly edge = new b2EdgeShape();
  private seed = 1;

  constructor(
    readonly maxGrains: number,
    private readonly pourRate: number,
  ) {
    this.world.SetAllowSleeping(true);
    const floor = this.world.CreateBody(new b2BodyDef());
    const slab = new b2PolygonShape();
    slab.SetAsBox(80, 1, new b2Vec2(0, -1), 0);
    floor.CreateFixture(slab, 0);
    this.container([new b2Vec2(-8, 22), new b2Vec2(-6, 12), new b2Vec2(6, 12), new b2Vec2(8, 22)]);
    this.grainDef.type = b2_dynamicBody;
    const grain = new b2CircleShape();
    grain.m_radius = GRAIN_RADIUS;
    this.grainFixture.shape = grain;
    this.grainFixture.density = 1;
    this.grainFixture.friction = 0.6;
  }

  /** A static body of edges along `points` (a stroke); null for fewer than two points. */
  container(points: readonly b2Vec2[]): b2Body | null {
    if (points.length < 2) return null;
    const body = this.world.CreateBody(new b2BodyDef());
    for (let i = 1; i < points.length; ++i) {
      this.edge.Set(points[i - 1], points[i]);
      body.CreateFixture(this.edge, 0);
    }
    this.containers.push(body);
    return body;
  }

  clearContainers(): void {
    // The first container stays: it catches the sand while nothing else is drawn.
    for (const body of this.containers.splice(1)) this.world.DestroyBody(body);
  }

  /** One row of grains at the spout's mouth, moving down at SPOUT_SPEED, while there is room for them. */
  pour(): void {
    const n = Math.min(this.pourRate, this.maxGrains - this.grains);
    for (let i = 0; i < n; ++i) {
      this.seed = (Math.imul(this.seed, 1664525) + 1013904223) >>> 0;
      const jitter = (this.seed / 4294967296 - 0.5) * 0.05;
      this.grainDef.position.Set(SPOUT.x + (i - (n - 1) / 2) * 2.1 * GRAIN_RADIUS + jitter, SPOUT.y);
      // Fast enough to leave a grain's diameter between this row and the last one in a step.
      this.grainDef.linearVelocity.Set(0, -SPOUT_SPEED);
      this.world.CreateBody(this.grainDef).CreateFixture(this.grainFixture);
    }
    this.grains += n;
  }
}

let gpuContext: GpuContext | null = null;
let sandbox: Sandbox | null = null;
let view: WorldView | null = null;
let pouring = true;
let steps = 0;
let stroke: b2Vec2[] | null = null;

const loop = new FrameLoop(
  () => {
    const box = sandbox;
    if (box === null) return null;
    const step = () => {
      if (pouring) box.pour();
      box.world.Step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
      steps++;
    };
    return view !== null ? view.frame(step, camera) : null;
  },
  (now) => publish(now),
  showMessage,
);

async function restart(): Promise<void> {
  sandbox = null;
  await loop.idle();
  await view?.close();
  view = null;
  const box = new Sandbox(gpuContext !== null ? GPU_GRAINS : JS_GRAINS, gpuContext !== null ? GPU_POUR : JS_POUR);
  view = await openWorldView(box.world, gpuContext, canvas);
  const rect = canvas.getBoundingClientRect();
  camera.fit({ x: 0, y: 20, halfWidth: 30, halfHeight: 24 }, rect.width, rect.height);
  steps = 0;
  loop.reset();
  sandbox = box;
}

// ---- Pointer: a stroke draws a container; the wheel zooms ----

canvas.addEventListener('pointerdown', (event) => {
  canvas.setPointerCapture(event.pointerId);
  stroke = [camera.toWorld(canvas, event)];
  event.preventDefault();
});

canvas.addEventListener('pointermove', (event) => {
  if (stroke === null) return;
  const p = camera.toWorld(canvas, event);
  const last = stroke[stroke.length - 1];
  if (Math.hypot(p.x - last.x, p.y - last.y) >= MIN_SEGMENT) stroke.push(p);
});

canvas.addEventListener('pointerup', () => {
  if (stroke !== null && sandbox !== null) {
    sandbox.container(stroke);
    window.sandDemo.containers = sandbox.containers.length;
  }
  stroke = null;
});

camera.zoomOnWheel(canvas);

pourButton.addEventListener('click', () => {
  pouring = !pouring;
  pourButton.setAttribute('aria-pressed', String(pouring));
  pourButton.textContent = pouring ? 'Stop pouring' : 'Pour';
});
$<HTMLButtonElement>('clear').addEventListener('click', () => sandbox?.clearContainers());
$<HTMLButtonElement>('restart').addEventListener('click', () => void restart());

// ---- What the page publishes ----

interface SandDemo {
  ready: boolean;
  backend: 'js' | 'webgpu' | null;
  grains: number;
  maxGrains: number;
  /** The containers: the first one and those drawn. */
  containers: number;
  steps: number;
  frameMs: number;
  workMs: number;
  /** Page coordinates of a world point. */
  worldToClient(x: number, y: number): { x: number; y: number };
}

declare global {
  interface Window {
    sandDemo: SandDemo;
  }
}

window.webphysicsDemo = { ready: false, panes: [] };
window.sandDemo = {
  ready: false,
  backend: null,
  grains: 0,
  maxGrains: 0,
  containers: 0,
  steps: 0,
  frameMs: NaN,
  workMs: NaN,
  worldToClient: (x: number, y: number) => camera.toClient(canvas, x, y),
};

function publish(now: number): void {
  if (sandbox === null) return;
  const backend = view instanceof GpuWorldView ? 'webgpu' : 'js';
  const frameMs = loop.frameTimes.median(now);
  const workMs = loop.workTimes.median(now);
  Object.assign(window.sandDemo, {
    ready: loop.frames > 0,
    backend,
    grains: sandbox.grains,
    maxGrains: sandbox.maxGrains,
    containers: sandbox.containers.length,
    steps,
    frameMs,
    workMs,
  });
  window.webphysicsDemo.panes = [
    { backend, adapter: backend === 'webgpu' ? (adapterNote.dataset.adapter ?? null) : null, bodies: sandbox.world.GetBodyCount(), steps, stepMs: workMs },
  ];
  window.webphysicsDemo.ready = loop.frames > 0;
  statsLine.textContent =
    `${backend === 'webgpu' ? 'WebGPU: stepped and drawn on the GPU' : 'JavaScript engine, drawn on a 2D canvas'} · ` +
    `${fmtCount(sandbox.grains)} of ${fmtCount(sandbox.maxGrains)} grains · ${sandbox.containers.length} containers · ` +
    `frame ${fmtMs(frameMs)} ms · step + draw ${fmtMs(workMs)} ms`;
}

// ---- Start ----

async function start(): Promise<void> {
  gpuContext = await openGpu(
    adapterNote,
    `Up to ${fmtCount(GPU_GRAINS)} grains, stepped and drawn on the GPU.`,
    `the JavaScript engine pours up to ${fmtCount(JS_GRAINS)} grains, drawn on a 2D canvas.`,
  );
  await restart();
  loop.start();
}

void start();
