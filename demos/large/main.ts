/*
 * The large-world page (large.html): 10^4 to 10^6 bodies stepped by the WebGPU backend and drawn
 * by GpuRenderer straight from the GPU's buffers, one step per display frame while the GPU keeps
 * up (a frame that finds the previous frame's work unfinished skips its step, and the page counts
 * it). A press on a body asks the GPU which body is under the pointer (GpuPointQuery) and drags it
 * with a b2MouseJoint; a press on empty space pans. Without WebGPU the JavaScript engine steps at
 * most 10^4 bodies and the comparison page's canvas view draws them, and the page says so.
 * `?scene=pyramids|rain|sand&bodies=N` selects from the URL; window.webphysicsDemo and
 * window.largeDemo tell tests and scripts what runs.
 */

import { b2BodyDef } from '../../src/dynamics/b2Body';
import type { b2Body } from '../../src/dynamics/b2Body';
import type { b2World } from '../../src/dynamics/b2World';
import { b2MouseJointDef } from '../../src/dynamics/joints/b2MouseJoint';
import type { b2MouseJoint } from '../../src/dynamics/joints/b2MouseJoint';
import { b2Vec2 } from '../../src/common/b2Math';
import type { GpuPointHit } from '../../src-gpu/query/pointQuery';
import type { GpuContext } from '../../src-gpu/device/device';
import { checkConfig, DT, POSITION_ITERATIONS, SCENE_TITLES, TRANSFORM_STRIDE, VELOCITY_ITERATIONS } from '../compare/config';
import type { SceneConfig, SceneGeometry, SceneName } from '../compare/config';
import { sceneGeometry } from '../compare/pane';
import { buildScene } from '../compare/scenes';
import type { BuiltScene } from '../compare/scenes';
import { Camera, PaneView } from '../compare/view';
import { $, fmtCount, fmtMs, showNote } from '../framework/demo';
import type { DemoPane } from '../framework/demo';
import { bodyAtPoint } from '../framework/canvasView';
import { FrameLoop, GpuWorldView, openGpu } from '../framework/gpuView';

const SCENES: readonly SceneName[] = ['pyramids', 'rain', 'sand'];
const GPU_COUNTS = [10_000, 20_000, 50_000, 100_000, 200_000, 500_000, 1_000_000];
const JS_COUNTS = [1_000, 2_000, 5_000, 10_000];
const SEED = 1;

const canvas = $<HTMLCanvasElement>('world');
const sceneInput = $<HTMLSelectElement>('scene');
const bodiesInput = $<HTMLSelectElement>('bodies');
const pauseButton = $<HTMLButtonElement>('pause');
const adapterNote = $<HTMLParagraphElement>('adapter');
const messageNote = $<HTMLParagraphElement>('message');
const statsLine = $<HTMLParagraphElement>('stats');
const camera = new Camera();

const showMessage = (text: string) => showNote(messageNote, text);

/** What steps and draws the world: the GPU (stepped and drawn there) or the JavaScript engine and a 2D canvas. */
interface Stage {
  readonly backend: 'js' | 'webgpu';
  readonly scene: BuiltScene;
  /** Steps once (unless paused) and draws; resolves when the frame's work is done. */
  frame(step: boolean): Promise<void>;
  /** The dynamic body under a world point, and the point in its frame. */
  bodyAt(x: number, y: number): Promise<GpuPointHit | null>;
  /** Releases what the stage holds. */
  close(): Promise<void>;
}

class GpuStage implements Stage {
  readonly backend = 'webgpu';
  private constructor(
    readonly scene: BuiltScene,
    private readonly view: GpuWorldView,
  ) {}

  static async create(scene: BuiltScene, context: GpuContext): Promise<GpuStage> {
    return new GpuStage(scene, await GpuWorldView.create(scene.world, context, canvas));
  }

  get lastFrame() {
    return this.view.lastFrame;
  }

  frame(step: boolean): Promise<void> {
    return this.view.frame(() => {
      if (step) this.scene.world.Step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
    }, camera);
  }

