/*
 * The benchmark scenes of `npm run bench` (bench/scenes.mjs, each defined once as plain data) as
 * testbed scenes: the world is built as bench/engines/webphysics.mjs builds it, stepped with the
 * scene's time step and iterations, with its spawning (the tumbler's boxes) after each step.
 */

import { makeScene, SCENE_IDS } from '../../bench/scenes.mjs';
import type { Scene, SceneBody } from '../../bench/scenes.mjs';
import {
  b2BodyDef,
  b2ChainShape,
  b2CircleShape,
  b2EdgeShape,
  b2FixtureDef,
  b2PolygonShape,
  b2RevoluteJointDef,
  b2Vec2,
  b2World,
  b2_dynamicBody,
  b2_kinematicBody,
  b2_staticBody,
} from '../../src/index';
import type { b2Body, b2Shape } from '../../src/index';
import type { Settings, StepSettings } from '../framework/settings';
import { Test, type TestEntry } from '../framework/test';

type Pair = [number, number];

interface ShapeData {
  kind: 'box' | 'circle' | 'polygon' | 'edge' | 'chain';
  density: number;
  friction: number;
  restitution: number;
  category: number;
  mask: number;
  [field: string]: unknown;
}

interface JointData {
  a: number;
  b: number;
  ax: number;
  ay: number;
  bx: number;
  by: number;
  refAngle: number;
  collideConnected: boolean;
  motor: { speed: number; maxTorque: number } | null;
}

/** Framing of each scene (centre and zoom of the Testbed's camera). */
const kViews: Record<string, { x: number; y: number; zoom: number }> = {
  bench2d: { x: 15.0, y: 20.0, zoom: 1.0 },
  'large-pyramid': { x: 0.0, y: 48.0, zoom: 2.2 },
  'many-pyramids': { x: 0.0, y: 10.0, zoom: 6.8 },
  'mixed-rain': { x: 0.0, y: 20.0, zoom: 1.0 },
  'joint-grid': { x: 50.0, y: -60.0, zoom: 2.6 },
  tumbler: { x: 0.0, y: 10.0, zoom: 0.8 },
};

const v = (p: Pair) => new b2Vec2(p[0], p[1]);

function makeShape(s: ShapeData): b2Shape {
  switch (s.kind) {
    case 'box': {
      const shape = new b2PolygonShape();
      if (s.cx !== undefined) shape.SetAsBox(s.hx as number, s.hy as number, new b2Vec2(s.cx as number, s.cy as number), s.angle as number);
      else shape.SetAsBox(s.hx as number, s.hy as number);
      return shape;
    }
    case 'polygon': {
      const shape = new b2PolygonShape();
      shape.Set((s.vertices as Pair[]).map(v));
      return shape;
    }
    case 'circle': {
      const shape = new b2CircleShape();
      shape.m_radius = s.r as number;
      shape.m_p.Set((s.cx as number | undefined) ?? 0, (s.cy as number | undefined) ?? 0);
      return shape;
    }
    case 'edge': {
      const shape = new b2EdgeShape();
      shape.Set(v(s.v1 as Pair), v(s.v2 as Pair));
      return shape;
    }
    case 'chain': {
      const shape = new b2ChainShape();
      const vertices = (s.vertices as Pair[]).map(v);
      if (s.loop) shape.CreateLoop(vertices);
      else {
        shape.CreateChain(vertices);
        if (s.prev) shape.SetPrevVertex(v(s.prev as Pair));
        if (s.next) shape.SetNextVertex(v(s.next as Pair));
      }
      return shape;
    }
  }
}

export class BenchScene extends Test {
  private readonly m_scene: Scene;
  private readonly m_bodies: b2Body[] = [];

  constructor(scene: Scene) {
    super(new b2World(new b2Vec2(scene.gravity[0], scene.gravity[1])));
    this.m_scene = scene;
    for (const d of scene.bodies) this.AddBody(d);
    for (const j of scene.joints as unknown as JointData[]) {
      const jd = new b2RevoluteJointDef();
      jd.bodyA = this.m_bodies[j.a];
      jd.bodyB = this.m_bodies[j.b];
      jd.localAnchorA.Set(j.ax, j.ay);
      jd.localAnchorB.Set(j.bx, j.by);
      jd.referenceAngle = j.refAngle;
      jd.collideConnected = j.collideConnected;
      if (j.motor) {
        jd.enableMotor = true;
        jd.motorSpeed = j.motor.speed;
        jd.maxMotorTorque = j.motor.maxTorque;
      }
      this.m_world.CreateJoint(jd);
    }
  }

  private AddBody(d: SceneBody): void {
    const bd = new b2BodyDef();
    bd.type = d.type === 'dynamic' ? b2_dynamicBody : d.type === 'kinematic' ? b2_kinematicBody : b2_staticBody;
    bd.position.Set(d.x, d.y);
    bd.angle = d.angle;
    bd.linearVelocity.Set(d.vx as number, d.vy as number);
    bd.angularVelocity = d.w as number;
    bd.bullet = d.bullet as boolean;
    bd.allowSleep = d.allowSleep as boolean;
    const body = this.m_world.CreateBody(bd);
    for (const s of d.shapes as unknown as ShapeData[]) {
      const fd = new b2FixtureDef();
      fd.shape = makeShape(s);
      fd.density = s.density;
      fd.friction = s.friction;
      fd.restitution = s.restitution;
      fd.filter.categoryBits = s.category;
      fd.filter.maskBits = s.mask;
      body.CreateFixture(fd);
    }
    this.m_bodies.push(body);
  }

  override Step(settings: Settings): void {
    const before = this.m_stepCount;
    super.Step(settings);
    const spawn = (this.m_scene as Scene & { spawn?: (step: number) => SceneBody[] | null }).spawn;
    if (this.m_stepCount > before && spawn !== undefined) {
      const more = spawn(this.m_stepCount);
      if (more) for (const d of more) this.AddBody(d);
    }
    this.m_debugDraw.DrawString(5, this.m_textLine, this.m_scene.description);
    this.m_textLine += 15;
  }

  override InitialView(): { x: number; y: number; zoom: number } | null {
    return kViews[this.m_scene.id] ?? null;
  }

  override StepSettingsOverride(): Partial<StepSettings> {
    return {
      hz: 1 / this.m_scene.dt,
      velocityIterations: this.m_scene.velocityIterations,
      positionIterations: this.m_scene.positionIterations,
    };
  }
}

/** One entry per benchmark scene whose data is available (mixed-rain needs the golden scenes). */
export function benchEntries(): TestEntry[] {
  const entries: TestEntry[] = [];
  for (const id of SCENE_IDS) {
    const probe = makeScene(id);
    if (probe === null) continue;
    entries.push({
      name: `Benchmark: ${probe.title}`,
      group: 'Benchmarks',
      createFcn: () => new BenchScene(makeScene(id)!),
    });
  }
  return entries;
}
