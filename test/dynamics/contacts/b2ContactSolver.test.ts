import { describe, expect, it } from 'vitest';
import { b2Manifold } from '../../../src/collision/b2Collision';
import { b2ManifoldField } from '../../../src/collision/b2ManifoldRecord';
import { b2CircleShape } from '../../../src/collision/shapes/b2CircleShape';
import { b2PolygonShape } from '../../../src/collision/shapes/b2PolygonShape';
import type { b2Shape } from '../../../src/collision/shapes/b2Shape';
import { b2Vec2 } from '../../../src/common/b2Math';
import { b2_linearSlop, b2_polygonRadius } from '../../../src/common/b2Settings';
import { b2BodyDef, b2BodyType } from '../../../src/dynamics/b2Body';
import type { b2Body } from '../../../src/dynamics/b2Body';
import { b2FixtureDef } from '../../../src/dynamics/b2Fixture';
import { b2World } from '../../../src/dynamics/b2World';
import { b2ContactListener } from '../../../src/dynamics/b2WorldCallbacks';
import type { b2ContactImpulse } from '../../../src/dynamics/b2WorldCallbacks';
import type { b2Contact } from '../../../src/dynamics/contacts/b2Contact';
import { b2ContactSolver, b2ContactSolverDef } from '../../../src/dynamics/contacts/b2ContactSolver';

/*
 * Hand-built islands: body 0 (A) below body 1 (B), a unit box whose centre is 0.5 above the
 * contact plane y = 0, with mass 1 and inverse inertia 6 (a unit box of density 1). A point at
 * x on the plane has rn = x, and the block matrix is k_ij = mB + iB * x_i * x_j: the points
 * x = -0.5 and 0.5 give K = [[2.5, -0.5], [-0.5, 2.5]], the points x = -0.5 and 0.25 give
 * K = [[2.5, 0.25], [0.25, 1.375]] with determinant 3.375.
 */

interface IslandOptions {
  /** x coordinates of the contact points on the plane y = 0 */
  pointsX: number[];
  vB: [number, number];
  wB?: number;
  /** y of body B's centre (0.5 puts the box exactly on the plane) */
  yB?: number;
  invMassA?: number;
  invIA?: number;
  impulses?: number[];
  tangentImpulses?: number[];
  friction?: number;
  restitution?: number;
  warmStarting?: boolean;
  dtRatio?: number;
}

function makeIsland(options: IslandOptions) {
  const yB = options.yB ?? 0.5;
  const manifold = new b2Manifold();
  manifold.type = b2Manifold.e_faceA;
  manifold.localNormal.Set(0.0, 1.0);
  manifold.localPoint.Set(0.0, 0.0);
  manifold.pointCount = options.pointsX.length;
  options.pointsX.forEach((x, i) => {
    const mp = manifold.points[i];
    mp.localPoint.Set(x, -0.5);
    mp.id.key = i;
    mp.normalImpulse = options.impulses?.[i] ?? 0.0;
    mp.tangentImpulse = options.tangentImpulses?.[i] ?? 0.0;
  });

  // The contact's friction and restitution, which its manifold's record holds.
  manifold.m_record[manifold.m_offset + b2ManifoldField.friction] = options.friction ?? 0.0;
  manifold.m_record[manifold.m_offset + b2ManifoldField.restitution] = options.restitution ?? 0.0;

  const shape = { m_radius: 0.0 };
  const bodyA = { m_islandIndex: 0, m_invMass: options.invMassA ?? 0.0, m_invI: options.invIA ?? 0.0, m_sweep: { localCenter: new b2Vec2() } };
  const bodyB = { m_islandIndex: 1, m_invMass: 1.0, m_invI: 6.0, m_sweep: { localCenter: new b2Vec2() } };
  const contact = {
    m_fixtureA: { GetShape: () => shape, GetBody: () => bodyA },
    m_fixtureB: { GetShape: () => shape, GetBody: () => bodyB },
    m_scalars: { toi: 1.0 },
    GetManifold: () => manifold,
  } as unknown as b2Contact;

  // The solver's b2Position and b2Velocity records: three doubles a body (see b2SolverData).
  const positionData = new Float64Array(6);
  positionData[4] = yB;
  const velocityData = new Float64Array(6);
  velocityData[3] = options.vB[0];
  velocityData[4] = options.vB[1];
  velocityData[5] = options.wB ?? 0.0;

  const def = new b2ContactSolverDef();
  def.step.dt = 1.0 / 60.0;
  def.step.inv_dt = 60.0;
  def.step.dtRatio = options.dtRatio ?? 1.0;
  def.step.warmStarting = options.warmStarting ?? true;
  def.contacts = [contact];
  def.count = 1;
  def.positions = positionData;
  def.velocities = velocityData;

  const solver = new b2ContactSolver(def);
  // The records read as the C++ structs: positions[i].c.y, velocities[i].w...
  const positions = [0, 1].map((i) => ({
    c: {
      get x() {
        return positionData[3 * i];
      },
      get y() {
        return positionData[3 * i + 1];
      },
    },
    get a() {
      return positionData[3 * i + 2];
    },
  }));
  const velocities = [0, 1].map((i) => ({
    v: {
      get x() {
        return velocityData[3 * i];
      },
      get y() {
        return velocityData[3 * i + 1];
      },
    },
    get w() {
      return velocityData[3 * i + 2];
    },
  }));
  return { solver, manifold, positions, velocities, positionData, velocityData };
}

