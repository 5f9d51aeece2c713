// Accuracy measures of a Box2D 2.2.1 world (docs/ACCURACY.md defines each, with its formula and
// unit). They read a world through the engine's public fields only (m_bodyList, m_jointList, the
// contact manager's list, m_xf, m_sweep), so they take the JavaScript engine's world and a world
// the GPU backend has synchronised alike. Nothing here steps a world or changes one.

// b2Manifold::Type and b2JointType (src/common/b2Constants.ts), as numbers: the measures take any
// build of the engine, so they import none of its modules.
const MANIFOLD_CIRCLES = 0;
const MANIFOLD_FACE_A = 1;
const MANIFOLD_FACE_B = 2;
const JOINT = { revolute: 1, prismatic: 2, distance: 3, pulley: 4, mouse: 5, gear: 6, wheel: 7, weld: 8, friction: 9, rope: 10 };
const TOUCHING_FLAG = 0x0002;
const STATIC_BODY = 0;

/** x, y of transform `xf` applied to local point `p`. */
function mulXf(xf, p) {
  return { x: xf.q.c * p.x - xf.q.s * p.y + xf.p.x, y: xf.q.s * p.x + xf.q.c * p.y + xf.p.y };
}

/** Rotation of `xf` applied to `v`. */
function mulRot(xf, v) {
  return { x: xf.q.c * v.x - xf.q.s * v.y, y: xf.q.s * v.x + xf.q.c * v.y };
}

/**
 * The separation of each manifold point of a contact (metres, negative when the shapes overlap),
 * as b2PositionSolverManifold computes it from the bodies' transforms now.
 */
export function contactSeparations(contact) {
  const m = contact.m_manifold;
  const fA = contact.m_fixtureA;
  const fB = contact.m_fixtureB;
  const xfA = fA.m_body.m_xf;
  const xfB = fB.m_body.m_xf;
  const radii = fA.m_shape.m_radius + fB.m_shape.m_radius;
  const out = [];
  if (m.pointCount === 0) return out;
  if (m.type === MANIFOLD_CIRCLES) {
    const a = mulXf(xfA, m.localPoint);
    const b = mulXf(xfB, m.points[0].localPoint);
    out.push(Math.hypot(b.x - a.x, b.y - a.y) - radii);
    return out;
  }
  if (m.type !== MANIFOLD_FACE_A && m.type !== MANIFOLD_FACE_B) throw new Error(`contactSeparations: unknown manifold type ${m.type}`);
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

/**
 * Penetration (metres): over every manifold point of the touching, non-sensor contacts, the
 * overlap depth max(0, -separation); its mean and maximum, and the number of points.
 */
export function penetration(world) {
  let sum = 0;
  let max = 0;
  let points = 0;
  for (let c = world.m_contactManager.m_contactList; c; c = c.m_next) {
    if ((c.m_flags & TOUCHING_FLAG) === 0 || c.m_fixtureA.m_isSensor || c.m_fixtureB.m_isSensor) continue;
    for (const s of contactSeparations(c)) {
      const depth = Math.max(0, -s);
      sum += depth;
      if (depth > max) max = depth;
      points++;
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
  const bodies = dynamicBodies(world);
  if (bodies.length === 0) return 0;
  let sum = 0;
  for (const b of bodies) sum += b.m_linearVelocity.x * b.m_linearVelocity.x + b.m_linearVelocity.y * b.m_linearVelocity.y;
  return Math.sqrt(sum / bodies.length);
}

/** The dynamic bodies' centres, x and y interleaved. */
export function positions(world) {
  const bodies = dynamicBodies(world);
  const out = new Float64Array(2 * bodies.length);
  bodies.forEach((b, i) => {
    out[2 * i] = b.m_sweep.c.x;
    out[2 * i + 1] = b.m_sweep.c.y;
  });
  return out;
}

/**
 * Trajectory error (metres) between two runs of one scene: the largest and the root mean square
 * distance between the same body's centres in two `positions()` snapshots.
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
 * Resting drift (metres): the largest distance any body's centre moved between two `positions()`
 * snapshots of a scene that should stay still.
 */
export function restingDrift(before, after) {
  return trajectoryError(before, after).max;
}
