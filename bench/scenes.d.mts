// Types for bench/scenes.mjs (see that file for the scene format).

export interface SceneShape {
  kind: 'box' | 'circle' | 'polygon' | 'edge' | 'chain';
  [field: string]: unknown;
}

export interface SceneBody {
  type: 'static' | 'kinematic' | 'dynamic';
  x: number;
  y: number;
  angle: number;
  shapes: SceneShape[];
  [field: string]: unknown;
}

export interface Scene {
  id: string;
  title: string;
  description: string;
  gravity: [number, number];
  dt: number;
  velocityIterations: number;
  positionIterations: number;
  bodies: SceneBody[];
  joints: Record<string, unknown>[];
  protocol: { preroll: number; steps: number; rounds: number; allocSteps?: number };
  quick: { preroll: number; steps: number; rounds: number };
  track: number[];
  check(before: ([number, number] | null)[], after: ([number, number] | null)[]): { ok: boolean; detail: string };
}

export const SCENE_IDS: string[];
export function goldenDir(): string;
export function makeScene(id: string, options?: { quick?: boolean }): Scene | null;
export function sceneFromB2dJson(json: unknown): SceneBody[];
export function sceneStepper(w: { step(): void; add(body: SceneBody): void }, scene: Scene): { steps: number; step(): void };
export function totalBodies(scene: Scene): number;
