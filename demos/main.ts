/*
 * The testbed page: Box2D 2.2.1's Testbed (Main.cpp) in the browser. One test runs at a time; each
 * frame clears the canvas, calls the test's Step (which steps the world and draws it), and draws
 * the title. The panel holds Main.cpp's GLUI controls; the mouse and keys work as in Main.cpp.
 * window.testbed exposes hooks for the browser tests (test/browser) and for the console.
 */

import { b2Vec2, b2_dynamicBody, b2_kinematicBody, b2_staticBody } from '../src/index';
import { BACKEND_NAMES, TestbedBackend } from './backend';
import type { BackendName } from './backend';
import { sceneDigests } from './determinism';
import { srand } from './framework/random';
import { g_debugDraw } from './framework/render';
import { $, detectWebGpu } from './framework/demo';
import type { DemoPane } from './framework/demo';
import { kStepSettingKeys, Settings } from './framework/settings';
import type { StepSettings } from './framework/settings';
import type { Test, TestEntry } from './framework/test';
import { benchEntries } from './scenes/bench';
import { JsonScene } from './scenes/json';
import { g_testEntries } from './tests/index';

const canvas = $<HTMLCanvasElement>('canvas');
const gpuCanvas = $<HTMLCanvasElement>('gpu-canvas');
const testList = $<HTMLSelectElement>('tests');
const webgpuStatus = $<HTMLParagraphElement>('webgpu-status');
const backendList = $<HTMLSelectElement>('backend');
const backendNote = $<HTMLParagraphElement>('backend-note');
const draw = g_debugDraw;
draw.SetCanvas(canvas);

// Main.cpp's state.
const settings = new Settings();
let settingsHz = 60.0;
let viewZoom = 1.0;
const entries: TestEntry[] = [...g_testEntries, ...benchEntries()];
let testIndex = 0;
let testSelection = 0;
let entry: TestEntry = entries[0];
let test: Test;
/** The step settings in force before the current scene replaced them with its own. */
let savedStepSettings: StepSettings | null = null;
/** Errors thrown by tests (also sent to the console). */
const errors: string[] = [];
let frameCount = 0;
const backends = new TestbedBackend((error, what) => report(error, what), gpuCanvas, draw);

function syncView(): void {
  draw.viewCenter.Set(settings.viewCenter.x, settings.viewCenter.y);
  draw.viewZoom = viewZoom;
}

function report(error: unknown, what: string): void {
  const message = error instanceof Error ? error.message : String(error);
  errors.push(`${what}: ${message}`);
  console.error(`${what}:`, error);
  showMessage(`${what}: ${message}`, 'warn');
}

function showMessage(text: string, kind: 'ok' | 'warn' | '' = ''): void {
  const note = $<HTMLParagraphElement>('message');
  note.textContent = text;
  note.className = `note ${kind}`;
  note.hidden = text === '';
}

/** Create the entry's test: the random numbers restart from srand(1), as in a fresh Testbed. */
function createTest(e: TestEntry): Test {
  srand(1);
  return e.createFcn();
}

function applyStepSettings(values: Partial<StepSettings>): void {
  for (const key of kStepSettingKeys) {
    const value = values[key];
    if (value !== undefined) settings[key] = value;
  }
  if (values.hz !== undefined) settingsHz = values.hz;
}

/** Switch to entry `index` now (Main.cpp does it at the end of the frame the selection changed). */
function switchTo(index: number): void {
  const next = entries[index];
  let created: Test;
  try {
    created = createTest(next);
  } catch (error) {
    report(error, `${next.name} could not be created`);
    testSelection = testIndex;
    testList.value = String(testIndex);
    return;
  }
  if (savedStepSettings !== null) {
    applyStepSettings(savedStepSettings);
    savedStepSettings = null;
  }
  test = created;
  testIndex = testSelection = index;
  entry = next;
  const override = test.StepSettingsOverride();
  if (override !== null) {
    savedStepSettings = { ...settings, hz: settingsHz } as StepSettings;
    applyStepSettings(override);
  }
  viewZoom = 1.0;
  settings.viewCenter.x = 0.0;
  settings.viewCenter.y = 20.0;
  const view = test.InitialView();
  if (view !== null) {
    settings.viewCenter.x = view.x;
    settings.viewCenter.y = view.y;
    viewZoom = view.zoom;
  }
  testList.value = String(index);
  refreshControls();
  showMessage('');
  putOnBackend();
}

