/*
 * The comparison page (compare.html): one scene stepped by the JavaScript engine and by the WebGPU
 * backend in two panes with one camera. Each pane's physics runs in a worker (worker.ts), so the
 * page stays responsive when a step takes longer than a frame; the page asks each worker for at most
 * one step per display frame, draws what comes back, and charts both step times over the run.
 * `?scene=NAME&bodies=N&seed=S&sleep=1` selects from the URL; window.webphysicsDemo tells tests and
 * scripts what runs.
 */

import { $, adapterName, detectWebGpu, fmtCount, fmtMs, showNote, StepTimes } from '../framework/demo';
import type { DemoPane } from '../framework/demo';
import { StepChart } from './chart';
import { BODY_COUNTS, checkConfig, DT, SCENE_NAMES, SCENE_TITLES, TRANSFORM_STRIDE } from './config';
import type { PaneStats, SceneConfig, SceneGeometry, SceneName } from './config';
import type { FromWorker, PaneBackend, ToWorker } from './protocol';
import { Camera, PaneView } from './view';

const sceneInput = $<HTMLSelectElement>('scene');
const bodiesInput = $<HTMLInputElement>('bodies');
const bodiesLabel = $<HTMLOutputElement>('bodies-label');
const seedInput = $<HTMLInputElement>('seed');
const sleepInput = $<HTMLInputElement>('sleep');
const adapterNote = $<HTMLParagraphElement>('adapter');
const messageNote = $<HTMLParagraphElement>('message');
const camera = new Camera();
const chart = new StepChart($<HTMLCanvasElement>('chart'));
const pageStarted = performance.now();

const DEFAULTS: SceneConfig = { scene: 'pyramids', bodies: 1000, seed: 1, sleep: false };

const showMessage = (text: string) => showNote(messageNote, text);

/** One pane: its worker, the buffers it steps into, its drawing and its statistics. */
class Pane {
  readonly view: PaneView;
  private readonly statsLine: HTMLParagraphElement;
  private worker: Worker | null = null;
  private geometry: SceneGeometry | null = null;
  /** The transforms drawn, and the spare set the worker steps into next. */
  private shown: { transforms: Float32Array; awake: Uint8Array } | null = null;
  private spare: { transforms: Float32Array; awake: Uint8Array } | null = null;
  private stats: PaneStats | null = null;
  private readonly times = new StepTimes();
  /** When the last steps came back (steps per second). */
  private readonly arrivals: number[] = [];
  private stepping = false;
  private dirty = false;
  private state = '';
  adapter: string | null = null;
  /** The reason this pane does not run, when it does not. */
  unavailable: string | null = null;

  constructor(
    readonly backend: PaneBackend,
    section: HTMLElement,
    readonly series: number,
  ) {
    this.view = new PaneView(section.querySelector('canvas')!);
    this.statsLine = section.querySelector('.stats')!;
  }

  get ready(): boolean {
    return this.stats !== null && this.stats.steps > 0;
  }

  build(config: SceneConfig): void {
    this.worker?.terminate();
    this.worker = null;
    this.geometry = this.shown = this.spare = this.stats = null;
    this.stepping = false;
    this.times.clear();
    this.arrivals.length = 0;
    if (this.unavailable !== null) {
      this.state = this.unavailable;
      this.dirty = true;
      return;
    }
    this.state = `building ${fmtCount(config.bodies)} bodies…`;
    this.dirty = true;
    const worker = new Worker(new URL('compare-worker.js', location.href), { type: 'module' });
    this.worker = worker;
    worker.onmessage = (event: MessageEvent<FromWorker>) => {
      if (this.worker === worker) this.receive(event.data);
    };
    worker.onerror = (event) => {
      if (this.worker === worker) this.fail(event.message || 'the worker failed to start');
    };
    const message: ToWorker = { type: 'build', backend: this.backend, config };
    worker.postMessage(message);
  }

  private fail(message: string): void {
    this.worker?.terminate();
    this.worker = null;
    this.stats = null;
    this.state = `failed: ${message}`;
    this.dirty = true;
    console.error(`${this.backend} pane: ${message}`);
  }

  private receive(message: FromWorker): void {
    const now = performance.now();
    switch (message.type) {
      case 'built': {
        this.geometry = message.geometry;
        this.stats = message.stats;
        if (message.adapter !== null) this.adapter = adapterName(message.adapter);
        const n = message.geometry.bodyStatic.length;
        const set = () => ({ transforms: new Float32Array(TRANSFORM_STRIDE * n).fill(NaN), awake: new Uint8Array(n) });
        this.shown = set();
        this.spare = set();
        this.state = `built in ${fmtMs(message.buildMs)} ms`;
        if (this.series === 0) this.fitCamera();
        break;
      }
      case 'stepped': {
        this.stepping = false;
        this.spare = this.shown;
        this.shown = { transforms: message.transforms, awake: message.awake };
        this.stats = message.stats;
        this.times.add(now, message.stats.stepMs);
        this.arrivals.push(now);
        chart.add(this.series, (now - pageStarted) / 1000, message.stats.stepMs);
        this.state = '';
        this.dirty = true;
        break;
      }
      case 'error':
        this.fail(message.message);
        break;
    }
  }