  bodyAt(x: number, y: number): Promise<GpuPointHit | null> {
    return this.view.bodyAt(x, y);
  }

  close(): Promise<void> {
    return this.view.close();
  }
}

class JsStage implements Stage {
  readonly backend = 'js';
  private readonly view = new PaneView(canvas);
  private readonly geometry: SceneGeometry;
  private readonly transforms: Float32Array;
  private readonly awake: Uint8Array;

  constructor(readonly scene: BuiltScene) {
    this.geometry = sceneGeometry(scene);
    this.transforms = new Float32Array(TRANSFORM_STRIDE * scene.bodies.length);
    this.awake = new Uint8Array(scene.bodies.length);
  }

  async frame(step: boolean): Promise<void> {
    const { world, bodies } = this.scene;
    if (step) world.Step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
    for (let i = 0; i < bodies.length; ++i) {
      const xf = bodies[i].m_xf;
      const at = TRANSFORM_STRIDE * i;
      this.transforms[at] = xf.p.x;
      this.transforms[at + 1] = xf.p.y;
      this.transforms[at + 2] = xf.q.c;
      this.transforms[at + 3] = xf.q.s;
      this.awake[i] = this.geometry.bodyStatic[i] === 0 && bodies[i].IsAwake() ? 1 : 0;
    }
    this.view.resize();
    this.view.draw(this.geometry, this.transforms, this.awake, camera);
  }

  async bodyAt(x: number, y: number): Promise<GpuPointHit | null> {
    return bodyAtPoint(this.scene.world, x, y);
  }

  async close(): Promise<void> {}
}

// ---- The scene, the stage and the loop ----

let gpuContext: GpuContext | null = null;
let stage: Stage | null = null;
let config: SceneConfig = { scene: 'pyramids', bodies: 10_000, seed: SEED, sleep: false };
let paused = false;
let building = false;
let ground: b2Body | null = null;
let mouse: { joint: b2MouseJoint; bodyIndex: number; target: b2Vec2 } | null = null;
let steps = 0;
const loop = new FrameLoop(
  () => {
    if (stage === null || building) return null;
    if (mouse !== null && !paused) mouse.joint.SetTarget(mouse.target);
    const stepping = !paused;
    return stage.frame(stepping).then(() => {
      if (stepping) steps++;
    });
  },
  (now) => publish(now),
  showMessage,
);

function counts(): number[] {
  return gpuContext !== null ? GPU_COUNTS : JS_COUNTS;
}

async function rebuild(next: SceneConfig): Promise<void> {
  building = true;
  try {
    mouse = null;
    await loop.idle();
    await stage?.close();
    stage = null;
    checkConfig(next, counts()[counts().length - 1]);
    config = next;
    const scene = buildScene(config, counts()[counts().length - 1]);
    // The mouse joint's fixed end, as the Testbed's m_groundBody.
    ground = scene.world.CreateBody(new b2BodyDef());
    stage = gpuContext !== null ? await GpuStage.create(scene, gpuContext) : new JsStage(scene);
    const rect = canvas.getBoundingClientRect();
    camera.fit(scene.view, rect.width, rect.height);
    steps = 0;
    loop.reset();
    const url = new URL(location.href);
    url.searchParams.set('scene', config.scene);
    url.searchParams.set('bodies', String(config.bodies));
    history.replaceState(null, '', url);
    sceneInput.value = config.scene;
    bodiesInput.value = String(config.bodies);
  } catch (error) {
    showMessage(`Could not build the scene: ${error instanceof Error ? error.message : String(error)}`);
    console.error(error);
  } finally {
    building = false;
  }
}

// ---- Pointer: drag a body with a mouse joint, or pan; wheel zooms ----

let pan: { x: number; y: number } | null = null;

