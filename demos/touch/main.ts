/*
 * The touch and play page (touch.html), after the original Web Physics work's "Touch&Play": a
 * box of bodies played with by pointer events, any number of fingers at once (a mouse or a pen is
 * one finger). A finger on a body drags it with its own b2MouseJoint, and letting go flings it
 * with the velocity the joint gave it; a tap on empty space drops a new body there; a finger held
 * still on a body for HOLD_MS pins the body to the world at that point with a revolute joint, or
 * unpins it. On WebGPU the world is stepped and drawn on the GPU (GpuWorldView, bodies picked by
 * GpuPointQuery); without WebGPU on the JavaScript engine (CanvasWorldView), and the page says so.
 * window.webphysicsDemo and window.touchDemo tell tests and scripts what runs.
 */

import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2BodyDef, b2_dynamicBody } from '../../src/dynamics/b2Body';
import type { b2Body } from '../../src/dynamics/b2Body';
import { b2World } from '../../src/dynamics/b2World';
import { b2MouseJointDef } from '../../src/dynamics/joints/b2MouseJoint';
import type { b2MouseJoint } from '../../src/dynamics/joints/b2MouseJoint';
import { b2RevoluteJointDef } from '../../src/dynamics/joints/b2RevoluteJoint';
import type { b2RevoluteJoint } from '../../src/dynamics/joints/b2RevoluteJoint';
import type { GpuContext } from '../../src-gpu/device/device';
import type { GpuPointHit } from '../../src-gpu/query/pointQuery';
import { DT, POSITION_ITERATIONS, VELOCITY_ITERATIONS } from '../compare/config';
import { Camera } from '../compare/view';
import { bodyAtPoint } from '../framework/canvasView';
import { $, fmtCount, fmtMs, showNote } from '../framework/demo';
import { FrameLoop, GpuWorldView, openGpu, openWorldView } from '../framework/gpuView';
import type { WorldView } from '../framework/gpuView';

/** Half the box's width and its height (m). */
const HALF_WIDTH = 10;
const HEIGHT = 16;
/** A finger held this long within HOLD_SLOP of where it went down pins or unpins. */
const HOLD_MS = 500;
const HOLD_SLOP = 0.3;
const MAX_BODIES = 2_000;

const canvas = $<HTMLCanvasElement>('world');
const adapterNote = $<HTMLParagraphElement>('adapter');
const statsLine = $<HTMLParagraphElement>('stats');
const showMessage = (text: string) => showNote($<HTMLParagraphElement>('message'), text);
const camera = new Camera();

class Playground {
  readonly world = new b2World(new b2Vec2(0, -10));
  readonly ground: b2Body;
  readonly bodies: b2Body[] = [];
  readonly pins = new Map<b2Body, b2RevoluteJoint>();
  private readonly bd = new b2BodyDef();
  private readonly box = new b2PolygonShape();
  private readonly disc = new b2CircleShape();

  constructor() {
    this.ground = this.world.CreateBody(new b2BodyDef());
    const wall = new b2PolygonShape();
    for (const [x, y, hx, hy] of [
      [0, -0.5, HALF_WIDTH + 1, 0.5],
      [-HALF_WIDTH - 0.5, HEIGHT / 2, 0.5, HEIGHT / 2],
      [HALF_WIDTH + 0.5, HEIGHT / 2, 0.5, HEIGHT / 2],
    ]) {
      wall.SetAsBox(hx, hy, new b2Vec2(x, y), 0);
      this.ground.CreateFixture(wall, 0);
    }
    this.box.SetAsBox(0.5, 0.5);
    this.disc.m_radius = 0.5;
    this.bd.type = b2_dynamicBody;
    for (let i = 0; i < 12; ++i) this.spawn(-6 + (i % 6) * 2.4, 1 + Math.floor(i / 6) * 2);
  }

  /** A box or a ball (alternately) at (x, y); null when the playground is full. */
  spawn(x: number, y: number): b2Body | null {
    if (this.bodies.length >= MAX_BODIES) return null;
    this.bd.position.Set(x, y);
    const body = this.world.CreateBody(this.bd);
    const fixture = body.CreateFixture(this.bodies.length % 2 === 0 ? this.box : this.disc, 1);
    fixture.SetFriction(0.6);
    this.bodies.push(body);
    return body;
  }

