/*
 * Replaying one run of the accuracy study in the page: the scene built and stepped exactly as
 * bench/accuracy/run.mjs steps it (the same scene, method and probe code), one frame of simulated
 * time per display frame, drawn as it goes; at the end the measures. On the JavaScript engine they
 * equal the study's bit for bit (the engine computes the same bits in every JavaScript engine);
 * on the WebGPU backend (`gpu`) the world is synchronised after every frame as in the study, and
 * the numbers are this device's.
 */

import * as b2 from '../../src/index';
import type { b2World } from '../../src/dynamics/b2World';
import type { b2Shape } from '../../src/collision/shapes/b2Shape';
import type { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import type { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import type { b2EdgeShape } from '../../src/collision/shapes/b2EdgeShape';
import type { b2ChainShape } from '../../src/collision/shapes/b2ChainShape';
import { ACCURACY_SCENES, buildScene, referencePositions, scenePositions } from '../../bench/accuracy/scenes.mjs';
import { applyMethod, methodById, stepFrame } from '../../bench/accuracy/methods.mjs';
import { trajectoryError } from '../../bench/accuracy/measures.mjs';
import { fitCanvas } from '../canvas';
import { WebGPUBackend } from '../../src-gpu/backend/backend';

export interface ReplayState {
  scene: string;
  method: string;
  /** Stepped by the WebGPU backend. */
  gpu: boolean;
  frame: number;
  frames: number;
  done: boolean;
  measures: Record<string, number> | null;
}

/** Draws a world's fixtures (static green, dynamic pink, as the Testbed colours them) to fit the canvas. */
function drawWorld(canvas: HTMLCanvasElement, world: b2World, view: { x: number; y: number; half: number }): void {
  const { width: w, height: h, dpr } = fitCanvas(canvas);
  const ctx = canvas.getContext('2d')!;
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  ctx.fillStyle = '#000';
  ctx.fillRect(0, 0, w, h);
  // On the WebGPU backend, every body brought to the last synchronisation first (a no-op on the engine).
  world.PullState();
  const scale = Math.min(w, h) / (2 * view.half);
  const sx = (x: number) => w / 2 + (x - view.x) * scale;
  const sy = (y: number) => h / 2 - (y - view.y) * scale;
  ctx.lineWidth = 1;
  for (let body = world.GetBodyList(); body; body = body.GetNext()) {
    const xf = body.m_xf;
    const px = (x: number, y: number) => sx(xf.q.c * x - xf.q.s * y + xf.p.x);
    const py = (x: number, y: number) => sy(xf.q.s * x + xf.q.c * y + xf.p.y);
    /** A path through the first `count` local vertices. */
    const path = (vertices: readonly { x: number; y: number }[], count: number) => {
      for (let i = 0; i < count; ++i) {
        const v = vertices[i];
        if (i === 0) ctx.moveTo(px(v.x, v.y), py(v.x, v.y));
        else ctx.lineTo(px(v.x, v.y), py(v.x, v.y));
      }
    };
    ctx.strokeStyle = body.GetType() === b2.b2_staticBody ? '#7fe57f' : '#e5b2b2';
    ctx.fillStyle = body.GetType() === b2.b2_staticBody ? 'rgba(127,229,127,0.25)' : 'rgba(229,178,178,0.25)';
    for (let f = body.GetFixtureList(); f; f = f.GetNext()) {
      const shape: b2Shape = f.GetShape();
      ctx.beginPath();
      switch (shape.m_type) {
        case b2.b2Shape.e_circle: {
          const c = shape as b2CircleShape;
          const cx = px(c.m_p.x, c.m_p.y);
          const cy = py(c.m_p.x, c.m_p.y);
          ctx.arc(cx, cy, c.m_radius * scale, 0, 2 * Math.PI);
          ctx.moveTo(cx, cy);
          ctx.lineTo(px(c.m_p.x + c.m_radius, c.m_p.y), py(c.m_p.x + c.m_radius, c.m_p.y));
          break;
        }
        case b2.b2Shape.e_polygon: {
          const p = shape as b2PolygonShape;
          path(p.m_vertices, p.m_vertexCount);
          ctx.closePath();
          break;
        }
        case b2.b2Shape.e_edge: {
          const e = shape as b2EdgeShape;
          ctx.moveTo(px(e.m_vertex1.x, e.m_vertex1.y), py(e.m_vertex1.x, e.m_vertex1.y));
          ctx.lineTo(px(e.m_vertex2.x, e.m_vertex2.y), py(e.m_vertex2.x, e.m_vertex2.y));
          break;
        }
        case b2.b2Shape.e_chain: {
          const c = shape as b2ChainShape;
          path(c.m_vertices, c.m_count);
          break;
        }
      }
      if (shape.m_type === b2.b2Shape.e_circle || shape.m_type === b2.b2Shape.e_polygon) ctx.fill();
      ctx.stroke();
    }
  }
  // Joints as the Testbed draws them: body A's origin to its anchor, body B's anchor to its origin.
  ctx.strokeStyle = '#80cccc';
  ctx.beginPath();
  for (let joint = world.GetJointList(); joint; joint = joint.GetNext()) {
    const pA = joint.GetBodyA().GetPosition();
    const pB = joint.GetBodyB().GetPosition();
    const a = joint.GetAnchorA(new b2.b2Vec2());
    const b = joint.GetAnchorB(new b2.b2Vec2());
    ctx.moveTo(sx(pA.x), sy(pA.y));
    ctx.lineTo(sx(a.x), sy(a.y));
    ctx.moveTo(sx(b.x), sy(b.y));
    ctx.lineTo(sx(pB.x), sy(pB.y));
  }
  ctx.stroke();
}

/** The view that frames the dynamic bodies (at least 6 m across), centred on them. */
function frameDynamic(world: b2World): { x: number; y: number; half: number } {
  let minX = Infinity;
  let minY = Infinity;
  let maxX = -Infinity;
  let maxY = -Infinity;
  for (let body = world.GetBodyList(); body; body = body.GetNext()) {
    if (body.GetType() === b2.b2_staticBody) continue;
    const p = body.GetPosition();
    minX = Math.min(minX, p.x);
    minY = Math.min(minY, p.y);
    maxX = Math.max(maxX, p.x);
    maxY = Math.max(maxY, p.y);
  }
  if (minX > maxX) return { x: 0, y: 0, half: 10 };
  return { x: (minX + maxX) / 2, y: (minY + maxY) / 2, half: Math.max(3, 0.6 * Math.max(maxX - minX, maxY - minY) + 1.5) };
}

/**
 * Replays `sceneId` with method `methodId` on `canvas` (on the WebGPU backend with `gpu`), one
 * frame of simulated time per display frame; `onFrame` sees the state after each drawing, the last
 * with the measures, `onError` what stopped it. Resolves, once the replay has started, with a
 * function that stops it.
 */
export async function replay(
  sceneId: string,
  methodId: string,
  gpu: boolean,
  canvas: HTMLCanvasElement,
  onFrame: (state: ReplayState) => void,
  onError: (error: unknown) => void,
): Promise<() => void> {
  const scene = ACCURACY_SCENES[sceneId as keyof typeof ACCURACY_SCENES];
  if (scene === undefined) throw new RangeError(`replay: unknown scene '${sceneId}'`);
  const id = sceneId as keyof typeof ACCURACY_SCENES;
  const method = methodById(methodId);
  // A trajectory scene is measured against the converged reference, run first on the engine (not drawn).
  const reference = scene.trajectory === true ? referencePositions(b2, id) : null;
  const { world, data, view, probe } = buildScene(b2, id);
  applyMethod(world, method);
  const backend = gpu ? await WebGPUBackend.create() : null;
  if (backend !== null) await world.SetBackend(backend);
  const frames = Math.round(scene.seconds * method.frameHz);
  const camera = scene.view ?? frameDynamic(world);
  const state: ReplayState = { scene: sceneId, method: methodId, gpu, frame: 0, frames, done: false, measures: null };
  let handle = 0;
  let stopped = false;
  const tick = async () => {
    if (stopped) return;
    state.frame++;
    stepFrame(world, method);
    if (backend !== null) await world.Synchronize();
    probe.sample(state.frame / method.frameHz);
    drawWorld(canvas, world, camera);
    if (state.frame >= frames) {
      const measures: Record<string, number> = { ...probe.result() };
      if (reference !== null) measures['trajectory error'] = trajectoryError(reference, scenePositions(data, view)).max;
      state.measures = measures;
      state.done = true;
      await backend?.destroy();
    } else if (!stopped) {
      handle = requestAnimationFrame(() => void tick().catch(fail));
    }
    onFrame(state);
  };
  const fail = (e: unknown) => {
    stopped = true;
    void backend?.destroy().catch(() => undefined);
    onError(e);
  };
  handle = requestAnimationFrame(() => void tick().catch(fail));
  return () => {
    stopped = true;
    cancelAnimationFrame(handle);
    if (!state.done) void backend?.destroy().catch(() => undefined);
  };
}