canvas.addEventListener('pointerdown', (event) => {
  if (stage === null || building) return;
  canvas.setPointerCapture(event.pointerId);
  const p = camera.toWorld(canvas, event);
  const current = stage;
  pan = { x: event.clientX, y: event.clientY };
  void current.bodyAt(p.x, p.y).then(
    (hit) => {
      if (hit === null || stage !== current || pan === null || ground === null) return;
      pan = null;
      const world: b2World = current.scene.world;
      const def = new b2MouseJointDef();
      def.bodyA = ground;
      def.bodyB = hit.body;
      def.target.Set(p.x, p.y);
      def.maxForce = 1000 * hit.body.GetMass();
      const joint = world.CreateJoint(def) as b2MouseJoint;
      // The anchor from the GPU's transform: the world's b2Body holds the state of its last read-back.
      joint.m_localAnchorB.Set(hit.localPoint.x, hit.localPoint.y);
      mouse = { joint, bodyIndex: current.scene.bodies.indexOf(hit.body), target: p };
      window.largeDemo.dragging = mouse.bodyIndex;
    },
    (error) => showMessage(`Picking failed: ${error instanceof Error ? error.message : String(error)}`),
  );
  event.preventDefault();
});

canvas.addEventListener('pointermove', (event) => {
  if (mouse !== null) mouse.target = camera.toWorld(canvas, event);
  else if (pan !== null) {
    camera.pan(event.clientX - pan.x, event.clientY - pan.y);
    pan = { x: event.clientX, y: event.clientY };
  }
});

canvas.addEventListener('pointerup', () => {
  pan = null;
  if (mouse !== null && stage !== null) stage.scene.world.DestroyJoint(mouse.joint);
  mouse = null;
  window.largeDemo.dragging = null;
});

camera.zoomOnWheel(canvas);

// ---- Controls and the URL ----

function fillControls(): void {
  sceneInput.replaceChildren(...SCENES.map((s) => new Option(SCENE_TITLES[s], s)));
  bodiesInput.replaceChildren(...counts().map((n) => new Option(fmtCount(n), String(n))));
}

sceneInput.addEventListener('change', () => void rebuild({ ...config, scene: sceneInput.value as SceneName }));
bodiesInput.addEventListener('change', () => void rebuild({ ...config, bodies: Number(bodiesInput.value) }));
pauseButton.addEventListener('click', () => {
  paused = !paused;
  pauseButton.setAttribute('aria-pressed', String(paused));
  pauseButton.textContent = paused ? 'Resume' : 'Pause';
});
$<HTMLButtonElement>('fit').addEventListener('click', () => {
  if (stage === null) return;
  const rect = canvas.getBoundingClientRect();
  camera.fit(stage.scene.view, rect.width, rect.height);
});

/** The URL's scene and size, or the defaults with the problems named. */
function fromUrl(): SceneConfig {
  const params = new URLSearchParams(location.search);
  const wanted: SceneConfig = { ...config, bodies: counts()[0] };
  const problems: string[] = [];
  const scene = params.get('scene');
  if (scene !== null) {
    if ((SCENES as readonly string[]).includes(scene)) wanted.scene = scene as SceneName;
    else problems.push(`scene must be one of ${SCENES.join(', ')} (got "${scene}")`);
  }
  const bodies = params.get('bodies');
  if (bodies !== null) {
    const n = Number(bodies);
    const list = counts();
    if (Number.isInteger(n) && n >= list[0] && n <= list[list.length - 1]) wanted.bodies = n;
    else problems.push(`bodies must be an integer from ${list[0]} to ${list[list.length - 1]} here (got "${bodies}")`);
  }
  if (problems.length > 0) showMessage(`URL: ${problems.join('; ')}; the default is used for each.`);
  return wanted;
}

// ---- What the page publishes ----

