// Types for bench/accuracy/scenes.mjs.
import type { b2World } from '../../src/dynamics/b2World';

/** What a probe reads: positions by body index (any engine's adapter), and a Box2D 2.2.1 world where there is one. */
export interface SceneView {
  position(index: number): [number, number] | null;
  world: b2World | null;
  /** The engine's exports, with `world`. */
  b2: unknown;
}

/** What a scene reports while it runs: sample(t) after every frame, result() once at the end. */
export interface AccuracyProbe {
  sample(t: number): void;
  result(): Record<string, number>;
}

/** A scene in the benchmark's format (bench/scenes.mjs). */
export interface SceneData {
  id: string;
  title: string;
  gravity: [number, number];
  dt: number;
  velocityIterations: number;
  positionIterations: number;
  bodies: object[];
  joints: object[];
}

export interface AccuracySceneDef {
  title: string;
  seconds: number;
  /** Measured against the converged reference's final positions (trajectory error). */
  trajectory?: boolean;
  /** Measured on a Box2D 2.2.1 world only: the peers do not run it. */
  worldOnly?: boolean;
  /** Where the accuracy page's replay looks (centre and half the height, in metres), when framing the bodies at the start would not do. */
  view?: { x: number; y: number; half: number };
  data(): SceneData;
  probe(view: SceneView): AccuracyProbe;
}

export type AccuracySceneId = 'stack' | 'pyramid' | 'chain' | 'mechanisms' | 'projectile' | 'pendulum' | 'bounce' | 'slide' | 'elastic' | 'collide' | 'drop';
export const ACCURACY_SCENES: Record<AccuracySceneId, AccuracySceneDef>;
export const ACCURACY_SCENE_IDS: AccuracySceneId[];
export function stackData(height: number): SceneData;
export function pyramidData(base: number): SceneData;
export function chainData(links: number, ratio?: number): SceneData;
export function mechanismsData(): SceneData;
export function plateData(speed: number, x0: number): SceneData;
export function scenePositions(data: SceneData, view: Pick<SceneView, 'position'>): Float64Array;
export function buildScene(b2: unknown, id: AccuracySceneId): { world: b2World; data: SceneData; view: SceneView; probe: AccuracyProbe };
export function referencePositions(b2: unknown, id: AccuracySceneId): Float64Array;
