/*
 * One pane of the comparison page without its drawing: a scene (scenes.ts) stepped by the
 * JavaScript engine (JsPane) or by the WebGPU backend through the world API (GpuPane), each step
 * writing every body's transform into a Float32Array in the scene's body order. The page runs a
 * pane in a worker (worker.ts); bench/gpu-compare.ts runs the same classes in Node to time them on
 * a real GPU.
 *
 * Step time is what an application pays per step to see its bodies move: world.Step on the
 * JavaScript engine; on the GPU world.Step (recorded and submitted) and the bulk read of every
 * transform (WebGPUBackend.readTransforms, one map), which waits for the step to finish.
 */

import type { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import type { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Shape } from '../../src/collision/shapes/b2Shape';
import { b2_staticBody } from '../../src/dynamics/b2Body';
import { WebGPUBackend } from '../../src-gpu/backend/backend';
import type { WebGPUBackendOptions } from '../../src-gpu/backend/backend';
import type { GpuAdapterSummary } from '../../src-gpu/device/device';
import { GEOMETRY_CIRCLE, GEOMETRY_POLYGON, TRANSFORM_STRIDE } from './config';
import type { PaneStats, SceneConfig, SceneGeometry } from './config';
import { buildScene } from './scenes';
import type { BuiltScene } from './scenes';

/** The geometry of a built scene's fixtures (circles and polygons, the kinds the scenes use). */
export function sceneGeometry(scene: BuiltScene): SceneGeometry {
  const kinds: number[] = [];
  const owners: number[] = [];
  const starts: number[] = [];
  const counts: number[] = [];
  const points: number[] = [];
  const bodyStatic = new Uint8Array(scene.bodies.length);
  scene.bodies.forEach((body, index) => {
    bodyStatic[index] = body.GetType() === b2_staticBody ? 1 : 0;
    for (let f = body.GetFixtureList(); f !== null; f = f.GetNext()) {
      const shape = f.GetShape();
      owners.push(index);
      starts.push(points.length);
      if (shape.GetType() === b2Shape.e_circle) {
        const c = shape as b2CircleShape;
        kinds.push(GEOMETRY_CIRCLE);
        counts.push(0);
        points.push(c.m_p.x, c.m_p.y, c.m_radius);
      } else if (shape.GetType() === b2Shape.e_polygon) {
        const p = shape as b2PolygonShape;
        kinds.push(GEOMETRY_POLYGON);
        counts.push(p.m_vertexCount);
        for (let i = 0; i < p.m_vertexCount; ++i) points.push(p.m_vertices[i].x, p.m_vertices[i].y);
      } else {
        throw new Error(`sceneGeometry: the comparison scenes draw circles and polygons, not shape type ${shape.GetType()}`);
      }
    }
  });
  return {
    bodyStatic,
    fixtureBody: Int32Array.from(owners),
    fixtureKind: Uint8Array.from(kinds),
    fixtureStart: Int32Array.from(starts),
    fixtureCount: Uint8Array.from(counts),
    points: Float32Array.from(points),
    view: scene.view,
  };
}

function checkOutputs(scene: BuiltScene, out: Float32Array, awake: Uint8Array): void {
  const n = scene.bodies.length;
  if (out.length < TRANSFORM_STRIDE * n) throw new RangeError(`out holds ${out.length} numbers; the scene needs ${TRANSFORM_STRIDE * n}`);
  if (awake.length < n) throw new RangeError(`awake holds ${awake.length} flags; the scene needs ${n}`);
}

/** The JavaScript engine stepping a scene. */
export class JsPane {
  readonly scene: BuiltScene;
  readonly stats: PaneStats;

  constructor(config: SceneConfig) {
    this.scene = buildScene(config);
    const world = this.scene.world;
    this.stats = { steps: 0, stepMs: 0, bodies: world.GetBodyCount(), joints: world.GetJointCount(), contacts: 0, touching: 0, awake: 0 };
  }

  /** One step; every body's transform into `out` and awake flag into `awake` (scene order; static bodies 0). */
  step(out: Float32Array, awake: Uint8Array): PaneStats {
    const { world, bodies, dt, velocityIterations, positionIterations } = this.scene;
    checkOutputs(this.scene, out, awake);
    const started = performance.now();
    world.Step(dt, velocityIterations, positionIterations);
    const stats = this.stats;
    stats.stepMs = performance.now() - started;
    stats.steps++;
    let awakeCount = 0;
    for (let i = 0; i < bodies.length; ++i) {
      const xf = bodies[i].m_xf;
      const at = TRANSFORM_STRIDE * i;
      out[at] = xf.p.x;
      out[at + 1] = xf.p.y;
      out[at + 2] = xf.q.c;
      out[at + 3] = xf.q.s;
      const on = bodies[i].IsAwake() && bodies[i].GetType() !== b2_staticBody ? 1 : 0;
      awake[i] = on;
      awakeCount += on;
    }
    stats.awake = awakeCount;
    stats.contacts = world.GetContactCount();
    let touching = 0;
    for (let c = world.GetContactList(); c !== null; c = c.GetNext()) if (c.IsTouching()) touching++;
    stats.touching = touching;
    stats.bodies = world.GetBodyCount();
    stats.joints = world.GetJointCount();
    return stats;
  }
}

/** The same scene stepped by the WebGPU backend through the world API. */
export class GpuPane {
  readonly scene: BuiltScene;
  readonly backend: WebGPUBackend;
  readonly stats: PaneStats;
  /** Per body (scene order): its slot in readTransforms' output. */
  private readonly slots: Int32Array;
  private readonly slotTransforms: Float32Array;
  private readonly slotAwake: Uint8Array;
  /** Per body (scene order): 1 unless static (static bodies are not counted awake). */
  private readonly dynamic: Uint8Array;

  private constructor(scene: BuiltScene, backend: WebGPUBackend) {
    this.scene = scene;
    this.backend = backend;
    const world = scene.world;
    this.slots = Int32Array.from(scene.bodies, (body) => backend.bodySlot(body));
    let slotCount = 0;
    for (const slot of this.slots) slotCount = Math.max(slotCount, slot + 1);
    this.slotTransforms = new Float32Array(TRANSFORM_STRIDE * slotCount);
    this.slotAwake = new Uint8Array(slotCount);
    this.dynamic = Uint8Array.from(scene.bodies, (body) => (body.GetType() === b2_staticBody ? 0 : 1));
    this.stats = { steps: 0, stepMs: 0, bodies: world.GetBodyCount(), joints: world.GetJointCount(), contacts: 0, touching: 0, awake: 0 };
  }

  /** Builds the scene and attaches a WebGPUBackend (options: a device, Dawn toggles...). */
  static async create(config: SceneConfig, options: WebGPUBackendOptions = {}): Promise<GpuPane> {
    const scene = buildScene(config);
    const backend = await WebGPUBackend.create(options);
    await scene.world.SetBackend(backend);
    return new GpuPane(scene, backend);
  }

  /** Frees the scene's GPU buffers; the pane cannot step afterwards. */
  destroy(): Promise<void> {
    return this.backend.destroy();
  }

  get adapter(): GpuAdapterSummary {
    return this.backend.ctx.adapterInfo;
  }

  /** One step; every body's transform and awake flag as JsPane.step gives them. */
  async step(out: Float32Array, awake: Uint8Array): Promise<PaneStats> {
    const { world, dt, velocityIterations, positionIterations } = this.scene;
    checkOutputs(this.scene, out, awake);
    const started = performance.now();
    world.Step(dt, velocityIterations, positionIterations);
    await this.backend.readTransforms(this.slotTransforms, this.slotAwake);
    const stats = this.stats;
    stats.stepMs = performance.now() - started;
    stats.steps++;
    const from = this.slotTransforms;
    const slots = this.slots;
    let awakeCount = 0;
    for (let i = 0; i < slots.length; ++i) {
      const s = TRANSFORM_STRIDE * slots[i];
      const at = TRANSFORM_STRIDE * i;
      out[at] = from[s];
      out[at + 1] = from[s + 1];
      out[at + 2] = from[s + 2];
      out[at + 3] = from[s + 3];
      const on = this.dynamic[i] & this.slotAwake[slots[i]];
      awake[i] = on;
      awakeCount += on;
    }
    stats.awake = awakeCount;
    const counts = this.backend.contactCounts;
    if (counts !== null) {
      stats.contacts = counts.contacts;
      stats.touching = counts.touching;
    }
    return stats;
  }
}
