/*
 * b2DebugDraw on a recording canvas context: the calls and colors world.DrawDebugData makes
 * through it for each flag (Box2D 2.2.1's DrawDebugData and palette), and its Box2DWeb setup.
 */

import { describe, expect, it } from 'vitest';
import {
  b2BodyDef,
  b2ChainShape,
  b2CircleShape,
  b2DebugDraw,
  b2DistanceJointDef,
  b2EdgeShape,
  b2MouseJointDef,
  b2PolygonShape,
  b2PulleyJointDef,
  b2RevoluteJointDef,
  b2Vec2,
  b2World,
  b2_dynamicBody,
  b2_kinematicBody,
} from '../../src/index';
import type { b2Body, b2DebugDrawContext, b2Shape } from '../../src/index';

type Call = [string, ...unknown[]];

/** A CanvasRenderingContext2D stand-in recording each call and each style assignment. */
class RecordingContext implements b2DebugDrawContext {
  readonly canvas = { width: 640, height: 480 };
  readonly calls: Call[] = [];
  private styles: Record<string, unknown> = { strokeStyle: '#000', fillStyle: '#000', lineWidth: 1 };

  get strokeStyle(): unknown {
    return this.styles.strokeStyle;
  }
  set strokeStyle(value: unknown) {
    this.set('strokeStyle', value);
  }
  get fillStyle(): unknown {
    return this.styles.fillStyle;
  }
  set fillStyle(value: unknown) {
    this.set('fillStyle', value);
  }
  get lineWidth(): number {
    return this.styles.lineWidth as number;
  }
  set lineWidth(value: number) {
    this.set('lineWidth', value);
  }

  private set(name: string, value: unknown): void {
    this.styles[name] = value;
    this.calls.push(['set', name, value]);
  }

  beginPath(): void {
    this.calls.push(['beginPath']);
  }
  closePath(): void {
    this.calls.push(['closePath']);
  }
  moveTo(x: number, y: number): void {
    this.calls.push(['moveTo', x, y]);
  }
  lineTo(x: number, y: number): void {
    this.calls.push(['lineTo', x, y]);
  }
  arc(x: number, y: number, r: number, a0: number, a1: number): void {
    this.calls.push(['arc', x, y, r, a0, a1]);
  }
  stroke(): void {
    this.calls.push(['stroke']);
  }
  fill(): void {
    this.calls.push(['fill']);
  }
  clearRect(x: number, y: number, w: number, h: number): void {
    this.calls.push(['clearRect', x, y, w, h]);
  }
}

/** Draw the world once with these flags at 10 px per unit; the calls after the clear. */
function draw(world: b2World, flags: number, setup?: (dd: b2DebugDraw) => void): Call[] {
  const ctx = new RecordingContext();
  const dd = new b2DebugDraw();
  dd.SetSprite(ctx);
  dd.SetDrawScale(10);
  dd.SetFillAlpha(0.5);
  dd.SetFlags(flags);
  setup?.(dd);
  world.SetDebugDraw(dd);
  world.DrawDebugData();
  expect(ctx.calls[0]).toEqual(['clearRect', 0, 0, 640, 480]);
  return ctx.calls.slice(1);
}

function body(world: b2World, type: number, x: number, y: number, shape: b2Shape | null): b2Body {
  const def = new b2BodyDef();
  def.type = type;
  def.position.Set(x, y);
  const b = world.CreateBody(def);
  if (shape !== null) b.CreateFixture(shape, 1);
  return b;
}

const strokes = (calls: Call[]) => calls.filter((c) => c[0] === 'set' && c[1] === 'strokeStyle').map((c) => c[2]);
const fills = (calls: Call[]) => calls.filter((c) => c[0] === 'set' && c[1] === 'fillStyle').map((c) => c[2]);
const drawing = (calls: Call[]) => calls.filter((c) => c[0] !== 'set');