const digits = 12;

describe('b2ContactSolver block solver', () => {
  it('case 1: both points approaching share the impulse and stop the box', () => {
    const { solver, velocities } = makeIsland({ pointsX: [-0.5, 0.25], vB: [0.0, -1.0] });
    solver.InitializeVelocityConstraints();
    expect(solver.m_velocityConstraints[0].pointCount).toBe(2);
    solver.SolveVelocityConstraints();
    const vc = solver.m_velocityConstraints[0];
    // K x = (1, 1) gives x = (1.125, 2.25) / 3.375.
    expect(vc.points[0].normalImpulse).toBeCloseTo(1.0 / 3.0, digits);
    expect(vc.points[1].normalImpulse).toBeCloseTo(2.0 / 3.0, digits);
    expect(velocities[1].v.y).toBeCloseTo(0.0, digits);
    expect(velocities[1].w).toBeCloseTo(0.0, digits);
    expect(velocities[0].v.y).toBe(0.0);
  });

  it('case 2: point 2 separating, point 1 alone takes the impulse (vn1 = 0, x2 = 0)', () => {
    // vn1 = -1 - 0.5 * 6 = -4, vn2 = -1 + 0.25 * 6 = 0.5; case 1 would need x2 < 0.
    const { solver, velocities } = makeIsland({ pointsX: [-0.5, 0.25], vB: [0.0, -1.0], wB: 6.0 });
    solver.InitializeVelocityConstraints();
    solver.SolveVelocityConstraints();
    const vc = solver.m_velocityConstraints[0];
    // x1 = 4 / k11, vn2 = 0.25 * 1.6 + 0.5 >= 0; then vB.y = -1 + 1.6 and w = 6 + 6 * (-0.5 * 1.6)
    expect(vc.points[0].normalImpulse).toBeCloseTo(1.6, digits);
    expect(vc.points[1].normalImpulse).toBe(0.0);
    expect(velocities[1].v.y).toBeCloseTo(0.6, digits);
    expect(velocities[1].w).toBeCloseTo(1.2, digits);
  });

  it('case 3: point 1 separating, point 2 alone takes the impulse (vn2 = 0, x1 = 0)', () => {
    // vn1 = -1 + 0.5 * 6 = 2, vn2 = -1 - 0.25 * 6 = -2.5
    const { solver, velocities } = makeIsland({ pointsX: [-0.5, 0.25], vB: [0.0, -1.0], wB: -6.0 });
    solver.InitializeVelocityConstraints();
    solver.SolveVelocityConstraints();
    const vc = solver.m_velocityConstraints[0];
    // x2 = 2.5 / k22 = 20 / 11; then vB.y = -1 + 20 / 11 and w = -6 + 6 * (0.25 * 20 / 11)
    expect(vc.points[0].normalImpulse).toBe(0.0);
    expect(vc.points[1].normalImpulse).toBeCloseTo(20.0 / 11.0, digits);
    expect(velocities[1].v.y).toBeCloseTo(9.0 / 11.0, digits);
    expect(velocities[1].w).toBeCloseTo(-36.0 / 11.0, digits);
  });

  it('case 4: both points separating releases the accumulated impulse', () => {
    // b' = b - K a = (1, 1) - (0.6, 0.6) >= 0, so x = 0 and d = -a.
    const { solver, velocities } = makeIsland({ pointsX: [-0.5, 0.5], vB: [0.0, 1.0], impulses: [0.3, 0.3] });
    solver.InitializeVelocityConstraints();
    solver.SolveVelocityConstraints();
    const vc = solver.m_velocityConstraints[0];
    expect(vc.points[0].normalImpulse).toBe(0.0);
    expect(vc.points[1].normalImpulse).toBe(0.0);
    expect(velocities[1].v.y).toBeCloseTo(0.4, digits);
    expect(velocities[1].w).toBeCloseTo(0.0, digits);
  });

  it('falls back to one point when the block matrix is ill-conditioned', () => {
    const { solver } = makeIsland({ pointsX: [-0.5, -0.5 + 1e-6], vB: [0.0, -1.0] });
    solver.InitializeVelocityConstraints();
    expect(solver.m_velocityConstraints[0].pointCount).toBe(1);
  });

  it('builds K and its inverse for a well-conditioned pair', () => {
    const { solver } = makeIsland({ pointsX: [-0.5, 0.5], vB: [0.0, -1.0] });
    solver.InitializeVelocityConstraints();
    const vc = solver.m_velocityConstraints[0];
    expect([vc.K.ex.x, vc.K.ex.y, vc.K.ey.x, vc.K.ey.y]).toEqual([2.5, -0.5, -0.5, 2.5]);
    // inverse = [[2.5, 0.5], [0.5, 2.5]] / 6
    expect(vc.normalMass.ex.x).toBe((1.0 / 6.0) * 2.5);
    expect(vc.normalMass.ey.x).toBe(-(1.0 / 6.0) * -0.5);
  });
});

