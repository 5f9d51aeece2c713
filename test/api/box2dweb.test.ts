/*
 * Programs written for Box2DWeb 2.1a (test/api/fixtures/*.js), run against the classic-script
 * bundle loaded as a browser loads it: the simulated worlds must behave, the 2.1a calls must map
 * onto Box2D 2.2.1, and what 2.2 removed must throw errors that say what to use instead.
 */

import { readFileSync } from 'node:fs';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { buildBundles } from '../support/bundles';
import { openPage, repoRoot } from './browser';
import type { Page } from './browser';

let dist: { dir: string; remove(): void };

beforeAll(() => {
  dist = buildBundles();
});

afterAll(() => {
  dist.remove();
});

function runProgram(files: string[], script = 'box2d.js'): any {
  const page = openPage(dist.dir, script);
  for (const file of files) page.runFixture(file);
  return page.window.result;
}

describe('the classic script in a browser-like page', () => {
  it("defines Box2DWeb's globals only (Box2D, Vector, Vector_a2j_Number), with its namespaces, and needs no Node globals", () => {
    const page = openPage(dist.dir);
    const globals = Object.keys(page.window).filter((k) => k !== 'window' && k !== 'self');
    expect(globals.sort()).toEqual(['Box2D', 'Vector', 'Vector_a2j_Number']);
    expect(page.run('typeof process + typeof require + typeof module')).toBe('undefinedundefinedundefined');
    for (const name of ['Common', 'Common.Math', 'Collision', 'Collision.Shapes', 'Dynamics', 'Dynamics.Contacts', 'Dynamics.Joints']) {
      expect(page.run(`typeof Box2D.${name}`)).toBe('object');
    }
    expect(page.run('Box2D.Dynamics.b2Body.b2_dynamicBody')).toBe(2);
    expect(page.run('Box2D.Dynamics.b2DebugDraw.e_centerOfMassBit')).toBe(0x10);
    expect(page.run('new Box2D.Dynamics.Joints.b2RevoluteJointDef().type')).toBe(page.run('Box2D.Dynamics.Joints.b2Joint.e_revoluteJoint'));
  });

  for (const script of ['box2d.js', 'box2d.min.js']) {
    it(`${script}: the classic demo's boxes and balls fall, hit the ground, and come to rest on it`, () => {
      const result = runProgram(['falling-bodies.js'], script);
      expect(result.bodies).toHaveLength(10);
      // After half a second every body has fallen 0.5 * g * t^2 (about 1.29 with the solver's
      // semi-implicit Euler), untouched.
      result.yAfterHalfSecond.forEach((y: number, k: number) => {
        const index = 9 - k;
        expect(y).toBeCloseTo(2 + (index % 3) + (10 * 30 * 31) / (2 * 3600), 9);
      });
      for (const body of result.bodies) {
        // Resting on the ground's top (y = 12.5), half a unit above it, within the contact slop.
        expect(body.y).toBeGreaterThan(11.97);
        expect(body.y).toBeLessThan(12.0);
        expect(body.x).toBeCloseTo(1.5 + body.index * 1.8, 6);
        expect(body.awake).toBe(false);
        expect(body.speed).toBe(0);
      }
      expect(result.events.groundHits).toBeGreaterThanOrEqual(10);
      expect(result.events.begin - result.events.end).toBe(result.contactCount);
      expect(result.events.postSolve).toBeGreaterThan(0);
      expect(result.events.preSolve).toBeGreaterThanOrEqual(result.events.postSolve);
      expect(result.events.maxImpulse).toBeGreaterThan(0);
      // Box2D 2.2 worlds have no ground body until GetGroundBody asks for one.
      expect(result.bodyCount).toBe(11);
    });
  }

  it("2.1a code's Vector and Vector_a2j_Number are Box2DWeb's, and a page's own Vector is left alone", () => {
    const page = openPage(dist.dir);
    expect(page.run('Vector === Array')).toBe(true);
    expect(page.run('JSON.stringify(Vector_a2j_Number(3)) + JSON.stringify(Vector_a2j_Number())')).toBe('[0,0,0][]');
    const vertexCount = page.run(`
      var b2Vec2 = Box2D.Common.Math.b2Vec2;
      var vertices = new Vector();
      vertices.push(new b2Vec2(0, 0), new b2Vec2(2, 0), new b2Vec2(1, 1));
      var shape = new Box2D.Collision.Shapes.b2PolygonShape();
      shape.SetAsVector(vertices, vertices.length);
      shape.GetVertexCount();
    `);
    expect(vertexCount).toBe(3);
    const own = openPage(dist.dir, 'box2d.min.js', 'function Vector(x, y) { this.x = x; this.y = y; }');
    expect(own.run('new Vector(1, 2).y + typeof Box2D.Dynamics.b2World')).toBe('2function');
  });

  it('joints hold: a revolute chain, a distance joint, a prismatic motor at its limit, a weld, a mouse joint', () => {
    const result = runProgram(['joints.js']);
    expect(result.maxChainStretch).toBeLessThan(0.01);
    // The chain swings down from (5, 1) without stretching (6 links of length 1).
    expect(result.tipDistanceFromAnchor).toBeLessThan(6.01);
    expect(result.tipY).toBeGreaterThan(4);
    expect(result.ballDistance).toBeCloseTo(2, 2);
    expect(result.distanceJointLength).toBe(2);
    expect(result.sliderTranslation).toBeCloseTo(3, 1);
    expect(result.sliderX).toBeCloseTo(3, 1);
    expect(result.sliderY).toBeCloseTo(5, 6);
    expect(result.weldGap).toBeCloseTo(1, 2);
    expect(result.weldAngleDifference).toBeCloseTo(0, 2);
    expect(result.weldFell).toBeGreaterThan(70);
    // The mouse target ends at (29, 3); the body follows it.
    expect(result.dragged.x).toBeCloseTo(29, 0);
    expect(result.dragged.y).toBeCloseTo(3, 1);
    expect(result.groundIsStatic).toBe(true);
    expect(result.groundIsSame).toBe(true);
    expect(result.jointCount).toBe(10);
    expect([...result.jointTypes].sort()).toEqual([1, 1, 1, 1, 1, 1, 2, 3, 5, 8]);
  });

  it('queries, ray casts, filters, destruction listeners and list walks work as in 2.1a', () => {
    const result = runProgram(['queries.js']);
    expect(result.picked).toBe('boxB');
    expect(result.missed).toBe(null);
    expect(result.pointHits).toEqual(['ball-fixture']);
    const hits = [...result.rayHits].sort((a: any, b: any) => a.fraction - b.fraction);
    expect(hits.map((h: any) => h.name)).toEqual(['boxA', 'boxB', 'ball']);
    expect(hits.map((h: any) => h.x)).toEqual([4.5, 9.5, 14.5]);
    expect(hits.every((h: any) => h.y === 9.5 && h.nx === -1)).toBe(true);
    expect(hits.map((h: any) => h.fraction)).toEqual([0.225, 0.475, 0.725]);
    expect(result.closest).toBe('boxA');
    expect([...result.all].sort()).toEqual(['ball', 'boxA', 'boxB']);
    // The SetAsEdge ground became a Box2D 2.2 edge shape.
    expect(result.down).toBe('ground');
    expect(result.groundShapeType).toBe(1);
    // The contact filter vetoed the ball, which fell through the ground.
    expect(result.vetoed).toBeGreaterThan(0);
    expect(result.ballY).toBeGreaterThan(20);
    // Same negative group: boxA stayed inside boxB.
    expect(result.boxOverlapDistance).toBeLessThan(0.05);
    expect(result.goodbyes).toEqual(['joint:pin']);
    expect(result.names).toEqual(['ball-fixture', 'boxB-fixture', 'boxA-fixture', 'ground-fixture']);
    expect(result.bodyCount).toBe(3);
  });

  it("vector and matrix helpers compute what Box2DWeb's do", () => {
    const r = runProgram(['math.js']);
    expect(r.v).toEqual([3, 4]);
    expect(r.copy).toEqual([8, 6]);
    expect(r.negative).toEqual([-3, -4]);
    expect(r.self).toEqual([3, 4]);
    expect(r.crossVF).toEqual([8, -6]);
    expect(r.crossFV).toEqual([-8, 6]);
    expect(r.minV).toEqual([3, -1]);
    expect(r.maxV).toEqual([5, 4]);
    expect(r.set).toEqual([3, 4]);
    expect(r.unit).toEqual([3 * (1 / 5), 4 * (1 / 5)]);
    expect(r.length).toBe(5);
    expect(r.rotation[0]).toBeCloseTo(0, 15);
    expect(r.rotation.slice(1)).toEqual([1, -1, r.rotation[0]]);
    expect(r.rotationAngle).toBeCloseTo(Math.PI / 2, 15);
    expect(r.rotated[0]).toBeCloseTo(-4, 14);
    expect(r.rotated[1]).toBeCloseTo(3, 14);
    expect(r.back[0]).toBeCloseTo(3, 14);
    expect(r.back[1]).toBeCloseTo(4, 14);
    expect([r.dot, r.crossVV, r.distance, r.clamp, r.abs]).toEqual([11, 2, 5, 5, 2]);
    expect([r.add, r.subtract, r.mulFV]).toEqual([
      [4, 6],
      [2, 2],
      [6, 8],
    ]);
    expect(r.position).toEqual([2, 3]);
    expect(r.R[0]).toBeCloseTo(0, 15);
    expect(r.R[1]).toBeCloseTo(1, 15);
    expect(r.R[2]).toBeCloseTo(-1, 15);
    expect(r.angle).toBeCloseTo(Math.PI / 2, 15);
    expect(r.mulX[0]).toBeCloseTo(2, 14);
    expect(r.mulX[1]).toBeCloseTo(4, 14);
    expect(r.mulXT[0]).toBeCloseTo(1, 14);
    expect(r.mulXT[1]).toBeCloseTo(0, 14);
    expect(r.worldPoint).toEqual(r.mulX);
    expect(r.localPoint[0]).toBeCloseTo(1, 14);
    expect(r.localPoint[1]).toBeCloseTo(0, 14);
    expect(r.mass).toBe(2);
  });

  it('debug drawing set up the Box2DWeb way draws the shapes and the joint on the canvas context', () => {
    const r = runProgram(['recording-context.js', 'debug-draw.js']);
    expect([r.flags, r.scale, r.fillAlpha, r.lineThickness, r.sprite]).toEqual([3, 30, 0.3, 1, true]);
    const calls: any[][] = r.calls;
    // DrawDebugData clears the canvas first, as Box2DWeb's did.
    expect(calls[0]).toEqual(['clearRect', 0, 0, 600, 400]);
    // The awake ball: a filled circle with its radius drawn, in the awake color, at 30 px per unit.
    const ballArc = calls.find((c) => c[0] === 'arc');
    expect(ballArc![1]).toBe(300);
    expect(ballArc![2]).toBeCloseTo(r.ballPosition.y * 30, 9);
    expect(ballArc![3]).toBe(30);
    const strokes = calls.filter((c) => c[0] === 'set' && c[1] === 'strokeStyle').map((c) => c[2]);
    expect(strokes).toEqual([
      'rgba(230,179,179,1)', // awake dynamic body (0.9, 0.7, 0.7)
      'rgba(128,230,128,1)', // static body (0.5, 0.9, 0.5)
      'rgba(128,204,204,1)', // the revolute joint's three segments (0.5, 0.8, 0.8)
      'rgba(128,204,204,1)',
      'rgba(128,204,204,1)',
    ]);
    const fills = calls.filter((c) => c[0] === 'set' && c[1] === 'fillStyle').map((c) => c[2]);
    expect(fills).toEqual(['rgba(230,179,179,0.3)', 'rgba(128,230,128,0.3)']);
    // The ground box (10 +- 5, 12 +- 0.5) in pixels.
    const moves = calls.filter((c) => c[0] === 'moveTo' || c[0] === 'lineTo').map((c) => c.slice(1));
    expect(moves).toContainEqual([150, 345]);
    expect(moves).toContainEqual([450, 375]);
  });

  it("the README's classic-script example runs, and its ball lands on the ground", () => {
    const readme = readFileSync(path.join(repoRoot, 'README.md'), 'utf8');
    const html = /```html\n([\s\S]*?)```/.exec(readme)![1];
    const script = /<script>\n([\s\S]*?)<\/script>/.exec(html)![1];
    const page = openPage(dist.dir);
    page.runFixture('recording-context.js');
    page.run(`
      var canvasContext = new RecordingContext(600, 400);
      var document = {
        getElementById: function (id) {
          return id === 'canvas' ? { getContext: function () { return canvasContext; } } : null;
        },
      };
      var frames = 0;
      function requestAnimationFrame(callback) {
        if (++frames < 120) callback();
      }
    `);
    page.run(script, 'README.html');
    const calls: unknown[][] = page.window.canvasContext.calls;
    expect(calls.filter((c) => c[0] === 'clearRect')).toHaveLength(120);
    const arcs = calls.filter((c) => c[0] === 'arc');
    expect(arcs).toHaveLength(120);
    // From y = 2 onto the ground's top at 12.5: the ball's center rests at 12 (360 px at 30 px/unit).
    expect(arcs[0][2]).toBeCloseTo(60, 0);
    expect(arcs[119][2] as number).toBeGreaterThan(358);
    expect(arcs[119][2] as number).toBeLessThan(361);
  });
});