/** Puts the current test on the chosen backend, and the choice into the URL. */
function putOnBackend(): void {
  const params = new URLSearchParams({ test: entry.name, backend: backends.chosen });
  if (location.search !== `?${params}` || location.hash !== '') history.replaceState(null, '', `?${params}`);
  backends.apply(test).then(refreshBackend, (error) => {
    report(error, `${entry.name} could not be put on WebGPU`);
    refreshBackend();
  });
}

/** Main.cpp's Restart: a new instance of the same test, the view kept. */
function restart(): void {
  try {
    test = createTest(entry);
  } catch (error) {
    report(error, `${entry.name} could not be created`);
    return;
  }
  putOnBackend();
}

/**
 * Main.cpp's SimulationLoop: one frame. On WebGPU a frame waits while the previous frame's
 * synchronisation (or a backend switch) runs: it is skipped, and counted.
 */
function simulationLoop(): void {
  if (backends.busy) {
    backends.skippedFrames++;
    return;
  }
  syncView();
  // A large world on WebGPU is drawn under the 2D canvas (TestbedBackend).
  const onGpu = backends.drawsOnGpu(test);
  draw.transparent = onGpu;
  gpuCanvas.hidden = !onGpu;
  draw.BeginFrame();
  test.SetTextLine(30);
  settings.hz = settingsHz;
  backends.beforeStep(test, settings);
  try {
    test.Step(settings);
  } catch (error) {
    report(error, `${entry.name} threw in Step`);
  }
  backends.afterStep(test);
  if (settings.drawStats) {
    for (const line of backends.describe(performance.now())) {
      draw.DrawString(5, test.m_textLine, line);
      test.m_textLine += 15;
    }
  }
  test.DrawTitle(5, 15, entry.name);
  draw.EndFrame();
  ++frameCount;
  refreshPauseButton();

  if (testSelection !== testIndex) {
    switchTo(testSelection);
  }
}

// The frame timer: Main.cpp redisplays every 16 ms (framePeriod), one Step per frame.
let autoRun = true;
let lastFrame = -Infinity;
function tick(now: number): void {
  requestAnimationFrame(tick);
  if (!autoRun || now - lastFrame < 1000 / 60 - 4) return;
  lastFrame = now;
  simulationLoop();
  publish(now);
  if (now - lastNote > 500) {
    lastNote = now;
    refreshBackend();
  }
}
let lastNote = 0;

// ---- The panel (Main.cpp's GLUI subwindow) ----

function fillTestList(): void {
  testList.textContent = '';
  const groups = new Map<string, HTMLOptGroupElement>();
  const labels: Record<string, string> = {
    Testbed: 'Box2D 2.2.1 Testbed',
    Benchmarks: 'Benchmark scenes',
    Files: 'Loaded files',
  };
  entries.forEach((e, i) => {
    const group = e.group ?? 'Testbed';
    let element = groups.get(group);
    if (element === undefined) {
      element = document.createElement('optgroup');
      element.label = labels[group] ?? group;
      groups.set(group, element);
      testList.append(element);
    }
    const option = document.createElement('option');
    option.value = String(i);
    option.textContent = e.name;
    element.append(option);
  });
  testList.value = String(testIndex);
}

const numberInputs: [HTMLInputElement, () => number, (v: number) => void, number, number][] = [
  [$('velocityIterations'), () => settings.velocityIterations, (v) => (settings.velocityIterations = v), 1, 500],
  [$('positionIterations'), () => settings.positionIterations, (v) => (settings.positionIterations = v), 0, 100],
  [$('hz'), () => settingsHz, (v) => (settingsHz = v), 5, 200],
];
const checkboxes = Array.from(document.querySelectorAll<HTMLInputElement>('input[data-setting]'));