describe('b2ContactSolver single point, friction and restitution', () => {
  it('stops a point approaching below the centre', () => {
    const { solver, velocities } = makeIsland({ pointsX: [0.0], vB: [0.0, -2.0] });
    solver.InitializeVelocityConstraints();
    solver.SolveVelocityConstraints();
    expect(solver.m_velocityConstraints[0].points[0].normalImpulse).toBe(2.0);
    expect(velocities[1].v.y).toBe(0.0);
  });

  it('reflects the approach speed with restitution 1 above the velocity threshold', () => {
    const { solver, velocities } = makeIsland({ pointsX: [0.0], vB: [0.0, -2.0], restitution: 1.0 });
    solver.InitializeVelocityConstraints();
    expect(solver.m_velocityConstraints[0].points[0].velocityBias).toBe(2.0);
    solver.SolveVelocityConstraints();
    expect(velocities[1].v.y).toBe(2.0);
  });

  it('ignores restitution below the velocity threshold', () => {
    const { solver, velocities } = makeIsland({ pointsX: [0.0], vB: [0.0, -0.5], restitution: 1.0 });
    solver.InitializeVelocityConstraints();
    expect(solver.m_velocityConstraints[0].points[0].velocityBias).toBe(0.0);
    solver.SolveVelocityConstraints();
    expect(velocities[1].v.y).toBe(0.0);
  });

  it('clamps friction to the friction coefficient times the accumulated normal impulse', () => {
    const { solver, velocities } = makeIsland({ pointsX: [0.0], vB: [3.0, -1.0], friction: 0.5 });
    solver.InitializeVelocityConstraints();
    // First pass: no normal impulse yet, so no friction; the normal impulse becomes 1.
    solver.SolveVelocityConstraints();
    const vcp = solver.m_velocityConstraints[0].points[0];
    // b2Clamp(-1.2, -0, 0) is max(-0, -1.2): a negative zero, as in the C++.
    expect(vcp.tangentImpulse).toBe(-0);
    expect(vcp.normalImpulse).toBe(1.0);
    // Second pass: the unclamped friction impulse -3 / 2.5 is clamped to -0.5 * 1. (The
    // constraint objects are filled from the solver's records when read, so read them again.)
    solver.SolveVelocityConstraints();
    expect(solver.m_velocityConstraints[0].points[0]).toBe(vcp);
    expect(vcp.tangentImpulse).toBe(-0.5);
    expect(velocities[1].v.x).toBe(2.5);
    expect(velocities[1].w).toBe(-1.5);
  });
});

