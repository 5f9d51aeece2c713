/*
 * A pane's worker: builds the scene, steps it on the JavaScript engine or the WebGPU backend
 * (pane.ts) when the page asks, and posts every body's transform back. Stepping here keeps the page
 * responsive however long a step takes.
 */

import { GpuPane, JsPane, sceneGeometry } from './pane';
import type { FromWorker, ToWorker } from './protocol';

const scope = self as unknown as {
  onmessage: ((event: MessageEvent<ToWorker>) => void) | null;
  postMessage(message: FromWorker, transfer?: Transferable[]): void;
};

let pane: JsPane | GpuPane | null = null;

function fail(error: unknown): void {
  scope.postMessage({ type: 'error', message: error instanceof Error ? error.message : String(error) });
}

async function handle(message: ToWorker): Promise<void> {
  if (message.type === 'build') {
    const started = performance.now();
    pane = message.backend === 'js' ? new JsPane(message.config) : await GpuPane.create(message.config);
    scope.postMessage({
      type: 'built',
      geometry: sceneGeometry(pane.scene),
      stats: pane.stats,
      adapter: pane instanceof GpuPane ? pane.adapter : null,
      buildMs: performance.now() - started,
    });
    return;
  }
  if (pane === null) throw new Error('step before build');
  const { transforms, awake } = message;
  const stats = pane instanceof GpuPane ? await pane.step(transforms, awake) : pane.step(transforms, awake);
  scope.postMessage({ type: 'stepped', stats, transforms, awake }, [transforms.buffer, awake.buffer]);
}

scope.onmessage = (event) => {
  handle(event.data).catch(fail);
};