  /** Asks the worker for the next step unless one is running. */
  requestStep(): void {
    if (this.worker === null || this.stepping || this.spare === null || this.geometry === null) return;
    const { transforms, awake } = this.spare;
    this.spare = null;
    this.stepping = true;
    const message: ToWorker = { type: 'step', transforms, awake };
    this.worker.postMessage(message, [transforms.buffer, awake.buffer]);
  }

  /** Frames this pane's scene; false before it is built. */
  fitCamera(): boolean {
    if (this.geometry === null) return false;
    this.view.resize();
    camera.fit(this.geometry.view, this.view.width, this.view.height);
    return true;
  }

  invalidate(): void {
    this.dirty = true;
  }

  draw(): void {
    if (!this.dirty) return;
    this.dirty = false;
    this.view.resize();
    if (this.geometry === null || this.shown === null || !this.ready) {
      this.view.message(this.state);
      return;
    }
    this.view.draw(this.geometry, this.shown.transforms, this.shown.awake, camera);
  }

  /** Steps per second over the last two seconds. */
  private rate(now: number): number {
    while (this.arrivals.length > 0 && this.arrivals[0] < now - 2000) this.arrivals.shift();
    return this.arrivals.length / 2;
  }

  describe(now: number): DemoPane {
    return {
      backend: this.backend,
      adapter: this.backend === 'webgpu' ? this.adapter : null,
      bodies: this.stats?.bodies ?? 0,
      steps: this.stats?.steps ?? 0,
      stepMs: this.ready ? this.times.median(now) : NaN,
    };
  }

  showStats(now: number): void {
    const s = this.stats;
    if (s === null || !this.ready) {
      this.statsLine.textContent = this.state;
      return;
    }
    const rate = this.rate(now);
    const realTime = rate * DT;
    const pace =
      realTime >= 0.95 ? 'keeping up with real time' : `behind: ${rate.toFixed(1)} steps/s, ${(100 * realTime).toFixed(0)}% of real time, frames skipped`;
    this.statsLine.textContent =
      `step ${fmtMs(this.times.median(now))} ms (median, last second) · ${fmtCount(s.steps)} steps, ${(s.steps * DT).toFixed(1)} s simulated\n` +
      `${fmtCount(s.bodies)} bodies (${fmtCount(s.awake)} awake) · ${fmtCount(s.contacts)} contacts (${fmtCount(s.touching)} touching)` +
      `${s.joints > 0 ? ` · ${fmtCount(s.joints)} joint${s.joints === 1 ? '' : 's'}` : ''}\n${pace}`;
  }
}

const panes = [new Pane('js', $('pane-js'), 0), new Pane('webgpu', $('pane-webgpu'), 1)];
chart.series.push({ label: 'JavaScript engine', colour: '#e6b3b3', points: [] }, { label: 'WebGPU backend', colour: '#80c0ff', points: [] });

window.webphysicsDemo = { ready: false, panes: [] };

function publish(now: number): void {
  const running = panes.filter((p) => p.unavailable === null);
  window.webphysicsDemo.panes = running.map((p) => p.describe(now));
  window.webphysicsDemo.ready = running.length > 0 && running.every((p) => p.ready);
}

// ---- Controls and the URL ----

for (const name of SCENE_NAMES) {
  const option = document.createElement('option');
  option.value = name;
  option.textContent = SCENE_TITLES[name];
  sceneInput.append(option);
}
bodiesInput.max = String(BODY_COUNTS.length - 1);

/** The slider stop nearest to n (in log scale). */
function stopOf(n: number): number {
  let best = 0;
  for (let i = 1; i < BODY_COUNTS.length; ++i) {
    if (Math.abs(Math.log(BODY_COUNTS[i] / n)) < Math.abs(Math.log(BODY_COUNTS[best] / n))) best = i;
  }
  return best;
}

let config: SceneConfig = { ...DEFAULTS };

function showControls(): void {
  sceneInput.value = config.scene;
  bodiesInput.value = String(stopOf(config.bodies));
  bodiesLabel.value = fmtCount(config.bodies);
  seedInput.value = String(config.seed);
  sleepInput.checked = config.sleep;
}