describe('b2ContactSolver warm starting and impulse storage', () => {
  it('scales the stored impulses by dtRatio when warm starting and zeroes them otherwise', () => {
    const warm = makeIsland({ pointsX: [-0.5, 0.5], vB: [0.0, 0.0], impulses: [1.5, 2.5], tangentImpulses: [0.5, -1.0], dtRatio: 0.5 });
    const points = warm.solver.m_velocityConstraints[0].points;
    expect([points[0].normalImpulse, points[1].normalImpulse]).toEqual([0.75, 1.25]);
    expect([points[0].tangentImpulse, points[1].tangentImpulse]).toEqual([0.25, -0.5]);

    const cold = makeIsland({ pointsX: [-0.5, 0.5], vB: [0.0, 0.0], impulses: [1.5, 2.5], warmStarting: false });
    const coldPoints = cold.solver.m_velocityConstraints[0].points;
    expect([coldPoints[0].normalImpulse, coldPoints[1].normalImpulse]).toEqual([0.0, 0.0]);
  });

  it('applies the warm-start impulses to the velocities', () => {
    const { solver, velocities } = makeIsland({ pointsX: [-0.5, 0.5], vB: [0.0, -1.0], impulses: [0.25, 0.75] });
    solver.InitializeVelocityConstraints();
    solver.WarmStart();
    // P = (0, 0.25) and (0, 0.75): vB.y += 1; w += 6 * (-0.5 * 0.25 + 0.5 * 0.75)
    expect(velocities[1].v.y).toBe(0.0);
    expect(velocities[1].w).toBe(1.5);
  });

  it('stores the accumulated impulses back into the manifold', () => {
    const { solver, manifold } = makeIsland({ pointsX: [-0.5, 0.5], vB: [0.0, -1.0], wB: 6.0 });
    solver.InitializeVelocityConstraints();
    solver.SolveVelocityConstraints();
    solver.StoreImpulses();
    const vc = solver.m_velocityConstraints[0];
    expect(manifold.points[0].normalImpulse).toBe(vc.points[0].normalImpulse);
    expect(manifold.points[1].normalImpulse).toBe(0.0);
    expect(manifold.points[0].normalImpulse).toBeCloseTo(1.6, digits);
  });

  it('reuses its constraint storage when re-initialised for another island', () => {
    const first = makeIsland({ pointsX: [-0.5, 0.5], vB: [0.0, -1.0], wB: 6.0 });
    first.solver.InitializeVelocityConstraints();
    const constraint = first.solver.m_velocityConstraints[0];
    const second = makeIsland({ pointsX: [-0.5, 0.5], vB: [0.0, -1.0] });
    const def = new b2ContactSolverDef();
    def.step.dtRatio = 1.0;
    def.step.warmStarting = true;
    def.contacts = first.solver.m_contacts;
    def.count = 1;
    def.positions = second.positionData;
    def.velocities = second.velocityData;
    first.solver.Initialize(def);
    expect(first.solver.m_velocityConstraints[0]).toBe(constraint);
    expect(constraint.K.ex.x).toBe(0.0);
    first.solver.InitializeVelocityConstraints();
    first.solver.SolveVelocityConstraints();
    expect(second.velocities[1].v.y).toBeCloseTo(0.0, digits);
  });
});

describe('b2ContactSolver island size', () => {
  it('refuses an island whose records or body indices would pass the masks on their offsets', () => {
    const { solver, velocities } = makeIsland({ pointsX: [-0.5, 0.5], vB: [0.0, -1.0] });
    const tooManyContacts = new b2ContactSolverDef();
    tooManyContacts.count = Math.floor(0x3fffffff / 34) + 1;
    expect(() => solver.Initialize(tooManyContacts)).toThrow('island too large');
    const tooManyBodies = new b2ContactSolverDef();
    tooManyBodies.positions = { length: 3 * 0x10000000 } as unknown as b2ContactSolverDef['positions'];
    expect(() => solver.Initialize(tooManyBodies)).toThrow('island too large');
    // Refused before anything changed: the island set up before still solves.
    expect(solver.m_count).toBe(1);
    solver.InitializeVelocityConstraints();
    solver.SolveVelocityConstraints();
    expect(velocities[1].v.y).toBeCloseTo(0.0, digits);
  });
});

