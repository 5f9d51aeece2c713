/*
 * Contact events of the WebGPU backend (src-gpu/events.ts): BeginContact / EndContact / PostSolve
 * delivered after the step, against the JavaScript engine's, on a scene where float32 cannot change
 * when shapes touch: two boxes and a circle dropped onto the ground from heights where no step
 * ends within 1e-6 m of touching, and a box thrown up by a force and landing again (its contact
 * ends, and begins again).
 */

import { expect, it } from 'vitest';
import { b2WorldManifold } from '../../src/collision/b2Collision';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2BodyDef, b2_dynamicBody } from '../../src/dynamics/b2Body';
import type { b2Body } from '../../src/dynamics/b2Body';
import { b2World } from '../../src/dynamics/b2World';
import type { b2WorldBackend } from '../../src/dynamics/b2WorldBackend';
import { b2ContactImpulse, b2ContactListener } from '../../src/dynamics/b2WorldCallbacks';
import type { b2Contact } from '../../src/dynamics/contacts/b2Contact';
import { WebGPUBackend } from '../../src-gpu/backend';
import { describeGpu } from './support';

const DT = 1 / 60;
const STEPS = 75;
/** The step before which box 'a' is pushed up (one step of 150 N on 1 kg: about 2.3 m/s). */
const PUSH_STEP = 40;

interface Scene {
  world: b2World;
  thrown: b2Body;
}

function scene(): Scene {
  const world = new b2World(new b2Vec2(0, -10));
  world.SetAllowSleeping(false);
  world.SetContinuousPhysics(false);
  const ground = world.CreateBody(new b2BodyDef());
  const g = new b2PolygonShape();
  g.SetAsBox(20, 1, new b2Vec2(0, -1), 0);
  ground.CreateFixture(g, 0).SetUserData('ground');
  const body = (x: number, y: number, name: string, circle: boolean): b2Body => {
    const def = new b2BodyDef();
    def.type = b2_dynamicBody;
    def.position.Set(x, y);
    const b = world.CreateBody(def);
    if (circle) {
      const s = new b2CircleShape();
      s.m_radius = 0.5;
      b.CreateFixture(s, 1).SetUserData(name);
    } else {
      const s = new b2PolygonShape();
      s.SetAsBox(0.5, 0.5);
      b.CreateFixture(s, 1).SetUserData(name);
    }
    return b;
  };
  const thrown = body(-4, 1.5, 'a', false);
  body(0, 1.0, 'b', false);
  body(4, 2.5, 'c', true);
  return { world, thrown };
}

interface Event {
  step: number;
  kind: 'begin' | 'end';
  pair: string;
  contact: b2Contact;
  touching: boolean;
}

class Recorder extends b2ContactListener {
  step = 0;
  readonly events: Event[] = [];
  readonly postSolves: { step: number; pair: string; normal: number[]; tangent: number[] }[] = [];
  readonly checks: string[] = [];
  private readonly wm = new b2WorldManifold();

  static pair(c: b2Contact): string {
    return `${c.GetFixtureA().GetUserData()}#${c.GetChildIndexA()}/${c.GetFixtureB().GetUserData()}#${c.GetChildIndexB()}`;
  }

  override BeginContact(c: b2Contact): void {
    this.events.push({ step: this.step, kind: 'begin', pair: Recorder.pair(c), contact: c, touching: c.IsTouching() });
    // The manifold is a real one: a point at the ground's surface (y = 0 up to the shapes'
    // radii and the penetration), the normal from A to B pointing up or down.
    const m = c.GetManifold();
    c.GetWorldManifold(this.wm);
    if (m.pointCount < 1 || Math.abs(Math.abs(this.wm.normal.y) - 1) > 1e-3 || Math.abs(this.wm.points[0].y) > 0.1) {
      this.checks.push(`step ${this.step} ${Recorder.pair(c)}: ${m.pointCount} points, normal (${this.wm.normal.x}, ${this.wm.normal.y}), point y ${this.wm.points[0].y}`);
    }
  }

  override EndContact(c: b2Contact): void {
    this.events.push({ step: this.step, kind: 'end', pair: Recorder.pair(c), contact: c, touching: c.IsTouching() });
  }

  override PostSolve(c: b2Contact, impulse: b2ContactImpulse): void {
    this.postSolves.push({ step: this.step, pair: Recorder.pair(c), normal: impulse.normalImpulses.slice(0, impulse.count), tangent: impulse.tangentImpulses.slice(0, impulse.count) });
  }
}

/** Runs the scene; `sync` says after which steps to synchronise (always after the last). */
async function run(backend: b2WorldBackend | null, sync: (step: number) => boolean): Promise<Recorder> {
  const { world, thrown } = scene();
  const listener = new Recorder();
  world.SetContactListener(listener);
  await world.SetBackend(backend);
  for (let step = 1; step <= STEPS; ++step) {
    if (step === PUSH_STEP) thrown.ApplyForceToCenter(new b2Vec2(0, 150));
    listener.step = step;
    world.Step(DT, 8, 3);
    if (sync(step) || step === STEPS) await world.Synchronize();
  }
  await world.SetBackend(null);
  return listener;
}