describe('b2DebugDraw', () => {
  it("keeps Box2DWeb's settings and flag constants", () => {
    const dd = new b2DebugDraw();
    const ctx = new RecordingContext();
    dd.SetSprite(ctx);
    dd.SetDrawScale(30);
    dd.SetLineThickness(2);
    dd.SetAlpha(0.8);
    dd.SetFillAlpha(0.3);
    dd.SetXFormScale(0.4);
    dd.SetFlags(b2DebugDraw.e_shapeBit | b2DebugDraw.e_jointBit);
    dd.AppendFlags(b2DebugDraw.e_aabbBit);
    dd.ClearFlags(b2DebugDraw.e_jointBit);
    expect([dd.GetSprite(), dd.GetDrawScale(), dd.GetLineThickness(), dd.GetAlpha(), dd.GetFillAlpha(), dd.GetXFormScale()]).toEqual([
      ctx,
      30,
      2,
      0.8,
      0.3,
      0.4,
    ]);
    expect(dd.GetFlags()).toBe(0x1 | 0x4);
    expect([b2DebugDraw.e_shapeBit, b2DebugDraw.e_jointBit, b2DebugDraw.e_aabbBit, b2DebugDraw.e_pairBit, b2DebugDraw.e_centerOfMassBit]).toEqual([
      1, 2, 4, 8, 16,
    ]);
  });

  it('e_shapeBit: solid polygons and circles in the color of their body state, edges and chains as segments', () => {
    const world = new b2World(new b2Vec2(0, 10), true);
    body(world, 0, 1, 2, new b2PolygonShape().SetAsBox(1, 0.5)); // static
    body(world, b2_kinematicBody, 5, 5, new b2CircleShape(2)); // kinematic
    const sleeper = body(world, b2_dynamicBody, 10, 0, new b2CircleShape(1));
    sleeper.SetAwake(false);
    const inactive = body(world, b2_dynamicBody, 20, 0, new b2CircleShape(1));
    inactive.SetActive(false);
    body(world, b2_dynamicBody, 30, 0, new b2CircleShape(1)); // awake
    body(world, 0, 0, 0, new b2EdgeShape(new b2Vec2(0, 40), new b2Vec2(10, 40)));
    const chain = new b2ChainShape();
    chain.CreateChain([new b2Vec2(0, 45), new b2Vec2(1, 45), new b2Vec2(2, 46)]);
    body(world, 0, 0, 0, chain);

    const calls = draw(world, b2DebugDraw.e_shapeBit);
    // The body list is newest first.
    expect(strokes(calls)).toEqual([
      'rgba(128,230,128,1)', // chain segment 1 (static)
      'rgba(128,230,128,1)', // its vertex circle
      'rgba(128,230,128,1)', // chain segment 2
      'rgba(128,230,128,1)', // its vertex circle
      'rgba(128,230,128,1)', // edge
      'rgba(230,179,179,1)', // awake dynamic (0.9, 0.7, 0.7)
      'rgba(128,128,77,1)', // inactive (0.5, 0.5, 0.3)
      'rgba(153,153,153,1)', // sleeping (0.6, 0.6, 0.6)
      'rgba(128,128,230,1)', // kinematic (0.5, 0.5, 0.9)
      'rgba(128,230,128,1)', // static box (0.5, 0.9, 0.5)
    ]);
    expect(fills(calls)).toEqual(['rgba(230,179,179,0.5)', 'rgba(128,128,77,0.5)', 'rgba(153,153,153,0.5)', 'rgba(128,128,230,0.5)', 'rgba(128,230,128,0.5)']);
    const shapes = drawing(calls);
    // Chain: a segment, then a 0.05 circle at its first vertex, for each of its two edges.
    expect(shapes.slice(0, 12)).toEqual([
      ['beginPath'],
      ['moveTo', 0, 450],
      ['lineTo', 10, 450],
      ['stroke'],
      ['beginPath'],
      ['arc', 0, 450, 0.5, 0, 2 * Math.PI],
      ['closePath'],
      ['stroke'],
      ['beginPath'],
      ['moveTo', 10, 450],
      ['lineTo', 20, 460],
      ['stroke'],
    ]);
    // The awake circle: filled, outlined, with its radius along the body's x axis.
    const start = shapes.findIndex((c) => c[0] === 'arc' && c[1] === 300) - 1;
    expect(start).toBe(20);
    expect(shapes.slice(start, start + 9)).toEqual([
      ['beginPath'],
      ['arc', 300, 0, 10, 0, 2 * Math.PI],
      ['closePath'],
      ['fill'],
      ['moveTo', 300, 0],
      ['lineTo', 310, 0],
      ['stroke'],
      ['beginPath'],
      ['arc', 200, 0, 10, 0, 2 * Math.PI],
    ]);
    // The static box at (1, 2), half-widths (1, 0.5): its polygon in pixels, filled then outlined.
    expect(shapes.slice(-8)).toEqual([
      ['beginPath'],
      ['moveTo', 0, 15],
      ['lineTo', 20, 15],
      ['lineTo', 20, 25],
      ['lineTo', 0, 25],
      ['closePath'],
      ['fill'],
      ['stroke'],
    ]);
  });

  it('e_jointBit: anchors joined to the body origins, a pulley through its ground anchors, no mouse joint', () => {
    const world = new b2World(new b2Vec2(0, 10), true);
    const a = body(world, 0, 0, 0, new b2PolygonShape().SetAsBox(0.5, 0.5));
    const b = body(world, b2_dynamicBody, 4, 0, new b2CircleShape(0.5));
    const c = body(world, b2_dynamicBody, 8, 0, new b2CircleShape(0.5));
    const revolute = new b2RevoluteJointDef();
    revolute.Initialize(a, b, new b2Vec2(2, 1));
    world.CreateJoint(revolute);
    const distance = new b2DistanceJointDef();
    distance.Initialize(b, c, new b2Vec2(4, 0), new b2Vec2(8, 0));
    world.CreateJoint(distance);
    const pulley = new b2PulleyJointDef();
    pulley.Initialize(b, c, new b2Vec2(4, -5), new b2Vec2(8, -5), new b2Vec2(4, 0), new b2Vec2(8, 0), 1);
    world.CreateJoint(pulley);
    const mouse = new b2MouseJointDef();
    mouse.bodyA = a;
    mouse.bodyB = c;
    mouse.target.Set(8, 0);
    world.CreateJoint(mouse);

    const calls = draw(world, b2DebugDraw.e_jointBit, (dd) => dd.SetLineThickness(3));
    expect(new Set(strokes(calls))).toEqual(new Set(['rgba(128,204,204,1)']));
    expect(calls.filter((call) => call[0] === 'set' && call[1] === 'lineWidth').every((call) => call[2] === 3)).toBe(true);
    const segments = drawing(calls)
      .filter((call) => call[0] === 'moveTo' || call[0] === 'lineTo')
      .map((call) => call.slice(1));
    const pairs: unknown[][] = [];
    for (let i = 0; i < segments.length; i += 2) pairs.push([segments[i], segments[i + 1]]);
    // Joints newest first: mouse (nothing), pulley (3), distance (1), revolute (3).
    expect(pairs).toEqual([
      [
        [40, -50],
        [40, 0],
      ],
      [
        [80, -50],
        [80, 0],
      ],
      [
        [40, -50],
        [80, -50],
      ],
      [
        [40, 0],
        [80, 0],
      ],
      [
        [0, 0],
        [20, 10],
      ],
      [
        [20, 10],
        [20, 10],
      ],
      [
        [40, 0],
        [20, 10],
      ],
    ]);
  });

  it('e_aabbBit: the fat AABB of each proxy of active bodies, outlined', () => {
    const world = new b2World(new b2Vec2(0, 10), true);
    body(world, 0, 1, 1, new b2PolygonShape().SetAsBox(1, 1));
    body(world, b2_dynamicBody, 5, 5, new b2CircleShape(1)).SetActive(false);
    const calls = draw(world, b2DebugDraw.e_aabbBit);
    // The box spans [0, 2] plus its skin (0.01) and the AABB margin (0.1).
    const lo = (0 - 0.01 - 0.1) * 10;
    const hi = (2 + 0.01 + 0.1) * 10;
    expect(strokes(calls)).toEqual(['rgba(230,77,230,1)']);
    expect(fills(calls)).toEqual([]);
    const path = drawing(calls);
    expect(path.map((c) => c[0])).toEqual(['beginPath', 'moveTo', 'lineTo', 'lineTo', 'lineTo', 'closePath', 'stroke']);
    const points = path.filter((c) => c[0] === 'moveTo' || c[0] === 'lineTo').map((c) => c.slice(1) as number[]);
    const expected = [
      [lo, lo],
      [hi, lo],
      [hi, hi],
      [lo, hi],
    ];
    points.forEach((p, i) => {
      expect(p[0]).toBeCloseTo(expected[i][0], 9);
      expect(p[1]).toBeCloseTo(expected[i][1], 9);
    });
  });

  it('e_pairBit: draws nothing, as Box2D 2.2.1 (its pair drawing is commented out)', () => {
    const world = new b2World(new b2Vec2(0, 10), true);
    body(world, 0, 0, 0, new b2PolygonShape().SetAsBox(5, 1));
    body(world, b2_dynamicBody, 0, -1.5, new b2CircleShape(1));
    world.Step(1 / 60, 8, 3);
    expect(world.GetContactCount()).toBe(1);
    expect(draw(world, b2DebugDraw.e_pairBit)).toEqual([]);
  });

  it('e_centerOfMassBit: each body frame at its center of mass, x axis red and y axis green', () => {
    const world = new b2World(new b2Vec2(0, 10), true);
    const b = body(world, b2_dynamicBody, 2, 3, new b2PolygonShape().SetAsBox(1, 1, new b2Vec2(1, 0), 0));
    b.SetTransform(b.GetPosition(), Math.PI / 2);
    const calls = draw(world, b2DebugDraw.e_centerOfMassBit, (dd) => {
      dd.SetXFormScale(2);
      dd.SetAlpha(0.5);
    });
    expect(strokes(calls)).toEqual(['rgba(255,0,0,0.5)', 'rgba(0,255,0,0.5)']);
    const c = b.GetWorldCenter();
    const q = b.GetTransform().q;
    const ends = drawing(calls).filter((call) => call[0] === 'moveTo' || call[0] === 'lineTo');
    expect(ends).toEqual([
      ['moveTo', c.x * 10, c.y * 10],
      ['lineTo', (c.x + 2 * q.c) * 10, (c.y + 2 * q.s) * 10],
      ['moveTo', c.x * 10, c.y * 10],
      ['lineTo', (c.x - 2 * q.s) * 10, (c.y + 2 * q.c) * 10],
    ]);
    expect(c.x).toBeCloseTo(2, 12);
    expect(c.y).toBeCloseTo(4, 12);
  });

  it('draws nothing but the clear with no flags, and Clear can be replaced to keep the canvas', () => {
    const world = new b2World(new b2Vec2(0, 10), true);
    body(world, 0, 0, 0, new b2PolygonShape().SetAsBox(1, 1));
    expect(draw(world, 0)).toEqual([]);
    const ctx = new RecordingContext();
    const dd = new b2DebugDraw();
    dd.SetSprite(ctx);
    dd.SetFlags(b2DebugDraw.e_shapeBit);
    dd.Clear = () => {};
    world.SetDebugDraw(dd);
    world.DrawDebugData();
    expect(ctx.calls[0]).toEqual(['beginPath']);
  });

  it('says what to do when drawing without a canvas context', () => {
    const world = new b2World(new b2Vec2(0, 10), true);
    body(world, 0, 0, 0, new b2PolygonShape().SetAsBox(1, 1));
    const dd = new b2DebugDraw();
    dd.SetFlags(b2DebugDraw.e_shapeBit);
    world.SetDebugDraw(dd);
    expect(() => world.DrawDebugData()).toThrow(/call SetSprite\(canvas.getContext\("2d"\)\) first/);
  });
});
