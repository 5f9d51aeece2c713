// Accuracy measures of a Box2D 2.2.1 world (docs/ACCURACY.md defines each, with its formula and
// unit). They read a world through the engine's public fields only (m_bodyList, m_jointList,
// m_xf, m_sweep, the fixtures' shapes), so they take the JavaScript engine's world and a world
// the GPU backend has synchronised alike (world.PullState() first brings every body to the last
// synchronisation; the contacts live on the GPU, so penetration computes its manifolds from the
// shapes with the engine's collide functions). Nothing here steps a world or changes its state.

// b2Manifold::Type and b2JointType (src/common/b2Constants.ts), as numbers: the measures take any
// build of the engine, so they import none of its modules.
const MANIFOLD_CIRCLES = 0;
const MANIFOLD_FACE_A = 1;
const MANIFOLD_FACE_B = 2;
const JOINT = { revolute: 1, prismatic: 2, distance: 3, pulley: 4, mouse: 5, gear: 6, wheel: 7, weld: 8, friction: 9, rope: 10 };
const STATIC_BODY = 0;
// b2ShapeType.
const CIRCLE = 0;
const EDGE = 1;
const POLYGON = 2;
const CHAIN = 3;

/** x, y of transform `xf` applied to local point `p`. */
function mulXf(xf, p) {
  return { x: xf.q.c * p.x - xf.q.s * p.y + xf.p.x, y: xf.q.s * p.x + xf.q.c * p.y + xf.p.y };
}

/** Rotation of `xf` applied to `v`. */
function mulRot(xf, v) {
  return { x: xf.q.c * v.x - xf.q.s * v.y, y: xf.q.s * v.x + xf.q.c * v.y };
}

/**
 * The separation of each point of manifold `m` (metres, negative when the shapes overlap), as
 * b2PositionSolverManifold computes it from transforms xfA and xfB and the shapes' radii.
 */
export function manifoldSeparations(m, xfA, xfB, radii) {
  const out = [];
  if (m.pointCount === 0) return out;
  if (m.type === MANIFOLD_CIRCLES) {
    const a = mulXf(xfA, m.localPoint);
    const b = mulXf(xfB, m.points[0].localPoint);
    out.push(Math.hypot(b.x - a.x, b.y - a.y) - radii);
    return out;
  }
  if (m.type !== MANIFOLD_FACE_A && m.type !== MANIFOLD_FACE_B) throw new Error(`manifoldSeparations: unknown manifold type ${m.type}`);
  const faceA = m.type === MANIFOLD_FACE_A;
  const xfFace = faceA ? xfA : xfB;
  const xfClip = faceA ? xfB : xfA;
  const normal = mulRot(xfFace, m.localNormal);
  const plane = mulXf(xfFace, m.localPoint);
  for (let i = 0; i < m.pointCount; ++i) {
    const clip = mulXf(xfClip, m.points[i].localPoint);
    out.push((clip.x - plane.x) * normal.x + (clip.y - plane.y) * normal.y - radii);
  }
  return out;
}

/** The shapes of a fixture as the narrow phase sees them: a chain's children as edges. */
function childShapes(b2, fixture) {
  const shape = fixture.m_shape;
  if (shape.m_type !== CHAIN) return [shape];
  const out = [];
  for (let i = 0; i < shape.GetChildCount(); ++i) {
    const edge = new b2.b2EdgeShape();
    shape.GetChildEdge(edge, i);
    out.push(edge);
  }
  return out;
}

/**
 * The manifold of two shapes at their bodies' transforms, with the engine's collide function for
 * the pair (b2Contact's registry order: polygon before circle, edge before circle or polygon);
 * null for a pair Box2D makes no contact for (edge against edge).
 */
function collide(b2, shapeA, xfA, shapeB, xfB) {
  let [a, b, ta, tb] = [shapeA, shapeB, xfA, xfB];
  if (a.m_type === CIRCLE && b.m_type !== CIRCLE) [a, b, ta, tb] = [b, a, tb, ta];
  if (a.m_type === POLYGON && b.m_type === EDGE) [a, b, ta, tb] = [b, a, tb, ta];
  const m = new b2.b2Manifold();
  if (a.m_type === CIRCLE) b2.b2CollideCircles(m, a, ta, b, tb);
  else if (a.m_type === POLYGON && b.m_type === CIRCLE) b2.b2CollidePolygonAndCircle(m, a, ta, b, tb);
  else if (a.m_type === POLYGON) b2.b2CollidePolygons(m, a, ta, b, tb);
  else if (a.m_type === EDGE && b.m_type === CIRCLE) b2.b2CollideEdgeAndCircle(m, a, ta, b, tb);
  else if (a.m_type === EDGE && b.m_type === POLYGON) b2.b2CollideEdgeAndPolygon(m, a, ta, b, tb);
  else return null;
  return { manifold: m, xfA: ta, xfB: tb, radii: a.m_radius + b.m_radius };
}