function refreshControls(): void {
  for (const [input, get] of numberInputs) input.value = String(get());
  for (const box of checkboxes) box.checked = (settings as unknown as Record<string, number>)[box.dataset.setting!] !== 0;
  refreshPauseButton();
}

function refreshPauseButton(): void {
  const button = $<HTMLButtonElement>('pause');
  const paused = settings.pause !== 0;
  if (button.getAttribute('aria-pressed') !== String(paused)) {
    button.setAttribute('aria-pressed', String(paused));
    button.textContent = paused ? 'Resume' : 'Pause';
  }
}

for (const [input, , set, lo, hi] of numberInputs) {
  input.addEventListener('change', () => {
    const value = Number(input.value);
    if (Number.isFinite(value)) set(Math.min(hi, Math.max(lo, input.id === 'hz' ? value : Math.round(value))));
    refreshControls();
  });
}
for (const box of checkboxes) {
  box.addEventListener('change', () => {
    (settings as unknown as Record<string, number>)[box.dataset.setting!] = box.checked ? 1 : 0;
    // Keys go back to the testbed (space would toggle the box instead of launching a bomb).
    box.blur();
    canvas.focus();
  });
}
testList.addEventListener('change', () => {
  testSelection = Number(testList.value);
  testList.blur();
  canvas.focus();
  if (!autoRun) switchTo(testSelection);
});
const button = (id: string, action: () => void) =>
  $<HTMLButtonElement>(id).addEventListener('click', (event) => {
    action();
    (event.currentTarget as HTMLButtonElement).blur();
    canvas.focus();
  });
button('pause', () => {
  settings.pause = settings.pause ? 0 : 1;
  refreshPauseButton();
});
button('single-step', () => {
  settings.pause = 1;
  settings.singleStep = 1;
  refreshPauseButton();
});
button('restart', restart);

// ---- Keyboard and mouse (Main.cpp's Keyboard, KeyboardSpecial, Mouse, MouseMotion, MouseWheel) ----

function isEditable(target: EventTarget | null): boolean {
  return target instanceof HTMLInputElement || target instanceof HTMLSelectElement || target instanceof HTMLTextAreaElement;
}

function resetView(): void {
  viewZoom = 1.0;
  settings.viewCenter.x = 0.0;
  settings.viewCenter.y = 20.0;
}

window.addEventListener('keydown', (event) => {
  if (isEditable(event.target) || event.ctrlKey || event.metaKey || event.altKey) return;
  const key = event.key;
  let handled = true;
  switch (key) {
    case 'z': // Press 'z' to zoom out.
      viewZoom = Math.min(1.1 * viewZoom, 20.0);
      break;
    case 'x': // Press 'x' to zoom in.
      viewZoom = Math.max(0.9 * viewZoom, 0.02);
      break;
    case 'r': // Press 'r' to reset.
      restart();
      break;
    case ' ': // Press space to launch a bomb.
      test.LaunchBomb();
      break;
    case 'p':
      settings.pause = settings.pause ? 0 : 1;
      break;
    case '[': // Press [ to prev test.
      testSelection = testSelection - 1 < 0 ? entries.length - 1 : testSelection - 1;
      testList.value = String(testSelection);
      break;
    case ']': // Press ] to next test.
      testSelection = testSelection + 1 >= entries.length ? 0 : testSelection + 1;
      testList.value = String(testSelection);
      break;
    case 'ArrowLeft':
      settings.viewCenter.x -= 0.5;
      break;
    case 'ArrowRight':
      settings.viewCenter.x += 0.5;
      break;
    case 'ArrowDown':
      settings.viewCenter.y -= 0.5;
      break;
    case 'ArrowUp':
      settings.viewCenter.y += 0.5;
      break;
    case 'Home':
      resetView();
      break;
    default:
      handled = key.length === 1;
      if (handled) {
        try {
          test.Keyboard(key);
        } catch (error) {
          report(error, `${entry.name} threw in Keyboard('${key}')`);
        }
      }
  }
  if (handled) event.preventDefault();
  if (!autoRun && (key === '[' || key === ']')) switchTo(testSelection);
});

