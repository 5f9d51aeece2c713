/*
 * The narrow phase and sleeping bodies (src-gpu/narrowphase/contacts.ts `keep`, persist.ts): a
 * contact of the previous step whose bodies are both asleep or static is kept, not collided, as
 * b2ContactManager::Collide updates a contact only when activeA || activeB.
 *   - a pile that fell asleep keeps every contact: no collide kernel runs over one (every bin
 *     empty, NP.KEPT counts them all), each keeps the manifold, touching state and impulses of the
 *     last step a body was awake, and contacts, counts and bodies keep every bit over more steps;
 *     the solver gets no item in any colour or the overflow set (all COLOUR_IDLE);
 *   - SetAwake(true) from JavaScript on one box: that step its contacts are collided (the
 *     manifolds a fresh collision of the same transforms gives) and the others kept; the island
 *     wakes, and from the next step nothing is kept;
 *   - a box dropped onto the sleeping pile: its new contacts are collided and wake the pile, whose
 *     contacts are all collided from the next step on; the pile gives under the box;
 *   - SetTransform on a sleeping box does not wake it (2.2.1, checked on the engine too): its
 *     contacts with sleeping bodies stay kept as they were; a contact new this step is collided
 *     even between sleeping bodies, and wakes them (b2ContactManager::AddPair).
 */

import { expect, it } from 'vitest';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2BodyDef, b2_dynamicBody } from '../../src/dynamics/b2Body';
import type { b2Body } from '../../src/dynamics/b2Body';
import type { b2World } from '../../src/dynamics/b2World';
import type { GpuContactRecord } from '../../src-gpu/narrowphase/records';
import { COLOUR_CAP } from '../../src-gpu/device/layout';
import { GpuStepper } from '../../src-gpu/stepper';
import { describeGpu } from './support';
import { allAsleep, allAwake, column, DT, motion, POSITION_ITERATIONS, pyramid, restingWorld, stepUntilAsleep, VELOCITY_ITERATIONS } from './resting';

const step = (stepper: GpuStepper) => stepper.step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);

/** The bodies of a GPU contact (A, B). */
function bodiesOf(stepper: GpuStepper, c: GpuContactRecord): [b2Body, b2Body] {
  return [stepper.mirror.fixtureAt(c.fixtureA)!.m_body, stepper.mirror.fixtureAt(c.fixtureB)!.m_body];
}

/** A contact's manifold as b2Contact::Evaluate leaves it, impulses aside. */
const geometry = (c: GpuContactRecord) => ({
  touching: c.touching,
  type: c.type,
  pointCount: c.pointCount,
  localNormal: c.localNormal,
  localPoint: c.localPoint,
  points: c.points.map((p) => ({ localPoint: p.localPoint, id: p.id })),
});

/** The manifold with its impulses: everything b2ContactManager::Collide leaves alone. */
const kept = (c: GpuContactRecord) => ({ ...geometry(c), impulses: c.points.map((p) => [p.normalImpulse, p.tangentImpulse]) });

/** A contact's place in the world: the world-list indices of its two bodies (the same in two worlds built alike). */
function placeOf(world: b2World, stepper: GpuStepper, c: GpuContactRecord): string {
  const index = new Map<b2Body, number>();
  let i = 0;
  for (let b = world.m_bodyList; b; b = b.m_next) index.set(b, i++);
  const [a, b] = bodiesOf(stepper, c);
  return `${index.get(a)}:${index.get(b)}`;
}

/** A box of half size 0.5 at (x, y), awake. */
function addBox(world: b2World, x: number, y: number): b2Body {
  const def = new b2BodyDef();
  def.type = b2_dynamicBody;
  def.position.Set(x, y);
  const body = world.CreateBody(def);
  const box = new b2PolygonShape();
  box.SetAsBox(0.5, 0.5);
  body.CreateFixture(box, 1);
  return body;
}