/**
 * Penetration (metres): the shapes' manifolds computed now, with the engine `b2` (the exports of
 * webphysics), for every pair of non-sensor fixtures of two bodies, at least one of them dynamic,
 * whose bounding boxes overlap; over their points, the overlap depth max(0, -separation). Its
 * mean over the overlapping points, its maximum, and the number of overlapping points.
 */
export function penetration(b2, world) {
  world.PullState();
  const entries = [];
  for (let body = world.m_bodyList; body; body = body.m_next) {
    for (let f = body.m_fixtureList; f; f = f.m_next) {
      if (f.m_isSensor) continue;
      for (const shape of childShapes(b2, f)) {
        const aabb = new b2.b2AABB();
        shape.ComputeAABB(aabb, body.m_xf, 0);
        entries.push({ body, shape, aabb });
      }
    }
  }
  let sum = 0;
  let max = 0;
  let points = 0;
  for (let i = 0; i < entries.length; ++i) {
    const p = entries[i];
    for (let j = i + 1; j < entries.length; ++j) {
      const q = entries[j];
      if (p.body === q.body || (p.body.m_type === STATIC_BODY && q.body.m_type === STATIC_BODY)) continue;
      if (p.aabb.upperBound.x < q.aabb.lowerBound.x || q.aabb.upperBound.x < p.aabb.lowerBound.x) continue;
      if (p.aabb.upperBound.y < q.aabb.lowerBound.y || q.aabb.upperBound.y < p.aabb.lowerBound.y) continue;
      const c = collide(b2, p.shape, p.body.m_xf, q.shape, q.body.m_xf);
      if (c === null) continue;
      for (const s of manifoldSeparations(c.manifold, c.xfA, c.xfB, c.radii)) {
        if (s >= 0) continue;
        sum -= s;
        if (-s > max) max = -s;
        points++;
      }
    }
  }
  return { mean: points > 0 ? sum / points : 0, max, points };
}

/** Angle of the body (radians), from its sweep. */
function angleOf(body) {
  return body.m_sweep.a;
}

/** World point of a body's local point. */
function worldPoint(body, local) {
  return mulXf(body.m_xf, local);
}

/**
 * A joint's position error, as its constraint defines it: `linear` in metres and `angular` in
 * radians (0 where the joint constrains no such thing). Limits and motors are not errors; a
 * mouse joint (a soft target) and a friction joint (no position constraint) have none.
 */
export function jointError(joint) {
  const bA = joint.m_bodyA;
  const bB = joint.m_bodyB;
  switch (joint.m_type) {
    case JOINT.revolute: {
      const a = worldPoint(bA, joint.m_localAnchorA);
      const b = worldPoint(bB, joint.m_localAnchorB);
      return { linear: Math.hypot(b.x - a.x, b.y - a.y), angular: 0 };
    }
    case JOINT.weld: {
      const a = worldPoint(bA, joint.m_localAnchorA);
      const b = worldPoint(bB, joint.m_localAnchorB);
      return { linear: Math.hypot(b.x - a.x, b.y - a.y), angular: Math.abs(angleOf(bB) - angleOf(bA) - joint.m_referenceAngle) };
    }
    case JOINT.prismatic:
    case JOINT.wheel: {
      const a = worldPoint(bA, joint.m_localAnchorA);
      const b = worldPoint(bB, joint.m_localAnchorB);
      const perp = mulRot(bA.m_xf, joint.m_localYAxisA);
      const linear = Math.abs((b.x - a.x) * perp.x + (b.y - a.y) * perp.y);
      const angular = joint.m_type === JOINT.prismatic ? Math.abs(angleOf(bB) - angleOf(bA) - joint.m_referenceAngle) : 0;
      return { linear, angular };
    }
    case JOINT.distance: {
      if (joint.m_frequencyHz > 0) return { linear: 0, angular: 0 };
      const a = worldPoint(bA, joint.m_localAnchorA);
      const b = worldPoint(bB, joint.m_localAnchorB);
      return { linear: Math.abs(Math.hypot(b.x - a.x, b.y - a.y) - joint.m_length), angular: 0 };
    }
    case JOINT.rope: {
      const a = worldPoint(bA, joint.m_localAnchorA);
      const b = worldPoint(bB, joint.m_localAnchorB);
      return { linear: Math.max(0, Math.hypot(b.x - a.x, b.y - a.y) - joint.m_maxLength), angular: 0 };
    }
    case JOINT.pulley: {
      const a = worldPoint(bA, joint.m_localAnchorA);
      const b = worldPoint(bB, joint.m_localAnchorB);
      const lengthA = Math.hypot(a.x - joint.m_groundAnchorA.x, a.y - joint.m_groundAnchorA.y);
      const lengthB = Math.hypot(b.x - joint.m_groundAnchorB.x, b.y - joint.m_groundAnchorB.y);
      return { linear: Math.abs(lengthA + joint.m_ratio * lengthB - joint.m_constant), angular: 0 };
    }
    case JOINT.gear: {
      const coordinate = (type, body, ground, localAnchor, groundAnchor, localAxis, referenceAngle) => {
        if (type === JOINT.revolute) return angleOf(body) - angleOf(ground) - referenceAngle;
        const p = worldPoint(body, localAnchor);
        const g = worldPoint(ground, groundAnchor);
        const axis = mulRot(ground.m_xf, localAxis);
        return (p.x - g.x) * axis.x + (p.y - g.y) * axis.y;
      };
      const a = coordinate(joint.m_typeA, bA, joint.m_bodyC, joint.m_localAnchorA, joint.m_localAnchorC, joint.m_localAxisC, joint.m_referenceAngleA);
      const b = coordinate(joint.m_typeB, bB, joint.m_bodyD, joint.m_localAnchorB, joint.m_localAnchorD, joint.m_localAxisD, joint.m_referenceAngleB);
      const error = Math.abs(a + joint.m_ratio * b - joint.m_constant);
      return joint.m_typeA === JOINT.revolute && joint.m_typeB === JOINT.revolute ? { linear: 0, angular: error } : { linear: error, angular: 0 };
    }
    default:
      return { linear: 0, angular: 0 };
  }
}

