// World heap and heap growth, each engine measured in a process of its own.
//
// Inputs: an engine id (and the WebPhysics bundles), a scene, the sleep setting and the number of
// steps the timed run gave its last world. Output: { worldBytes, heapGrowthBytes } (see
// memory.mjs for what they count), worldBytes null where it is not above zero.
//
// Why a process: several engines keep their last world reachable from module state until a world
// of theirs steps again (@box2d/core's heap stays 38 MiB above its start after a many-pyramids
// world is destroyed and an empty world is made and stepped, until the next full world steps), so
// in the benchmark's process, where each engine builds a world per round and scene, the retained
// heap after building a world counted the previous one too: heap growth came out as minus a whole
// world, and a world after a larger one as negative. A fresh process first runs the scene built
// small (quick mode), so that the engine's code is compiled and its bytecode made before the
// count, then measures an empty world, the scene's world as built, and that world after the run.
// What the engine may keep of the small world is in all three and cancels, except in the growth,
// which it can understate by that much (box2d-wasm's JavaScript side: 150-230 KiB on the pyramids,
// where its growth reads negative).
import { fileURLToPath } from 'node:url';
import { retainedHeap } from './memory.mjs';
import { runJsonChild } from './command.mjs';

/**
 * The heap a built world holds: retained heap with it built minus with an empty world of the
 * engine; null when that is not above zero (the tumbler's world starts as one body, within the
 * noise of two measurements).
 */
export function worldHeapBytes(builtHeap, baseHeap) {
  const bytes = builtHeap - baseHeap;
  return bytes > 0 ? bytes : null;
}

/**
 * Runs this file in a new Node process for one engine, scene and sleep setting, `steps` steps, and
 * returns its { worldBytes, heapGrowthBytes }; throws with the child's error output if it fails.
 */
export function measureHeapInChild({ engine, oursBundle, baselineBundle, scene, quick, sleep, steps }) {
  const args = JSON.stringify({ engine, oursBundle, baselineBundle, scene, quick, sleep, steps });
  return runJsonChild(['--expose-gc', fileURLToPath(import.meta.url), args], `heap measurement of ${engine} on ${scene}`);
}

async function main(args) {
  const { engineById } = await import('./harness.mjs');
  const { makeScene, sceneStepper } = await import('./scenes.mjs');
  const o = JSON.parse(args);
  const e = engineById(o.engine);
  const api = await e.load({ oursBundle: o.oursBundle, baselineBundle: o.baselineBundle });

  const small = makeScene(o.scene, { quick: true });
  const warm = e.create(api, small, { sleep: o.sleep });
  const warmStepper = sceneStepper(warm, small);
  for (let i = 0; i < small.quick.preroll + small.quick.steps; i++) warmStepper.step();
  warm.destroy();

  const scene = makeScene(o.scene, { quick: o.quick });
  const empty = e.create(api, { ...scene, bodies: [], joints: [], spawn: undefined }, { sleep: o.sleep });
  empty.step();
  const baseHeap = retainedHeap();
  empty.destroy();

  const w = e.create(api, scene, { sleep: o.sleep });
  const { step } = sceneStepper(w, scene);
  const builtHeap = retainedHeap();
  for (let i = 0; i < o.steps; i++) step();
  const endHeap = retainedHeap();
  w.destroy();
  process.stdout.write(`${JSON.stringify({ worldBytes: worldHeapBytes(builtHeap, baseHeap), heapGrowthBytes: endHeap - builtHeap })}\n`);
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  main(process.argv[2]).catch((err) => {
    process.stderr.write(`${err?.stack ?? err}\n`);
    process.exit(1);
  });
}
