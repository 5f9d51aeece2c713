/*
 * The accuracy page (accuracy.html): a study's results (accuracy.json, or accuracy-h100.json where
 * the GPU's runs are timed; copied beside the page from bench/results/accuracy when the demos are
 * built) drawn as one chart per scene and measure, a tooltip naming the method under the pointer,
 * and a replay of the chosen method's run of the scene that measures it again in the page.
 * ?study=&scene=&measure=&method= select them.
 * `window.webphysicsAccuracy` is the state tests read.
 */

import { $ } from '../framework/demo';
import { MEASURE_UNITS, formatNumber, labelOf as resultLabel } from '../../bench/accuracy/report.mjs';
import type { AccuracyRun, AccuracyScene } from '../../bench/accuracy/run.mjs';
import { ParetoChart } from './chart';
import { replay } from './replay';
import type { ReplayState } from './replay';

export interface AccuracyPageState {
  ready: boolean;
  error: string | null;
  /** The study's file. */
  study: string;
  scene: string;
  measure: string;
  /** The chart's points in CSS pixels of the chart canvas. */
  points: { key: string; x: number; y: number; front: boolean }[];
  /** The tooltip's text, empty when hidden. */
  tip: string;
  replay: ReplayState | null;
  /** The study's measures for the replayed scene and method. */
  expected: Record<string, number> | null;
}

declare global {
  interface Window {
    webphysicsAccuracy: AccuracyPageState;
  }
}

const state: AccuracyPageState = { ready: false, error: null, study: '', scene: '', measure: '', points: [], tip: '', replay: null, expected: null };
window.webphysicsAccuracy = state;

const studySelect = $<HTMLSelectElement>('study');
const sceneSelect = $<HTMLSelectElement>('scene');
const measureSelect = $<HTMLSelectElement>('measure');
const methodSelect = $<HTMLSelectElement>('method');
const about = $<HTMLParagraphElement>('about');
const tip = $<HTMLDivElement>('tip');
const chartCanvas = $<HTMLCanvasElement>('chart');
const worldCanvas = $<HTMLCanvasElement>('world');
const replayButton = $<HTMLButtonElement>('replay');
const replayResult = $<HTMLParagraphElement>('replay-result');
const chart = new ParetoChart(chartCanvas);

let run: AccuracyRun | null = null;
let stopReplay: (() => void) | null = null;

const labelOf = (method: string, backend: string) => resultLabel(run!, { key: method, method, backend, msPerSecond: null, measures: {} });

function currentScene(): AccuracyScene {
  return run!.scenes.find((s) => s.id === sceneSelect.value)!;
}

/** The results the page can replay: the JavaScript engine's, and the WebGPU backend's where this browser has WebGPU. */
function replayable(scene: AccuracyScene) {
  const gpu = 'gpu' in navigator && navigator.gpu !== undefined;
  return scene.results.filter((r) => r.backend === 'js' || (gpu && r.backend === 'webgpu'));
}

function fillMeasures(scene: AccuracyScene, wanted: string | null): void {
  measureSelect.replaceChildren(...scene.measures.map((m) => new Option(m, m)));
  if (wanted !== null && scene.measures.includes(wanted)) measureSelect.value = wanted;
  const results = replayable(scene);
  const previous = methodSelect.value;
  methodSelect.replaceChildren(...results.map((r) => new Option(labelOf(r.method, r.backend), r.key)));
  if (results.some((r) => r.key === previous)) methodSelect.value = previous;
}

function drawChart(): void {
  const scene = currentScene();
  const measure = measureSelect.value;
  chart.draw(scene, measure, MEASURE_UNITS[measure as keyof typeof MEASURE_UNITS] ?? '');
  state.scene = scene.id;
  state.measure = measure;
  state.points = chart.points.map((p) => ({ key: p.result.key, x: p.x, y: p.y, front: p.front }));
  const url = new URL(location.href);
  url.searchParams.set('study', studySelect.value);
  url.searchParams.set('scene', scene.id);
  url.searchParams.set('measure', measure);
  history.replaceState(null, '', url);
}

function showTip(event: MouseEvent): void {
  const rect = chartCanvas.getBoundingClientRect();
  const p = chart.pointAt(event.clientX - rect.left, event.clientY - rect.top);
  if (p === null) {
    tip.hidden = true;
    state.tip = '';
    return;
  }
  const r = p.result;
  state.tip = `${labelOf(r.method, r.backend)}: ${formatNumber(r.msPerSecond!)} ms per simulated second, ${measureSelect.value} ${formatNumber(r.measures[measureSelect.value])}${p.front ? ' (on the Pareto front)' : ''}`;
  tip.textContent = state.tip;
  tip.hidden = false;
  tip.style.left = `${Math.min(p.x + 12, rect.width - tip.offsetWidth - 4)}px`;
  tip.style.top = `${p.y + 12}px`;
}