function perStep(events: Event[]): Map<number, string[]> {
  const out = new Map<number, string[]>();
  for (const e of events) {
    if (!out.has(e.step)) out.set(e.step, []);
    out.get(e.step)!.push(`${e.kind} ${e.pair}`);
  }
  return out;
}

describeGpu('WebGPUBackend: contact events after the step', (ctx) => {
  let js: Recorder;
  let gpu: Recorder;
  let batched: Recorder;

  it('BeginContact and EndContact: per step, the same count and fixture pairs (A and B, children) as the engine', async () => {
    js = await run(null, () => true);
    gpu = await run(await WebGPUBackend.create({ context: ctx }), () => true);
    const a = perStep(js.events);
    const b = perStep(gpu.events);
    const sorted = (m: Map<number, string[]>) => [...m.entries()].map(([step, list]) => `${step}: ${[...list].sort().join(', ')}`);
    console.log(`engine events: ${sorted(a).join(' | ')}`);
    expect(sorted(b)).toEqual(sorted(a));
    // The scene has what the test is about: four begins (one twice) and an end.
    expect(js.events.filter((e) => e.kind === 'begin').length).toBe(4);
    expect(js.events.filter((e) => e.kind === 'end').length).toBe(1);
    expect(gpu.checks).toEqual([]);
  }, 400_000);

  it('delivers a step\'s events in the documented order (pair order), with IsTouching set, and the same b2Contact for a begin and its end', () => {
    // Pairs are ordered by the fixtures' proxy slots, i.e. creation order here: ground, a, b, c.
    const rank = (pair: string) => ['a', 'b', 'c'].indexOf(pair.split('/')[1].split('#')[0]);
    for (const list of perStep(gpu.events).values()) {
      const ranks = list.map((e) => rank(e.split(' ')[1]));
      expect(ranks).toEqual([...ranks].sort((x, y) => x - y));
    }
    const open = new Map<string, b2Contact>();
    let ends = 0;
    for (const e of gpu.events) {
      expect(e.touching).toBe(e.kind === 'begin');
      if (e.kind === 'begin') open.set(e.pair, e.contact);
      else {
        expect(e.contact).toBe(open.get(e.pair));
        ends++;
      }
    }
    expect(ends).toBe(1);
  });

  it('steps taken without synchronising: every step\'s events at the next synchronisation, in step order', async () => {
    batched = await run(await WebGPUBackend.create({ context: ctx }), (step) => step % 4 === 0);
    // Each synchronisation delivers after the last of its steps (the listener's `step` then). The
    // push is applied between Steps that wait to be recorded: its force must still go into step
    // PUSH_STEP (WebGPUBackend takes a queued step's forces when Step is called), or the thrown
    // box's events move.
    const flat = (r: Recorder) => r.events.map((e) => `${e.kind} ${e.pair}`);
    expect(flat(batched)).toEqual(flat(gpu));
    for (let i = 0; i < batched.events.length; ++i) {
      const s = gpu.events[i].step;
      expect(batched.events[i].step).toBe(s % 4 === 0 || s === STEPS ? s : Math.min(STEPS, 4 * Math.ceil(s / 4)));
    }
  }, 300_000);

  it('PostSolve: every touching contact each step, with impulses within 2e-4 N s of the engine\'s for a box at rest', () => {
    // Box 'b' lands at about step 16 and rests; by step 35 its contact carries m g dt / 2 = 0.0833
    // N s per point. The engine's float64 block solver and the GPU's float32 one agree to a few
    // ulps of the impulses per iteration; 2e-4 (0.25%) leaves room for the float32 positions.
    const at = (r: Recorder, step: number) => r.postSolves.filter((p) => p.step === step && p.pair.startsWith('ground#0/b'));
    for (const step of [30, 35]) {
      const [a] = at(js, step);
      const [b] = at(gpu, step);
      expect(b, `GPU PostSolve for ground/b at step ${step}`).toBeDefined();
      expect(b.normal.length).toBe(a.normal.length);
      expect(b.normal.length).toBe(2);
      for (let k = 0; k < a.normal.length; ++k) {
        expect(Math.abs(b.normal[k] - a.normal[k])).toBeLessThan(2e-4);
        expect(Math.abs(b.tangent[k] - a.tangent[k])).toBeLessThan(2e-4);
      }
      expect(a.normal[0] + a.normal[1]).toBeCloseTo(10 * DT, 2);
      // The same contacts get PostSolve on both.
      const pairs = (r: Recorder) => r.postSolves.filter((p) => p.step === step).map((p) => p.pair).sort();
      expect(pairs(gpu)).toEqual(pairs(js));
    }
  });
});