/** The largest linear (m) and angular (rad) joint error in the world, and the joints measured. */
export function jointErrors(world) {
  world.PullState();
  let linear = 0;
  let angular = 0;
  let joints = 0;
  for (let j = world.m_jointList; j; j = j.m_next) {
    const e = jointError(j);
    if (e.linear > linear) linear = e.linear;
    if (e.angular > angular) angular = e.angular;
    joints++;
  }
  return { linear, angular, joints };
}

/** The world's dynamic bodies, in list order. */
export function dynamicBodies(world) {
  const out = [];
  for (let b = world.m_bodyList; b; b = b.m_next) if (b.m_type !== STATIC_BODY) out.push(b);
  return out;
}

/**
 * Kinetic energy (J), potential energy in gravity `g` (J, zero at y = 0: -m g·c), linear momentum
 * (kg m/s) and angular momentum about the origin (kg m²/s) of the world's bodies.
 */
export function energyAndMomentum(world) {
  world.PullState();
  const g = world.m_gravity;
  let kinetic = 0;
  let potential = 0;
  let px = 0;
  let py = 0;
  let angular = 0;
  for (const b of dynamicBodies(world)) {
    const v = b.m_linearVelocity;
    const w = b.m_angularVelocity;
    const c = b.m_sweep.c;
    kinetic += 0.5 * b.m_mass * (v.x * v.x + v.y * v.y) + 0.5 * b.m_I * w * w;
    potential -= b.m_mass * (g.x * c.x + g.y * c.y);
    px += b.m_mass * v.x;
    py += b.m_mass * v.y;
    angular += b.m_mass * (c.x * v.y - c.y * v.x) + b.m_I * w;
  }
  return { kinetic, potential, total: kinetic + potential, momentum: { x: px, y: py }, angular };
}

/** Root mean square of the dynamic bodies' linear speed (m/s): the jitter of bodies that should rest. */
export function rmsSpeed(world) {
  world.PullState();
  const bodies = dynamicBodies(world);
  if (bodies.length === 0) return 0;
  let sum = 0;
  for (const b of bodies) sum += b.m_linearVelocity.x * b.m_linearVelocity.x + b.m_linearVelocity.y * b.m_linearVelocity.y;
  return Math.sqrt(sum / bodies.length);
}

/**
 * Trajectory error (metres) between two runs of one scene: the largest and the root mean square
 * distance between the same body's centres in two snapshots (x and y interleaved, in body order).
 */
export function trajectoryError(a, b) {
  if (a.length !== b.length) throw new RangeError(`trajectoryError: snapshots of ${a.length / 2} and ${b.length / 2} bodies`);
  let max = 0;
  let sum = 0;
  const n = a.length / 2;
  for (let i = 0; i < n; ++i) {
    const d = Math.hypot(a[2 * i] - b[2 * i], a[2 * i + 1] - b[2 * i + 1]);
    if (d > max) max = d;
    sum += d * d;
  }
  return { max, rms: n > 0 ? Math.sqrt(sum / n) : 0 };
}

/**
 * Resting drift (metres): the largest distance any body's centre moved between two snapshots of
 * a scene that should stay still.
 */
export function restingDrift(before, after) {
  return trajectoryError(before, after).max;
}
