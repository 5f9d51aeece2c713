// Types for bench/accuracy/scenes.mjs.
import type { b2Body } from '../../src/dynamics/b2Body';
import type { b2World } from '../../src/dynamics/b2World';

/** What a scene reports while it runs: sample(t) after every frame, result() once at the end. */
export interface AccuracyProbe {
  sample(t: number): void;
  result(): Record<string, number>;
}

export interface AccuracySceneDef {
  title: string;
  seconds: number;
  /** Measured against the converged reference's final positions (trajectory error). */
  trajectory?: boolean;
  /** `b2`: the engine's exports. */
  build(b2: unknown): { world: b2World; probe: AccuracyProbe };
}

export const ACCURACY_SCENES: Record<'stack' | 'pyramid' | 'chain' | 'pendulum' | 'bounce' | 'slide' | 'elastic' | 'drop', AccuracySceneDef>;
export const ACCURACY_SCENE_IDS: string[];
export function buildStack(b2: unknown, height: number): { world: b2World; boxes: b2Body[] };
export function buildPyramid(b2: unknown, base: number): { world: b2World; boxes: b2Body[] };
export function buildChain(b2: unknown, links: number, ratio?: number): { world: b2World; bodies: b2Body[] };