  /** Pins `body` to the world at `at`, the point `local` of the body, or unpins it when it is pinned. */
  togglePin(body: b2Body, at: b2Vec2, local: { x: number; y: number }): void {
    const pin = this.pins.get(body);
    if (pin !== undefined) {
      this.world.DestroyJoint(pin);
      this.pins.delete(body);
      return;
    }
    const def = new b2RevoluteJointDef();
    def.bodyA = this.ground;
    def.bodyB = body;
    def.localAnchorA.Set(at.x, at.y);
    // The picked point in the body's frame: on WebGPU the world's b2Body holds its last read-back.
    def.localAnchorB.Set(local.x, local.y);
    def.referenceAngle = body.GetAngle();
    this.pins.set(body, this.world.CreateJoint(def) as b2RevoluteJoint);
  }
}

/** A finger (pointer) on the canvas: where it went down, the joint it drags with, where it is. */
interface Finger {
  downAt: number;
  start: b2Vec2;
  at: b2Vec2;
  hit: GpuPointHit | null;
  joint: b2MouseJoint | null;
  held: boolean;
}

let gpuContext: GpuContext | null = null;
let playground: Playground | null = null;
let view: WorldView | null = null;
let steps = 0;
let spawned = 0;
let pinned = 0;
const fingers = new Map<number, Finger>();

function bodyAt(x: number, y: number): Promise<GpuPointHit | null> {
  if (view instanceof GpuWorldView) return view.bodyAt(x, y);
  return Promise.resolve(playground === null ? null : bodyAtPoint(playground.world, x, y));
}

const loop = new FrameLoop(
  () => {
    const current = playground;
    if (current === null) return null;
    const now = performance.now();
    for (const finger of fingers.values()) {
      finger.joint?.SetTarget(finger.at);
      // A finger held still on a body pins or unpins it, once.
      if (
        !finger.held &&
        finger.hit !== null &&
        now - finger.downAt >= HOLD_MS &&
        Math.hypot(finger.at.x - finger.start.x, finger.at.y - finger.start.y) < HOLD_SLOP
      ) {
        finger.held = true;
        if (finger.joint !== null) current.world.DestroyJoint(finger.joint);
        finger.joint = null;
        current.togglePin(finger.hit.body, finger.start, finger.hit.localPoint);
        pinned = current.pins.size;
      }
    }
    const step = () => {
      current.world.Step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
      steps++;
    };
    return view !== null ? view.frame(step, camera) : null;
  },
  (now) => publish(now),
  showMessage,
);

async function restart(): Promise<void> {
  playground = null;
  fingers.clear();
  await loop.idle();
  await view?.close();
  view = null;
  const next = new Playground();
  view = await openWorldView(next.world, gpuContext, canvas);
  const rect = canvas.getBoundingClientRect();
  camera.fit({ x: 0, y: HEIGHT / 2, halfWidth: HALF_WIDTH + 1.5, halfHeight: HEIGHT / 2 + 1 }, rect.width, rect.height);
  steps = 0;
  spawned = 0;
  pinned = 0;
  loop.reset();
  playground = next;
}

// ---- Fingers ----

canvas.addEventListener('pointerdown', (event) => {
  const current = playground;
  if (current === null) return;
  canvas.setPointerCapture(event.pointerId);
  const p = camera.toWorld(canvas, event);
  const finger: Finger = { downAt: performance.now(), start: p, at: p.Clone(), hit: null, joint: null, held: false };
  fingers.set(event.pointerId, finger);
  event.preventDefault();
  void bodyAt(p.x, p.y).then(
    (hit) => {
      if (playground !== current) return;
      if (hit === null) {
        // A tap drops a body even when the finger is gone before the GPU answers.
        if (current.spawn(p.x, p.y) !== null) spawned++;
        return;
      }
      if (fingers.get(event.pointerId) !== finger) return;
      finger.hit = hit;
      const def = new b2MouseJointDef();
      def.bodyA = current.ground;
      def.bodyB = hit.body;
      def.target.Set(p.x, p.y);
      def.maxForce = 1000 * hit.body.GetMass();
      finger.joint = current.world.CreateJoint(def) as b2MouseJoint;
      // The anchor from the picked point: on WebGPU the world's b2Body holds its last read-back.
      finger.joint.m_localAnchorB.Set(hit.localPoint.x, hit.localPoint.y);
    },
    (error) => showMessage(`Picking failed: ${error instanceof Error ? error.message : String(error)}`),
  );
});