window.addEventListener('keyup', (event) => {
  if (isEditable(event.target) || event.key.length !== 1) return;
  try {
    test.KeyboardUp(event.key);
  } catch (error) {
    report(error, `${entry.name} threw in KeyboardUp('${event.key}')`);
  }
});

function eventToWorld(event: MouseEvent): b2Vec2 {
  const rect = canvas.getBoundingClientRect();
  syncView();
  return draw.ConvertScreenToWorld(event.clientX - rect.left, event.clientY - rect.top);
}

let leftDown = false;
let rightDown = false;
const lastp = new b2Vec2();

canvas.addEventListener('pointerdown', (event) => {
  canvas.focus();
  canvas.setPointerCapture(event.pointerId);
  const p = eventToWorld(event);
  if (event.button === 0) {
    leftDown = true;
    if (event.shiftKey) test.ShiftMouseDown(p);
    else test.MouseDown(p);
  } else if (event.button === 2) {
    lastp.Assign(p);
    rightDown = true;
  }
  event.preventDefault();
});

canvas.addEventListener('pointermove', (event) => {
  // GLUT's motion callback: only while a button is held.
  if (!leftDown && !rightDown) return;
  const p = eventToWorld(event);
  test.MouseMove(p);
  if (rightDown) {
    settings.viewCenter.x -= p.x - lastp.x;
    settings.viewCenter.y -= p.y - lastp.y;
    lastp.Assign(eventToWorld(event));
  }
});

canvas.addEventListener('pointerup', (event) => {
  const p = eventToWorld(event);
  if (event.button === 0 && leftDown) {
    leftDown = false;
    test.MouseUp(p);
  } else if (event.button === 2) {
    rightDown = false;
  }
});

canvas.addEventListener('contextmenu', (event) => event.preventDefault());

canvas.addEventListener(
  'wheel',
  (event) => {
    event.preventDefault();
    if (event.deltaY < 0) viewZoom /= 1.1;
    else if (event.deltaY > 0) viewZoom *= 1.1;
  },
  { passive: false },
);

// ---- b2dJson files: dropped on the page or opened ----

function loadJson(text: string, name: string): boolean {
  try {
    JsonScene.FromText(text);
  } catch (error) {
    const message = error instanceof Error ? error.message : String(error);
    console.warn(`${name} is not a b2dJson scene:`, error);
    showMessage(`${name} is not a b2dJson scene: ${message}`, 'warn');
    return false;
  }
  entries.push({ name: `File: ${name}`, group: 'Files', createFcn: () => JsonScene.FromText(text) });
  fillTestList();
  testSelection = entries.length - 1;
  switchTo(entries.length - 1);
  return true;
}

const dropHint = $<HTMLDivElement>('drop-hint');
window.addEventListener('dragover', (event) => {
  event.preventDefault();
  dropHint.hidden = false;
});
window.addEventListener('dragleave', (event) => {
  if (event.relatedTarget === null) dropHint.hidden = true;
});
window.addEventListener('drop', (event) => {
  event.preventDefault();
  dropHint.hidden = true;
  const file = event.dataTransfer?.files[0];
  if (file !== undefined) void file.text().then((text) => loadJson(text, file.name));
});
$<HTMLInputElement>('open-json').addEventListener('change', (event) => {
  const input = event.currentTarget as HTMLInputElement;
  const file = input.files?.[0];
  if (file !== undefined) void file.text().then((text) => loadJson(text, file.name));
  input.value = '';
  canvas.focus();
});

// ---- Backends: the JavaScript engine, or WebGPU where the browser has an adapter ----