interface LargeDemo {
  ready: boolean;
  backend: 'js' | 'webgpu' | null;
  scene: SceneName;
  bodies: number;
  frames: number;
  steps: number;
  /** Display frames that waited because the previous frame's work was not done. */
  skipped: number;
  /** Median over the last second: time between frames, and from a frame's step call to its work done. */
  frameMs: number;
  gpuFrameMs: number;
  /** What the renderer drew in the last frame (WebGPU). */
  drawn: { proxies: number; joints: number } | null;
  /** The dragged body (index in the scene's body list), null when none. */
  dragging: number | null;
  /** Page coordinates of a world point. */
  worldToClient(x: number, y: number): { x: number; y: number };
  /** Centres the view on (x, y) at `scale` CSS pixels per metre. */
  lookAt(x: number, y: number, scale: number): void;
  /** Body `index`'s position now (on WebGPU: after a world.Synchronize). */
  bodyPosition(index: number): Promise<{ x: number; y: number }>;
}

declare global {
  interface Window {
    largeDemo: LargeDemo;
  }
}

window.webphysicsDemo = { ready: false, panes: [] };
window.largeDemo = {
  ready: false,
  backend: null,
  scene: config.scene,
  bodies: 0,
  frames: 0,
  steps: 0,
  skipped: 0,
  frameMs: NaN,
  gpuFrameMs: NaN,
  drawn: null,
  dragging: null,
  worldToClient: (x: number, y: number) => camera.toClient(canvas, x, y),
  lookAt(x: number, y: number, scale: number) {
    Object.assign(camera, { x, y, scale });
  },
  async bodyPosition(index: number) {
    if (stage === null) throw new Error('no scene yet');
    const body = stage.scene.bodies[index];
    if (body === undefined) throw new RangeError(`index must be a body of the scene (0 to ${stage.scene.bodies.length - 1}); got ${index}`);
    if (stage.backend === 'webgpu') await stage.scene.world.Synchronize();
    const p = body.GetPosition();
    return { x: p.x, y: p.y };
  },
};

function publish(now: number): void {
  if (stage === null) return;
  const frameMs = loop.frameTimes.median(now);
  const gpuFrameMs = loop.workTimes.median(now);
  const { frames, waited: skipped } = loop;
  const drawn = stage instanceof GpuStage ? stage.lastFrame : null;
  Object.assign(window.largeDemo, {
    ready: frames > 0,
    backend: stage.backend,
    scene: config.scene,
    bodies: stage.scene.bodies.length,
    frames,
    steps,
    skipped,
    frameMs,
    gpuFrameMs,
    drawn: drawn === null ? null : { proxies: drawn.proxies, joints: drawn.joints },
    dragging: mouse?.bodyIndex ?? null,
  });
  const pane: DemoPane = {
    backend: stage.backend,
    adapter: stage.backend === 'webgpu' ? (adapterNote.dataset.adapter ?? null) : null,
    bodies: stage.scene.bodies.length,
    steps,
    stepMs: gpuFrameMs,
  };
  window.webphysicsDemo.panes = [pane];
  window.webphysicsDemo.ready = frames > 0;
  const where = stage.backend === 'webgpu' ? 'WebGPU: stepped and drawn on the GPU' : 'JavaScript engine, drawn on a 2D canvas';
  statsLine.textContent =
    `${where} · ${fmtCount(stage.scene.bodies.length)} bodies · step ${fmtCount(steps)} · ` +
    `frame ${fmtMs(frameMs)} ms (${Number.isFinite(frameMs) && frameMs > 0 ? (1000 / frameMs).toFixed(0) : '–'} fps) · ` +
    `${stage.backend === 'webgpu' ? 'step + draw done on the GPU in' : 'step + draw'} ${fmtMs(gpuFrameMs)} ms` +
    (skipped > 0 ? ` · ${fmtCount(skipped)} display frames waited for the GPU` : '');
}

// ---- Start ----

async function start(): Promise<void> {
  gpuContext = await openGpu(
    adapterNote,
    `Up to ${fmtCount(GPU_COUNTS[GPU_COUNTS.length - 1])} bodies, stepped and drawn on the GPU.`,
    `the JavaScript engine runs, with at most ${fmtCount(JS_COUNTS[JS_COUNTS.length - 1])} bodies drawn on a 2D canvas.`,
  );
  fillControls();
  await rebuild(fromUrl());
  loop.start();
}

void start();
