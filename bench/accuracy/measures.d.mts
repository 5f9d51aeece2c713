// Types for bench/accuracy/measures.mjs. The measures read any build of the engine through its
// public fields, so the world and its parts are typed by what they read.

/** What the measures read of a b2World (the engine's own class satisfies it). */
export type MeasuredWorld = object;

export function manifoldSeparations(manifold: object, xfA: object, xfB: object, radii: number): number[];
/** `b2`: the engine's exports (its collide functions and shapes). */
export function penetration(b2: unknown, world: MeasuredWorld): { mean: number; max: number; points: number };
export function jointError(joint: object): { linear: number; angular: number };
export function jointErrors(world: MeasuredWorld): { linear: number; angular: number; joints: number };
export function dynamicBodies(world: MeasuredWorld): object[];
export function energyAndMomentum(world: MeasuredWorld): {
  kinetic: number;
  potential: number;
  total: number;
  momentum: { x: number; y: number };
  angular: number;
};
export function rmsSpeed(world: MeasuredWorld): number;
export function trajectoryError(a: Float64Array, b: Float64Array): { max: number; rms: number };
export function restingDrift(before: Float64Array, after: Float64Array): number;
