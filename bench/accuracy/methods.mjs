// The methods the accuracy study compares (docs/ACCURACY.md, "Methods"): how a world is stepped
// through one frame of simulated time. A frame is 1 / frameHz seconds, taken in `substeps` equal
// steps of velocityIterations / positionIterations, with or without warm starting.

/** One method: the settings a world is stepped with. */
function method(id, label, settings) {
  return { id, label, frameHz: 60, substeps: 1, velocityIterations: 8, positionIterations: 3, warmStarting: true, ...settings };
}

/** The JavaScript engine's methods. */
export const METHODS = [
  method('iter-1-1', '1/1 iterations', { velocityIterations: 1, positionIterations: 1 }),
  method('iter-2-1', '2/1 iterations', { velocityIterations: 2, positionIterations: 1 }),
  method('iter-4-2', '4/2 iterations', { velocityIterations: 4, positionIterations: 2 }),
  method('iter-8-3', '8/3 iterations (Box2D default)', {}),
  method('iter-16-6', '16/6 iterations', { velocityIterations: 16, positionIterations: 6 }),
  method('iter-32-12', '32/12 iterations', { velocityIterations: 32, positionIterations: 12 }),
  method('no-warm-start', '8/3, no warm starting', { warmStarting: false }),
  method('dt-30', '8/3 at 30 Hz', { frameHz: 30 }),
  method('substeps-2', '8/3, 2 substeps', { substeps: 2 }),
  method('substeps-4', '8/3, 4 substeps', { substeps: 4 }),
  method('substeps-8', '8/3, 8 substeps', { substeps: 8 }),
];

/** The converged reference of the trajectory error: 1/960 s steps and 100 iterations of each kind. */
export const REFERENCE = method('reference', 'reference: 1/960 s, 100/100 iterations', { substeps: 16, velocityIterations: 100, positionIterations: 100 });

/** The method the stability limits vary one setting of. */
export const DEFAULT_METHOD = METHODS.find((m) => m.id === 'iter-8-3');

/** A method by id; throws naming the known ones. */
export function methodById(id) {
  const m = METHODS.find((x) => x.id === id);
  if (!m) throw new RangeError(`unknown method '${id}': ${METHODS.map((x) => x.id).join(', ')}`);
  return m;
}

/**
 * Applies a method's world-wide settings (warm starting), with sleeping off: a body put to sleep
 * stops moving and costing, which would hide both the error and the cost of keeping it at rest.
 */
export function applyMethod(world, m) {
  world.SetWarmStarting(m.warmStarting);
  world.SetAllowSleeping(false);
}

/** Steps `world` through one frame of `m`. */
export function stepFrame(world, m) {
  const dt = 1 / (m.frameHz * m.substeps);
  for (let k = 0; k < m.substeps; ++k) world.Step(dt, m.velocityIterations, m.positionIterations);
}