const webgpu = detectWebGpu().then((status) => {
  const message =
    status.name !== null
      ? `This browser has WebGPU (adapter: ${status.name}). Choose the WebGPU backend above to step the tests on it.`
      : `${status.reason}. The JavaScript backend runs everything.`;
  webgpuStatus.textContent = message;
  webgpuStatus.className = `note ${status.adapter ? 'ok' : 'warn'}`;
  document.body.dataset.webgpu = status.adapter ? 'adapter' : status.api ? 'no-adapter' : 'none';
  backendList.querySelector<HTMLOptionElement>('option[value="webgpu"]')!.disabled = !status.adapter;
  return status;
});

/** Steps the current test on `name` from now on; resolves with what steps it (a refused test stays on JavaScript). */
async function chooseBackend(name: BackendName): Promise<BackendName> {
  const status = await webgpu;
  if (name === 'webgpu' && !status.adapter) {
    showMessage(`WebGPU is not available here (${status.reason}); the JavaScript engine runs.`, 'warn');
    name = 'js';
  }
  backends.chosen = name;
  backendList.value = name;
  putOnBackend();
  await backends.idle();
  return backends.active;
}

backendList.addEventListener('change', () => {
  void chooseBackend(backendList.value as BackendName);
  backendList.blur();
  canvas.focus();
});

/** The panel's note: what steps the test, and what the WebGPU backend's read-back costs. */
function refreshBackend(): void {
  backendList.value = backends.chosen;
  let text = '';
  if (backends.chosen === 'webgpu' && backends.active === 'js' && backends.refusal !== null) {
    text = `${entry.name} runs on the JavaScript engine: ${backends.refusal}.`;
  } else if (backends.active === 'webgpu') {
    const read = backends.readStats;
    text =
      `Stepping on WebGPU (${backends.adapter}). Each frame reads the world back once (world.Synchronize: positions, ` +
      `velocities, contact events)${read === null ? '' : `: ${(read.bytes / 1024).toFixed(1)} KB, ${read.unpackMs.toFixed(2)} ms on the host to unpack and ${read.pullMs.toFixed(2)} ms to update the bodies drawn`}; ` +
      (backends.drawsOnGpu(test)
        ? "this large world is drawn from the GPU's own buffers after each step (GpuRenderer): no body is read back to draw it. "
        : 'the drawing is one step behind the GPU. ') +
      `${backends.skippedFrames} frames skipped while a read-back ran.`;
  }
  backendNote.textContent = text;
  backendNote.className = `note ${backends.refusal !== null ? 'warn' : ''}`;
  backendNote.hidden = text === '';
}

// ---- window.webphysicsDemo: the state every demo page publishes ----

window.webphysicsDemo = { ready: false, panes: [] };

function publish(now: number): void {
  const pane: DemoPane = {
    backend: backends.active,
    adapter: backends.active === 'webgpu' ? backends.adapter : null,
    bodies: test.m_world.GetBodyCount(),
    steps: test.m_stepCount,
    stepMs: backends.times.median(now),
  };
  window.webphysicsDemo.panes = [pane];
  window.webphysicsDemo.ready = frameCount > 0;
}

// ---- Hooks for tests and the console ----

const bodyTypeNames = new Map([
  [b2_staticBody, 'static'],
  [b2_kinematicBody, 'kinematic'],
  [b2_dynamicBody, 'dynamic'],
]);