describeGpu('GPU narrow phase: contacts of sleeping bodies are kept, not collided (b2ContactManager::Collide)', (ctx) => {
  it('a pile asleep: no pair collided, the manifolds of the last awake step, every bit kept over further steps', async () => {
    const { world, boxes } = restingWorld(pyramid(5));
    const stepper = new GpuStepper(ctx, world);
    await stepUntilAsleep(stepper, boxes);
    // Collided at the start of the step that put the pile to sleep, impulses stored by its solve.
    const lastAwake = new Map((await stepper.narrowPhase.readContacts()).map((c) => [`${c.a}:${c.b}`, c]));
    expect([...lastAwake.values()].some((c) => c.kept)).toBe(false);

    const first = await step(stepper);
    expect(first.contactCount).toBeGreaterThan(boxes.length);
    expect(first.keptCount).toBe(first.contactCount);
    expect(first.binCounts.every((n) => n === 0)).toBe(true);
    const contacts = await stepper.narrowPhase.readContacts();
    for (const c of contacts) {
      expect(c.kept && c.warm && !c.began && !c.ended).toBe(true);
      const before = lastAwake.get(`${c.a}:${c.b}`);
      expect(before).toBeDefined();
      expect(kept(c)).toEqual(kept(before!));
    }
    const touching = contacts.filter((c) => c.touching).length;
    expect(first.solverCount).toBe(touching);
    const bytes = await stepper.narrowPhase.readAll();
    await stepper.readBodies();
    const bodies = motion(boxes);

    for (let k = 0; k < 10; ++k) {
      const r = await step(stepper);
      expect([r.contactCount, r.keptCount, r.solverCount, r.eventCount]).toEqual([first.contactCount, first.contactCount, touching, 0]);
      expect(r.binCounts.every((n) => n === 0)).toBe(true);
      // Nothing to solve: every solver contact is idle (COLOUR_IDLE), past every pass's range.
      expect([r.coloursUsed, r.colourItems]).toEqual([0, Array(COLOUR_CAP + 1).fill(0)]);
      expect(await stepper.narrowPhase.readAll()).toEqual(bytes);
    }
    await stepper.readBodies();
    stepper.destroy();
    expect(allAsleep(boxes)).toBe(true);
    expect(motion(boxes)).toEqual(bodies);
    console.log(`a sleeping 5-row pyramid: ${first.contactCount} contacts kept (${touching} touching), none collided`);
  });

  it("SetAwake(true) from JavaScript re-collides the box's contacts that step, as a fresh collision of the same transforms, and its island's from the next", async () => {
    const rows = pyramid(4);
    const { world, boxes } = restingWorld(rows);
    const stepper = new GpuStepper(ctx, world);
    await stepUntilAsleep(stepper, boxes);
    await step(stepper);

    // The same transforms collided afresh: a world built alike, given the read-back motion, on a
    // stepper of its own, collision only (every contact is new there, so every one is collided).
    const copy = restingWorld(rows);
    for (let b = world.m_bodyList, c = copy.world.m_bodyList; b && c; b = b.m_next, c = c.m_next) {
      c.m_xf.p.Assign(b.m_xf.p);
      c.m_xf.q.c = b.m_xf.q.c;
      c.m_xf.q.s = b.m_xf.q.s;
      c.m_sweep.c0.Assign(b.m_sweep.c0);
      c.m_sweep.c.Assign(b.m_sweep.c);
      c.m_sweep.a0 = b.m_sweep.a0;
      c.m_sweep.a = b.m_sweep.a;
    }
    const fresh = new GpuStepper(ctx, copy.world);
    const freshResult = await fresh.step(0, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
    expect(freshResult.keptCount).toBe(0);
    const expected = new Map((await fresh.narrowPhase.readContacts()).map((c) => [placeOf(copy.world, fresh, c), c]));
    fresh.destroy();

    const top = boxes[boxes.length - 1];
    top.SetAwake(true);
    const woken = await step(stepper);
    const contacts = await stepper.narrowPhase.readContacts();
    const ofTop = contacts.filter((c) => bodiesOf(stepper, c).includes(top));
    expect(ofTop.length).toBeGreaterThanOrEqual(2);
    for (const c of contacts) expect(c.kept).toBe(!ofTop.includes(c));
    expect(woken.keptCount).toBe(woken.contactCount - ofTop.length);
    expect(woken.binCounts.reduce((s, n) => s + n, 0)).toBe(ofTop.length);
    for (const c of ofTop) expect(geometry(c)).toEqual(geometry(expected.get(placeOf(world, stepper, c))!));

    const next = await step(stepper);
    expect(next.keptCount).toBe(0);
    await stepper.readBodies();
    stepper.destroy();
    expect(allAwake(boxes)).toBe(true);
  });

  it('a box dropped onto the sleeping pile: its new contacts are collided and wake the pile, collided from then on; the pile gives under it', async () => {
    const { world, boxes } = restingWorld(pyramid(3));
    const stepper = new GpuStepper(ctx, world);
    await stepUntilAsleep(stepper, boxes);
    await step(stepper);
    const top = boxes[boxes.length - 1];
    const place = () => [top.m_xf.p.x, top.m_xf.p.y, top.m_sweep.a];
    const asleepAt = place();
    const dropped = addBox(world, top.m_xf.p.x, top.m_xf.p.y + 2);
    let met = -1;
    for (let k = 1; k <= 60; ++k) {
      const r = await step(stepper);
      const contacts = await stepper.narrowPhase.readContacts();
      const ofDropped = contacts.filter((c) => bodiesOf(stepper, c).includes(dropped));
      if (met < 0 && ofDropped.some((c) => bodiesOf(stepper, c).includes(top))) {
        met = k;
        // The pile was asleep as the step began: only the new contacts are collided.
        for (const c of contacts) expect(c.kept).toBe(!ofDropped.includes(c));
        expect(r.keptCount).toBe(r.contactCount - ofDropped.length);
      } else if (met > 0 && k === met + 1) {
        // b2ContactManager::AddPair woke the pile: every contact is collided.
        expect(r.keptCount).toBe(0);
        await stepper.readBodies();
        expect(allAwake(boxes)).toBe(true);
      }
    }
    await stepper.readBodies();
    stepper.destroy();
    expect(met).toBeGreaterThan(0);
    expect(dropped.m_xf.p.y).toBeGreaterThan(top.m_xf.p.y + 0.9);
    expect(dropped.m_xf.p.y).toBeLessThan(top.m_xf.p.y + 1.1);
    expect(place()).not.toEqual(asleepAt);
    console.log(`dropped box: met the pile at step ${met}, rests ${(dropped.m_xf.p.y - top.m_xf.p.y).toFixed(3)} m above the top box`);
  });

  it('SetTransform on a sleeping box does not wake it, as in 2.2.1: its contacts stay kept; new pairs of sleeping bodies are collided and wake them', async () => {
    // 2.2.1's rule, on the engine: the lifted box stays asleep and its contact keeps its manifold.
    const engine = restingWorld(column(0, 2));
    for (let k = 0; k < 200 && !allAsleep(engine.boxes); ++k) engine.world.Step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
    expect(allAsleep(engine.boxes)).toBe(true);
    const [low, high] = engine.boxes;
    const between = () => {
      for (let ce = high.m_contactList; ce; ce = ce.next) if (ce.other === low) return ce.contact;
      throw new Error('no contact');
    };
    const engineBefore = JSON.stringify(between().m_manifold);
    high.SetTransform(new b2Vec2(high.m_xf.p.x, high.m_xf.p.y + 0.05), high.m_sweep.a);
    engine.world.Step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
    expect(high.IsAwake() || low.IsAwake()).toBe(false);
    expect(JSON.stringify(between().m_manifold)).toBe(engineBefore);

    const { world, boxes } = restingWorld([...column(0, 2), [3, 0.5]]);
    const stepper = new GpuStepper(ctx, world);
    await stepUntilAsleep(stepper, boxes);
    await step(stepper);
    const [bottom, upper, lone] = boxes;
    const pairKey = (c: GpuContactRecord) => bodiesOf(stepper, c).includes(upper) && bodiesOf(stepper, c).includes(bottom);
    const before = (await stepper.narrowPhase.readContacts()).find(pairKey)!;
    expect(before.touching).toBe(true);
    // The engine's own broad phase still holds the moves of the bodies' creation (this world never
    // stepped on the engine): drop them, as WebGPUBackend does at each synchronisation, so that
    // SetTransform's FindNewContacts sees only what the lift itself moves (nothing: it stays
    // inside its fat AABB).
    world.m_contactManager.m_broadPhase.m_moveCount = 0;
    const lifted = upper.m_xf.p.y + 0.05;
    upper.SetTransform(new b2Vec2(upper.m_xf.p.x, lifted), upper.m_sweep.a);
    for (let k = 0; k < 3; ++k) {
      const r = await step(stepper);
      expect(r.keptCount).toBe(r.contactCount);
    }
    const after = (await stepper.narrowPhase.readContacts()).find(pairKey)!;
    expect(after.kept).toBe(true);
    expect(kept(after)).toEqual(kept(before));
    await stepper.readBodies();
    expect(allAsleep(boxes)).toBe(true);
    // It stays where it was put (to the float32 offset the GPU keeps), floating, as in 2.2.1.
    expect(upper.m_xf.p.y).toBeCloseTo(lifted, 6);

    // A fixture added to the lone box against the column's side (no mass: the body's motion stays):
    // its pairs with both column boxes are new, so they are collided although every body was
    // asleep as the step began (2.2.1's next step has AddPair wake them first), and they wake the
    // three boxes. The column's own contact is still kept that step: the GPU wakes after the
    // collide, where 2.2.1's AddPair woke before it.
    const side = new b2PolygonShape();
    side.SetAsBox(0.5, 0.5, new b2Vec2(1 - lone.m_xf.p.x, upper.m_xf.p.y - lone.m_xf.p.y), 0);
    lone.CreateFixture(side, 0);
    const r = await step(stepper);
    const contacts = await stepper.narrowPhase.readContacts();
    const fresh = contacts.filter((c) => !c.warm);
    expect(fresh.length).toBe(2);
    for (const c of fresh) {
      expect(c.kept).toBe(false);
      expect(bodiesOf(stepper, c)).toContain(lone);
    }
    expect(r.keptCount).toBe(r.contactCount - 2);
    expect(fresh.filter((c) => c.touching).length).toBe(1);
    await stepper.readBodies();
    stepper.destroy();
    expect(allAwake(boxes)).toBe(true);
  });
});