/** The configuration the URL asks for; a bad parameter is named in the message and its default kept. */
function fromUrl(): SceneConfig {
  const params = new URLSearchParams(location.search);
  const wanted: SceneConfig = { ...DEFAULTS };
  const problems: string[] = [];
  const scene = params.get('scene');
  if (scene !== null) {
    if ((SCENE_NAMES as readonly string[]).includes(scene)) wanted.scene = scene as SceneName;
    else problems.push(`scene must be one of ${SCENE_NAMES.join(', ')} (got "${scene}")`);
  }
  for (const key of ['bodies', 'seed'] as const) {
    const text = params.get(key);
    if (text === null) continue;
    const trial = { ...wanted, [key]: Number(text) };
    try {
      checkConfig(trial);
      wanted[key] = trial[key];
    } catch (error) {
      problems.push((error as Error).message);
    }
  }
  const sleep = params.get('sleep');
  if (sleep !== null) wanted.sleep = sleep === '1' || sleep === 'true';
  if (problems.length > 0) showMessage(`URL: ${problems.join('; ')}. Using the default instead.`);
  return wanted;
}

function toUrl(): void {
  const params = new URLSearchParams({ scene: config.scene, bodies: String(config.bodies), seed: String(config.seed) });
  if (config.sleep) params.set('sleep', '1');
  history.replaceState(null, '', `?${params}`);
}

function rebuild(): void {
  try {
    checkConfig(config);
  } catch (error) {
    showMessage((error as Error).message);
    return;
  }
  showControls();
  toUrl();
  chart.mark((performance.now() - pageStarted) / 1000, `${config.scene} ${fmtCount(config.bodies)}`);
  for (const pane of panes) pane.build(config);
}

sceneInput.addEventListener('change', () => {
  config = { ...config, scene: sceneInput.value as SceneName };
  rebuild();
});
bodiesInput.addEventListener('input', () => {
  bodiesLabel.value = fmtCount(BODY_COUNTS[Number(bodiesInput.value)]);
});
bodiesInput.addEventListener('change', () => {
  config = { ...config, bodies: BODY_COUNTS[Number(bodiesInput.value)] };
  rebuild();
});
seedInput.addEventListener('change', () => {
  const seed = Number(seedInput.value);
  try {
    checkConfig({ ...config, seed });
  } catch (error) {
    showMessage((error as Error).message);
    seedInput.value = String(config.seed);
    return;
  }
  showMessage('');
  config = { ...config, seed };
  rebuild();
});
sleepInput.addEventListener('change', () => {
  config = { ...config, sleep: sleepInput.checked };
  rebuild();
});

// ---- The camera: drag to pan and wheel to zoom, on either pane ----

const redrawAll = () => panes.forEach((p) => p.invalidate());
$<HTMLButtonElement>('fit').addEventListener('click', () => {
  panes.find((p) => p.fitCamera());
  redrawAll();
});

for (const pane of panes) {
  const canvas = pane.view.canvas;
  let drag: { x: number; y: number } | null = null;
  canvas.addEventListener('pointerdown', (event) => {
    canvas.setPointerCapture(event.pointerId);
    drag = { x: event.clientX, y: event.clientY };
  });
  canvas.addEventListener('pointermove', (event) => {
    if (drag === null) return;
    camera.pan(event.clientX - drag.x, event.clientY - drag.y);
    drag = { x: event.clientX, y: event.clientY };
    redrawAll();
  });
  canvas.addEventListener('pointerup', () => (drag = null));
  camera.zoomOnWheel(canvas, redrawAll);
}
window.addEventListener('resize', redrawAll);

// ---- WebGPU: is there an adapter? ----

async function findAdapter(): Promise<void> {
  const status = await detectWebGpu();
  if (status.name !== null) {
    panes[1].adapter = status.name;
    adapterNote.textContent = `WebGPU adapter: ${status.name}.`;
    adapterNote.className = 'note ok';
    document.body.dataset.webgpu = 'adapter';
    return;
  }
  panes[1].unavailable = `${status.reason}: the JavaScript engine runs alone.`;
  adapterNote.textContent = panes[1].unavailable;
  adapterNote.className = 'note warn';
  document.body.dataset.webgpu = 'none';
}

// ---- The frame loop ----

let lastText = 0;
function frame(now: number): void {
  requestAnimationFrame(frame);
  for (const pane of panes) pane.draw();
  for (const pane of panes) pane.requestStep();
  if (now - lastText > 250) {
    lastText = now;
    for (const pane of panes) pane.showStats(now);
    chart.draw((now - pageStarted) / 1000);
  }
  publish(now);
}

config = fromUrl();
showControls();
void findAdapter().then(() => {
  rebuild();
  requestAnimationFrame(frame);
});