function startReplay(): void {
  stopReplay?.();
  stopReplay = null;
  const scene = currentScene();
  const result = scene.results.find((r) => r.key === methodSelect.value)!;
  const gpu = result.backend === 'webgpu';
  const label = labelOf(result.method, result.backend);
  state.expected = result.measures;
  state.replay = null;
  replayResult.textContent = 'Running…';
  const onFrame = (s: ReplayState) => {
    state.replay = { ...s, measures: s.measures === null ? null : { ...s.measures } };
    if (!s.done) {
      replayResult.textContent = `${label}: ${((s.frame / s.frames) * 100).toFixed(0)} % of ${scene.seconds} s`;
      return;
    }
    const same = Object.entries(s.measures!).every(([k, v]) => Object.is(v, result.measures[k]));
    // The GPU's numbers are this device's; the study's came from its own adapter, through Dawn in Node.
    const studyGpu = run!.machine.gpu as { description?: string; device?: string } | null;
    const verdict = same
      ? 'the same as the study, bit for bit'
      : gpu
        ? `on this device; the study measured it on ${studyGpu?.description || studyGpu?.device || 'another adapter'}`
        : "NOT the study's numbers";
    replayResult.textContent = `${label}: ${Object.entries(s.measures!)
      .map(([k, v]) => `${k} ${formatNumber(v)}`)
      .join(', ')}; ${verdict}`;
  };
  const onError = (e: unknown) => {
    state.error = e instanceof Error ? e.message : String(e);
    replayResult.textContent = `The replay stopped: ${state.error}`;
  };
  replay(scene.id, result.method, gpu, worldCanvas, onFrame, onError).then((stop) => (stopReplay = stop), onError);
}

/** Loads the study chosen in studySelect and shows it, keeping the scene, measure and method where it has them. */
async function loadStudy(wanted: { scene: string | null; measure: string | null; method: string | null }): Promise<void> {
  state.ready = false;
  const file = studySelect.value;
  const response = await fetch(file);
  if (!response.ok) throw new Error(`${file}: ${response.status} ${response.statusText} (npm run bench:accuracy writes it)`);
  run = (await response.json()) as AccuracyRun;
  state.study = file;
  sceneSelect.replaceChildren(...run.scenes.map((s) => new Option(s.title, s.id)));
  if (wanted.scene !== null && run.scenes.some((s) => s.id === wanted.scene)) sceneSelect.value = wanted.scene;
  fillMeasures(currentScene(), wanted.measure);
  if (wanted.method !== null && Array.from(methodSelect.options).some((o) => o.value === wanted.method)) methodSelect.value = wanted.method;
  const gpu = run.machine.gpu as { description?: string; device?: string; software?: boolean } | null;
  about.textContent = `The study of ${run.date.slice(0, 10)}: ${run.scenes.length} scenes, ${run.methods.length} methods; JavaScript engine timed on ${run.machine.cpus} x ${run.machine.cpuModel}, Node ${run.machine.node}${gpu ? `; WebGPU on ${gpu.description || gpu.device}${gpu.software ? ' (software: errors only, not timed)' : ' (timed)'}` : ''}.`;
  about.className = 'note';
  drawChart();
  state.ready = true;
}

function failed(e: unknown): void {
  state.error = e instanceof Error ? e.message : String(e);
  about.textContent = `Could not load the study: ${state.error}`;
  about.className = 'note warn';
}

async function main(): Promise<void> {
  const params = new URLSearchParams(location.search);
  const wantedStudy = params.get('study');
  if (wantedStudy !== null && Array.from(studySelect.options).some((o) => o.value === wantedStudy)) studySelect.value = wantedStudy;
  await loadStudy({ scene: params.get('scene'), measure: params.get('measure'), method: params.get('method') });
  studySelect.addEventListener('change', () => {
    loadStudy({ scene: sceneSelect.value, measure: measureSelect.value, method: methodSelect.value }).catch(failed);
  });
  sceneSelect.addEventListener('change', () => {
    fillMeasures(currentScene(), measureSelect.value);
    drawChart();
  });
  measureSelect.addEventListener('change', drawChart);
  chartCanvas.addEventListener('mousemove', showTip);
  chartCanvas.addEventListener('mouseleave', () => {
    tip.hidden = true;
    state.tip = '';
  });
  replayButton.addEventListener('click', startReplay);
  window.addEventListener('resize', drawChart);
}

main().catch(failed);
