/*
 * The comparison page's settings and the shapes of what its panes exchange, without the engine:
 * the page itself imports only this (the engine and the WebGPU backend live in the workers).
 */

export const SCENE_NAMES = ['pyramids', 'rain', 'joint-grid', 'tumbler', 'sand'] as const;
export type SceneName = (typeof SCENE_NAMES)[number];

export const SCENE_TITLES: Record<SceneName, string> = {
  pyramids: 'Pyramids',
  rain: 'Rain (circles and boxes)',
  'joint-grid': 'Joint grid',
  tumbler: 'Tumbler',
  sand: 'Sand pile',
};

/** The slider's stops: 10^2 to 2 x 10^5 bodies, three per decade. */
export const BODY_COUNTS = [100, 200, 500, 1000, 2000, 5000, 10000, 20000, 50000, 100000, 200000];
export const MIN_BODIES = BODY_COUNTS[0];
export const MAX_BODIES = BODY_COUNTS[BODY_COUNTS.length - 1];

export interface SceneConfig {
  scene: SceneName;
  /** Dynamic bodies asked for (MIN_BODIES to MAX_BODIES). */
  bodies: number;
  /** The random layout's seed (rain's jitter, sizes and velocities). */
  seed: number;
  /** b2World.SetAllowSleeping. */
  sleep: boolean;
}

/** What the camera frames first: a centre and half-extents in metres. */
export interface SceneView {
  x: number;
  y: number;
  halfWidth: number;
  halfHeight: number;
}

export const DT = 1 / 60;
export const VELOCITY_ITERATIONS = 8;
export const POSITION_ITERATIONS = 3;

/**
 * Throws a RangeError naming the field and its rule when a configuration is not one the page can
 * build (`maxBodies`: the page's own limit; the large-world page's is higher).
 */
export function checkConfig(config: SceneConfig, maxBodies = MAX_BODIES): void {
  if (!SCENE_NAMES.includes(config.scene)) {
    throw new RangeError(`scene must be one of ${SCENE_NAMES.join(', ')}; got ${JSON.stringify(config.scene)}`);
  }
  if (!Number.isInteger(config.bodies) || config.bodies < MIN_BODIES || config.bodies > maxBodies) {
    throw new RangeError(`bodies must be an integer from ${MIN_BODIES} to ${maxBodies}; got ${config.bodies}`);
  }
  if (!Number.isInteger(config.seed) || config.seed < 0 || config.seed > 0xffffffff) {
    throw new RangeError(`seed must be an integer from 0 to 2^32 - 1; got ${config.seed}`);
  }
}

/** Numbers per body in a pane's transforms: x, y, cos, sin. */
export const TRANSFORM_STRIDE = 4;

/** Fixture kinds in SceneGeometry. */
export const GEOMETRY_CIRCLE = 0;
export const GEOMETRY_POLYGON = 1;

/** The shapes of a scene's fixtures in body coordinates, for drawing from transforms alone. */
export interface SceneGeometry {
  /** Per body (scene order): 1 for a static body. */
  bodyStatic: Uint8Array;
  /** Per fixture: the index of its body. */
  fixtureBody: Int32Array;
  /** Per fixture: GEOMETRY_CIRCLE or GEOMETRY_POLYGON. */
  fixtureKind: Uint8Array;
  /** Per fixture: where its numbers start in `points`. */
  fixtureStart: Int32Array;
  /** Per fixture: a polygon's vertex count (x, y pairs in `points`); 0 for a circle (x, y, radius). */
  fixtureCount: Uint8Array;
  points: Float32Array;
  view: SceneView;
}

/** What a pane reports after each step. */
export interface PaneStats {
  steps: number;
  /** Wall time of the last step in milliseconds (pane.ts says what it covers). */
  stepMs: number;
  bodies: number;
  joints: number;
  /** The engine's contact list (b2World.GetContactCount on JavaScript; WebGPUBackend.contactCounts). */
  contacts: number;
  /** Of those, the touching ones. */
  touching: number;
  awake: number;
}