describe('b2ContactSolver position solver', () => {
  it('pushes a penetrating box out and reports success only within 3 slops', () => {
    const deep = makeIsland({ pointsX: [-0.5, 0.5], vB: [0.0, 0.0], yB: 0.4 });
    expect(deep.solver.SolvePositionConstraints()).toBe(false);
    expect(deep.positions[1].c.y).toBeGreaterThan(0.4);
    expect(deep.positions[0].c.y).toBe(0.0);

    // separation -0.01 >= -3 * b2_linearSlop
    const shallow = makeIsland({ pointsX: [-0.5, 0.5], vB: [0.0, 0.0], yB: 0.49 });
    expect(shallow.solver.SolvePositionConstraints()).toBe(true);
  });

  it('corrects one point by -C / K with C = baumgarte * (separation + slop)', () => {
    const { solver, positions } = makeIsland({ pointsX: [0.0], vB: [0.0, 0.0], yB: 0.4 });
    solver.SolvePositionConstraints();
    // The contact point is below the centre, so K = mB = 1.
    const separation = -0.5 + 0.4;
    expect(positions[1].c.y).toBe(0.4 + -(0.2 * (separation + 0.005)) / 1.0);
    expect(positions[1].a).toBe(0.0);
  });

  it('TOI: moves body A only when it is a TOI body, and body B of every contact (2.2.1)', () => {
    const notToi = makeIsland({ pointsX: [0.0], vB: [0.0, 0.0], yB: 0.4, invMassA: 1.0 });
    notToi.solver.SolveTOIPositionConstraints(5, 6);
    expect(notToi.positions[0].c.y).toBe(0.0);
    // C = b2_toiBaugarte * (separation + slop), K = mB
    const separation = -0.5 + 0.4;
    expect(notToi.positions[1].c.y).toBe(0.4 + -(0.75 * (separation + 0.005)) / 1.0);

    const toi = makeIsland({ pointsX: [0.0], vB: [0.0, 0.0], yB: 0.4, invMassA: 1.0 });
    toi.solver.SolveTOIPositionConstraints(0, 1);
    expect(toi.positions[0].c.y).toBeLessThan(0.0);
    // K = mA + mB = 2
    expect(toi.positions[1].c.y).toBe(0.4 + -(0.75 * (separation + 0.005)) / 2.0);
  });

  it('TOI: reports success within 1.5 slops', () => {
    const tight = makeIsland({ pointsX: [0.0], vB: [0.0, 0.0], yB: 0.5 - 0.007 });
    expect(tight.solver.SolveTOIPositionConstraints(0, 1)).toBe(true);
    const loose = makeIsland({ pointsX: [0.0], vB: [0.0, 0.0], yB: 0.5 - 0.008 });
    expect(loose.solver.SolveTOIPositionConstraints(0, 1)).toBe(false);
  });
});

/*
 * Whole-world behaviour: these run the contact solver through b2World.Step.
 */

function createBody(world: b2World, type: b2BodyType, x: number, y: number, shape: b2Shape, restitution = 0.0): b2Body {
  const bd = new b2BodyDef();
  bd.type = type;
  bd.position.Set(x, y);
  const body = world.CreateBody(bd);
  const fd = new b2FixtureDef();
  fd.shape = shape;
  fd.density = 1.0;
  fd.friction = 0.6;
  fd.restitution = restitution;
  body.CreateFixture(fd);
  return body;
}

function circle(radius: number): b2CircleShape {
  const shape = new b2CircleShape();
  shape.m_radius = radius;
  return shape;
}

