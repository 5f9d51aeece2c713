/*
 * The GPU graph colouring (src-gpu/colour.ts) on a pyramid of boxes and on a plate carrying more
 * circles than there are colours: every solver contact gets exactly one colour or the overflow
 * set, no two contacts of a colour share a dynamic body, static bodies block nothing, the colour
 * lists are the contacts sorted by (colour, index), the overflow set is solved (not dropped), and
 * the colouring and the solved bodies are the same bits run to run.
 */

import { expect, it } from 'vitest';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2BodyDef, b2_dynamicBody } from '../../src/dynamics/b2Body';
import { b2FixtureDef } from '../../src/dynamics/b2Fixture';
import { b2World } from '../../src/dynamics/b2World';
import { COLOUR_CAP } from '../../src-gpu/layout';
import { GpuStepper } from '../../src-gpu/stepper';
import { describeGpu } from './support';

const DT = 1 / 60;
const CB_DYNAMIC_A = 0x100;
const CB_DYNAMIC_B = 0x200;

function ground(world: b2World, halfWidth = 40): void {
  const body = world.CreateBody(new b2BodyDef());
  const box = new b2PolygonShape();
  box.SetAsBox(halfWidth, 1, new b2Vec2(0, -1), 0);
  body.CreateFixture(box, 0);
}

function pyramid(rows: number): b2World {
  const world = new b2World(new b2Vec2(0, -10));
  world.SetAllowSleeping(false);
  ground(world);
  const shape = new b2PolygonShape();
  shape.SetAsBox(0.5, 0.5);
  for (let row = 0; row < rows; ++row) {
    for (let i = 0; i < rows - row; ++i) {
      const def = new b2BodyDef();
      def.type = b2_dynamicBody;
      def.position.Set(-rows / 2 + i + 0.5 * row + 0.5, 0.5 + row);
      world.CreateBody(def).CreateFixture(shape, 1);
    }
  }
  return world;
}

/** A wide plate on the ground with `n` circles resting on it: every contact shares the plate. */
function crowdedPlate(n: number): b2World {
  const world = new b2World(new b2Vec2(0, -10));
  world.SetAllowSleeping(false);
  ground(world);
  const plateDef = new b2BodyDef();
  plateDef.type = b2_dynamicBody;
  plateDef.position.Set(0, 0.25);
  const plateShape = new b2PolygonShape();
  plateShape.SetAsBox(n * 0.25 + 1, 0.25);
  world.CreateBody(plateDef).CreateFixture(plateShape, 1);
  const circle = new b2CircleShape();
  circle.m_radius = 0.2;
  for (let i = 0; i < n; ++i) {
    const def = new b2BodyDef();
    def.type = b2_dynamicBody;
    def.position.Set(-n * 0.25 + 0.5 * i + 0.25, 0.7);
    const fd = new b2FixtureDef();
    fd.shape = circle;
    fd.density = 1;
    world.CreateBody(def).CreateFixture(fd);
  }
  return world;
}

interface Colouring {
  colours: Uint32Array;
  bodies: Uint32Array;
  keys: Uint32Array;
  colourStart: number[];
}

function checkColouring(c: Colouring, label: string): { overflow: number; sharedStatic: boolean; used: number } {
  const n = c.colours.length;
  // Exactly one colour (or the overflow set) per contact.
  for (let k = 0; k < n; ++k) expect(c.colours[k], `${label}: contact ${k}`).toBeLessThanOrEqual(COLOUR_CAP);
  // The lists: (colour, k) sorted by colour then k, each contact once, and the starts agree.
  const seen = new Uint8Array(n);
  for (let e = 0; e < n; ++e) {
    const colour = c.keys[2 * e];
    const k = c.keys[2 * e + 1];
    expect(colour, `${label}: entry ${e}`).toBe(c.colours[k]);
    expect(seen[k], `${label}: contact ${k} listed twice`).toBe(0);
    seen[k] = 1;
    if (e > 0) {
      const before = c.keys[2 * e - 2] * 2 ** 32 + c.keys[2 * e - 1];
      expect(colour * 2 ** 32 + k, `${label}: entry ${e} out of order`).toBeGreaterThan(before);
    }
  }
  for (let colour = 0; colour <= COLOUR_CAP + 1; ++colour) {
    let first = 0;
    while (first < n && c.keys[2 * first] < colour) first++;
    expect(c.colourStart[colour], `${label}: start of colour ${colour}`).toBe(first);
  }
  // No two contacts of one colour share a dynamic body; static ones may be shared.
  let sharedStatic = false;
  let used = 0;
  for (let colour = 0; colour < COLOUR_CAP; ++colour) {
    const dynamicOwner = new Map<number, number>();
    const staticUsers = new Map<number, number>();
    let size = 0;
    for (let k = 0; k < n; ++k) {
      if (c.colours[k] !== colour) continue;
      size++;
      const flags = c.bodies[4 * k + 2];
      for (const [body, dynamic] of [
        [c.bodies[4 * k], (flags & CB_DYNAMIC_A) !== 0],
        [c.bodies[4 * k + 1], (flags & CB_DYNAMIC_B) !== 0],
      ] as [number, boolean][]) {
        if (dynamic) {
          const other = dynamicOwner.get(body);
          if (other !== undefined) throw new Error(`${label}: contacts ${other} and ${k} of colour ${colour} share dynamic body ${body}`);
          dynamicOwner.set(body, k);
        } else {
          staticUsers.set(body, (staticUsers.get(body) ?? 0) + 1);
        }
      }
    }
    if (size > 0) used++;
    for (const count of staticUsers.values()) if (count > 1) sharedStatic = true;
  }
  let overflow = 0;
  for (let k = 0; k < n; ++k) if (c.colours[k] === COLOUR_CAP) overflow++;
  return { overflow, sharedStatic, used };
}