canvas.addEventListener('pointermove', (event) => {
  const finger = fingers.get(event.pointerId);
  if (finger !== undefined) finger.at = camera.toWorld(canvas, event);
});

function lift(event: PointerEvent): void {
  const finger = fingers.get(event.pointerId);
  if (finger === undefined) return;
  if (finger.joint !== null && playground !== null) playground.world.DestroyJoint(finger.joint);
  fingers.delete(event.pointerId);
}
canvas.addEventListener('pointerup', lift);
canvas.addEventListener('pointercancel', lift);
camera.zoomOnWheel(canvas);
$<HTMLButtonElement>('restart').addEventListener('click', () => void restart());

// ---- What the page publishes ----

interface TouchDemo {
  ready: boolean;
  backend: 'js' | 'webgpu' | null;
  steps: number;
  bodies: number;
  /** Bodies dropped by taps, and bodies pinned now. */
  spawned: number;
  pinned: number;
  /** The fingers dragging a body now: its index in the playground's bodies. */
  dragging: number[];
  /** Page coordinates of a world point. */
  worldToClient(x: number, y: number): { x: number; y: number };
  /** Body `index`'s position now (on WebGPU: after a world.Synchronize). */
  bodyPosition(index: number): Promise<{ x: number; y: number }>;
}

declare global {
  interface Window {
    touchDemo: TouchDemo;
  }
}

window.webphysicsDemo = { ready: false, panes: [] };
window.touchDemo = {
  ready: false,
  backend: null,
  steps: 0,
  bodies: 0,
  spawned: 0,
  pinned: 0,
  dragging: [],
  worldToClient: (x: number, y: number) => camera.toClient(canvas, x, y),
  async bodyPosition(index: number) {
    if (playground === null) throw new Error('no playground yet');
    const body = playground.bodies[index];
    if (body === undefined) throw new RangeError(`index must be a body of the playground (0 to ${playground.bodies.length - 1}); got ${index}`);
    if (view instanceof GpuWorldView) await playground.world.Synchronize();
    const p = body.GetPosition();
    return { x: p.x, y: p.y };
  },
};

function publish(now: number): void {
  if (playground === null) return;
  const backend = view instanceof GpuWorldView ? 'webgpu' : 'js';
  const workMs = loop.workTimes.median(now);
  const bodies = playground.bodies;
  const dragging = [...fingers.values()].filter((f) => f.joint !== null && f.hit !== null).map((f) => bodies.indexOf(f.hit!.body));
  Object.assign(window.touchDemo, { ready: loop.frames > 0, backend, steps, bodies: bodies.length, spawned, pinned, dragging });
  window.webphysicsDemo.panes = [
    { backend, adapter: backend === 'webgpu' ? (adapterNote.dataset.adapter ?? null) : null, bodies: playground.world.GetBodyCount(), steps, stepMs: workMs },
  ];
  window.webphysicsDemo.ready = loop.frames > 0;
  statsLine.textContent =
    `${backend === 'webgpu' ? 'WebGPU: stepped and drawn on the GPU' : 'JavaScript engine, drawn on a 2D canvas'} · ` +
    `${fmtCount(bodies.length)} bodies, ${pinned} pinned · ${fingers.size} fingers down · frame ${fmtMs(loop.frameTimes.median(now))} ms`;
}

// ---- Start ----

async function start(): Promise<void> {
  gpuContext = await openGpu(adapterNote, 'Stepped and drawn on the GPU.', 'the JavaScript engine runs, drawn on a 2D canvas.');
  await restart();
  loop.start();
}

void start();