describe('b2ContactSolver in a world', () => {
  it('keeps a resting box on the ground with two points and non-negative normal impulses', () => {
    const world = new b2World(new b2Vec2(0.0, -10.0));
    world.SetAllowSleeping(false);
    createBody(world, b2BodyType.b2_staticBody, 0.0, -0.5, new b2PolygonShape().SetAsBox(5.0, 0.5));
    const box = createBody(world, b2BodyType.b2_dynamicBody, 0.0, 0.5, new b2PolygonShape().SetAsBox(0.5, 0.5));

    const reports: { count: number; normalImpulses: number[] }[] = [];
    world.SetContactListener(
      new (class extends b2ContactListener {
        override PostSolve(contact: b2Contact, impulse: b2ContactImpulse): void {
          reports.push({ count: impulse.count, normalImpulses: impulse.normalImpulses.slice(0, impulse.count) });
        }
      })(),
    );

    for (let i = 0; i < 180; ++i) {
      world.Step(1.0 / 60.0, 8, 3);
    }

    expect(reports.length).toBeGreaterThan(170);
    for (const report of reports) {
      expect(report.count).toBe(2);
      for (const impulse of report.normalImpulses) {
        expect(impulse).toBeGreaterThanOrEqual(0.0);
      }
    }
    // Settled: the two impulses carry the weight m * g * dt = 1 * 10 / 60, half each.
    const last = reports[reports.length - 1];
    expect(last.normalImpulses[0] + last.normalImpulses[1]).toBeCloseTo(10.0 / 60.0, 6);
    expect(last.normalImpulses[0]).toBeCloseTo(last.normalImpulses[1], 6);
    // The position solver leaves the two polygon skins overlapping by the linear slop; the box
    // neither tips nor slides.
    expect(box.GetPosition().y).toBeCloseTo(0.5 + 2.0 * b2_polygonRadius - b2_linearSlop, 6);
    expect(Math.abs(box.GetPosition().x)).toBeLessThan(1e-9);
    expect(Math.abs(box.GetAngle())).toBeLessThan(1e-9);
  });

  it('bounces a restitution-1 ball back to nearly its drop height', () => {
    const world = new b2World(new b2Vec2(0.0, -10.0));
    createBody(world, b2BodyType.b2_staticBody, 0.0, -0.5, new b2PolygonShape().SetAsBox(5.0, 0.5));
    const dropHeight = 5.0;
    const radius = 0.5;
    const ball = createBody(world, b2BodyType.b2_dynamicBody, 0.0, dropHeight + radius, circle(radius), 1.0);

    let bounced = false;
    let apex = 0.0;
    for (let i = 0; i < 240; ++i) {
      world.Step(1.0 / 60.0, 8, 3);
      const vy = ball.GetLinearVelocity().y;
      if (!bounced && vy > 0.0) bounced = true;
      if (bounced) apex = Math.max(apex, ball.GetPosition().y - radius);
      if (bounced && vy < 0.0) break;
    }

    expect(bounced).toBe(true);
    expect(apex).toBeGreaterThan(0.99 * dropHeight);
    expect(apex).toBeLessThan(1.01 * dropHeight);
  });

  it('lets a ball pass up through a platform whose contact PreSolve disables, then land on it', () => {
    // The Testbed's One-Sided Platform: the contact is disabled while the ball is below the top.
    function run(oneSided: boolean): { passedThrough: boolean; finalY: number } {
      const world = new b2World(new b2Vec2(0.0, -10.0));
      const platformTop = 10.0 + 0.5;
      const radius = 0.5;
      const platform = createBody(world, b2BodyType.b2_staticBody, 0.0, 10.0, new b2PolygonShape().SetAsBox(3.0, 0.5));
      const ball = createBody(world, b2BodyType.b2_dynamicBody, 0.0, 7.0, circle(radius));
      ball.SetLinearVelocity(new b2Vec2(0.0, 14.0));

      if (oneSided) {
        world.SetContactListener(
          new (class extends b2ContactListener {
            override PreSolve(contact: b2Contact): void {
              const bodies = [contact.GetFixtureA().GetBody(), contact.GetFixtureB().GetBody()];
              if (bodies.includes(platform) && bodies.includes(ball) && ball.GetPosition().y < platformTop + radius - 3.0 * 0.005) {
                contact.SetEnabled(false);
              }
            }
          })(),
        );
      }

      let passedThrough = false;
      for (let i = 0; i < 240; ++i) {
        world.Step(1.0 / 60.0, 8, 3);
        if (ball.GetPosition().y - radius > platformTop) passedThrough = true;
      }
      return { passedThrough, finalY: ball.GetPosition().y };
    }

    const oneSided = run(true);
    expect(oneSided.passedThrough).toBe(true);
    // Resting on top: the circle and the platform's skin overlap by the linear slop.
    expect(oneSided.finalY).toBeCloseTo(10.5 + 0.5 + b2_polygonRadius - b2_linearSlop, 6);

    const solid = run(false);
    expect(solid.passedThrough).toBe(false);
    expect(solid.finalY).toBeLessThan(10.0);
  });
});