async function colouringAfter(ctx: Parameters<Parameters<typeof describeGpu>[1]>[0], build: () => b2World, steps: number) {
  const world = build();
  const stepper = new GpuStepper(ctx, world);
  for (let i = 0; i < steps; ++i) await stepper.step(DT, 8, 3);
  const c = await stepper.solver.readColouring();
  await stepper.readBodies();
  const state: number[] = [];
  for (let b = world.m_bodyList; b; b = b.m_next) state.push(b.m_xf.p.x, b.m_xf.p.y, b.m_sweep.a, b.m_linearVelocity.x, b.m_linearVelocity.y, b.m_angularVelocity);
  stepper.destroy();
  return { colouring: { colours: c.colours, bodies: c.bodies, keys: c.keys, colourStart: c.state.colourStart }, state, world };
}

describeGpu('GPU solver: graph colouring', (ctx) => {
  it('colours a 12-row pyramid: one colour per contact, no shared dynamic body in a colour, ground shared, sorted lists', async () => {
    const { colouring } = await colouringAfter(ctx, () => pyramid(12), 5);
    expect(colouring.colours.length).toBeGreaterThan(100);
    const r = checkColouring(colouring, 'pyramid');
    console.log(`pyramid: ${colouring.colours.length} contacts, ${r.used} colours, ${r.overflow} in the overflow set`);
    expect(r.sharedStatic).toBe(true);
    expect(r.overflow).toBe(0);
  });

  it('puts what the colour cap cannot hold in the overflow set and solves it: 40 circles on one plate stay on it', async () => {
    const n = 40;
    const { colouring, world } = await colouringAfter(ctx, () => crowdedPlate(n), 60);
    const r = checkColouring(colouring, 'plate');
    console.log(`plate: ${colouring.colours.length} contacts, ${r.used} colours, ${r.overflow} in the overflow set`);
    // The n circle-plate contacts share the plate, so at most one per colour.
    expect(r.overflow).toBeGreaterThanOrEqual(n - COLOUR_CAP);
    // Solved, not dropped: after one second every circle still rests on the plate (its centre at
    // plate top + radius, within b2_linearSlop + 1 mm; a dropped contact would let its circle sink
    // through), and the plate is not in the ground (centre >= half height - slop - 1 mm).
    let plateY = 0;
    for (let b = world.m_bodyList; b; b = b.m_next) if (b.m_fixtureList!.m_shape.m_type === 2 && b.m_type === b2_dynamicBody) plateY = b.m_xf.p.y;
    expect(plateY).toBeGreaterThan(0.25 - 0.006);
    let circles = 0;
    for (let b = world.m_bodyList; b; b = b.m_next) {
      if (b.m_fixtureList!.m_shape.m_type !== 0) continue;
      circles++;
      expect(Math.abs(b.m_xf.p.y - (plateY + 0.25 + 0.2))).toBeLessThan(0.006);
    }
    expect(circles).toBe(n);
  });

  it('gives the same colours, lists and solved bodies, bit for bit, run to run', async () => {
    const first = await colouringAfter(ctx, () => pyramid(10), 20);
    const second = await colouringAfter(ctx, () => pyramid(10), 20);
    expect(Array.from(second.colouring.colours)).toEqual(Array.from(first.colouring.colours));
    expect(Array.from(second.colouring.keys)).toEqual(Array.from(first.colouring.keys));
    expect(second.state).toEqual(first.state);
  });
});