describe('Box2DWeb calls that Box2D 2.2 removed', () => {
  let page: Page;

  beforeAll(() => {
    page = openPage(dist.dir);
    page.run(`
      var world = new Box2D.Dynamics.b2World(new Box2D.Common.Math.b2Vec2(0, 10), true);
      var bodyDef = new Box2D.Dynamics.b2BodyDef();
      bodyDef.type = Box2D.Dynamics.b2Body.b2_dynamicBody;
      var body = world.CreateBody(bodyDef);
      body.CreateFixture2(new Box2D.Collision.Shapes.b2CircleShape(1), 1);
      var other = world.CreateBody(bodyDef);
      other.CreateFixture2(new Box2D.Collision.Shapes.b2CircleShape(1), 1);
      world.Step(1 / 60, 8, 3);
    `);
  });

  const cases: [string, string, RegExp][] = [
    ['world.SetBroadPhase({})', 'b2World.SetBroadPhase', /dynamic-tree broad phase/],
    ['world.AddController({})', 'b2World.AddController', /ApplyForce/],
    ['world.CreateController({})', 'b2World.CreateController', /ApplyForce/],
    ['new Box2D.Dynamics.Controllers.b2BuoyancyController()', 'new b2BuoyancyController()', /ApplyForce/],
    ['new Box2D.Dynamics.Controllers.b2GravityController()', 'new b2GravityController()', /ApplyForce/],
    ['body.GetControllerList()', 'b2Body.GetControllerList', /ApplyForce/],
    ['body.Split(function () { return false; })', 'b2Body.Split', /DestroyFixture/],
    ['body.Merge(other)', 'b2Body.Merge', /DestroyBody/],
    ['new Box2D.Dynamics.b2BodyDef().inertiaScale = 2', 'b2BodyDef.inertiaScale', /SetMassData/],
    ['new Box2D.Dynamics.Joints.b2PulleyJointDef().maxLengthA = 5', 'b2PulleyJointDef.maxLengthA', /b2RopeJointDef/],
    ['new Box2D.Dynamics.b2ContactFilter().RayCollide = function () {}', 'b2ContactFilter.RayCollide', /return(ing)? -1/],
    ['world.GetContactList().SetSensor(true)', 'b2Contact.SetSensor', /fixture\.SetSensor/],
    ['world.GetContactList().IsContinuous()', 'b2Contact.IsContinuous', /IsBullet/],
    ['body.GetFixtureList().GetShape().ComputeSubmergedArea()', 'b2Shape.ComputeSubmergedArea', /buoyancy/],
    ['new Box2D.Collision.Shapes.b2EdgeChainDef()', 'new b2EdgeChainDef()', /b2ChainShape/],
    ['Box2D.Dynamics.b2DebugDraw.e_controllerBit', 'b2DebugDraw.e_controllerBit', /Controllers were removed/],
    ['Box2D.Common.b2Settings.b2_toiSlop', 'b2Settings.b2_toiSlop', /b2_linearSlop/],
  ];

  for (const [code, call, instead] of cases) {
    it(`${code} throws, naming ${call} and what to use instead`, () => {
      let error: unknown = null;
      try {
        page.run(code);
      } catch (e) {
        error = e;
      }
      expect(error).not.toBe(null);
      const message = (error as Error).message;
      expect(message.startsWith(`${call} is not available: Box2D 2.2 removed it.`)).toBe(true);
      expect(message).toMatch(instead);
    });
  }

  it('inertiaScale = 1 (the only value 2.2 supports) is accepted', () => {
    expect(page.run('var d = new Box2D.Dynamics.b2BodyDef(); d.inertiaScale = 1; d.inertiaScale')).toBe(1);
  });

  it('joint motor getters without the inverse time step throw instead of returning NaN', () => {
    page.run(`
      var jd = new Box2D.Dynamics.Joints.b2RevoluteJointDef();
      jd.Initialize(body, other, new Box2D.Common.Math.b2Vec2(0, 0));
      var revolute = world.CreateJoint(jd);
    `);
    expect(() => page.run('revolute.GetMotorTorque()')).toThrow(/GetMotorTorque\(1 \/ timeStep\).*GetMaxMotorTorque/);
    expect(page.run('revolute.GetMotorTorque(60)')).toBe(0);
  });
});