const hooks = {
  /** The test list: names and groups. */
  entries: () => entries.map((e) => ({ name: e.name, group: e.group ?? 'Testbed' })),
  /** Switch to a test by name now; false when there is none of that name. */
  select(name: string): boolean {
    const index = entries.findIndex((e) => e.name === name);
    if (index < 0) return false;
    testSelection = index;
    switchTo(index);
    return entry.name === name;
  },
  /** Start or stop the frame timer (the tests drive frames with frame()). */
  setAutoRun(flag: boolean): void {
    autoRun = flag;
  },
  /** Run n frames now (each one Step of the test and a redraw). */
  frame(n = 1): void {
    for (let i = 0; i < n; ++i) simulationLoop();
    publish(performance.now());
    refreshBackend();
  },
  /** Run n frames, each after the previous one's synchronisation (WebGPU) is done. */
  async frameAsync(n = 1): Promise<void> {
    for (let i = 0; i < n; ++i) {
      await backends.idle();
      simulationLoop();
    }
    await backends.idle();
    publish(performance.now());
    refreshBackend();
  },
  /** Choose the backend; resolves with what steps the current test. */
  setBackend: chooseBackend,
  /** The backend chosen, the one stepping the test, and why they differ. */
  backend: () => ({
    chosen: backends.chosen,
    active: backends.active,
    refusal: backends.refusal,
    adapter: backends.adapter,
    drawsOnGpu: backends.drawsOnGpu(test),
  }),
  /** Bodies that have fetched the last synchronisation's state (on WebGPU, a body fetches it when read). */
  fetchedBodies() {
    const world = test.m_world;
    let fetched = 0;
    for (let b = world.m_bodyList; b !== null; b = b.m_next) if (b.m_stateEpoch === world.m_stateEpoch) fetched++;
    return fetched;
  },
  settings,
  /** The current test and its world. */
  state() {
    const world = test.m_world;
    return {
      name: entry.name,
      frames: frameCount,
      stepCount: test.m_stepCount,
      bodyCount: world.GetBodyCount(),
      jointCount: world.GetJointCount(),
      contactCount: world.GetContactCount(),
      mouseJoint: test.m_mouseJoint !== null,
      bomb: test.m_bomb !== null,
      viewCenter: { ...settings.viewCenter },
      viewZoom,
    };
  },
  /** The world's bodies (list order): position, angle, velocity, type and flags. */
  bodies() {
    const out = [];
    for (let b = test.m_world.GetBodyList(); b !== null; b = b.GetNext()) {
      const p = b.GetPosition();
      const v = b.GetLinearVelocity();
      out.push({
        x: p.x,
        y: p.y,
        angle: b.GetAngle(),
        vx: v.x,
        vy: v.y,
        type: bodyTypeNames.get(b.GetType()),
        awake: b.IsAwake(),
        bullet: b.IsBullet(),
        fixtures: b.GetFixtureList() !== null,
      });
    }
    return out;
  },
  /** Page (client) coordinates of a world point, for synthetic mouse events. */
  worldToClient(x: number, y: number) {
    syncView();
    const rect = canvas.getBoundingClientRect();
    const s = draw.ConvertWorldToScreen({ x, y });
    return { x: rect.left + s.x, y: rect.top + s.y };
  },
  /** Canvas pixels that differ from the background, outside this frame's text. */
  drawnPixels: () => draw.CountDrawnPixels(),
  /** The lines of text drawn in the last frame. */
  text: () => draw.texts.slice(),
  loadJson,
  sceneDigests,
  webgpu,
  errors,
};

declare global {
  interface Window {
    testbed: typeof hooks;
  }
}
window.testbed = hooks;

// ---- Start ----

fillTestList();
refreshControls();
{
  // ?test=NAME&backend=js|webgpu, or the older #NAME.
  const params = new URLSearchParams(location.search);
  const wanted = params.get('test') ?? decodeURIComponent(location.hash.slice(1));
  const index = entries.findIndex((e) => e.name === wanted);
  const backend = params.get('backend');
  if (backend !== null && !(BACKEND_NAMES as readonly string[]).includes(backend)) {
    report(new Error(`backend must be one of ${BACKEND_NAMES.join(', ')}; got "${backend}"`), 'URL');
  }
  testSelection = index >= 0 ? index : 0;
  switchTo(testSelection);
  if (wanted !== '' && index < 0) showMessage(`URL: no test named "${wanted}"; showing ${entry.name}.`, 'warn');
  if (backend === 'webgpu') void chooseBackend('webgpu');
}
requestAnimationFrame(tick);
canvas.focus();
