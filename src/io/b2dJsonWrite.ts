/*
 * Writing a world, or a loaded scene with its names, custom properties and images, as b2dJson.
 *
 * The output lists bodies, each body's fixtures and the joints in creation order (the C++ lists
 * are prepended, so they are walked backwards), writes every field explicitly, and carries the
 * values that make b2dJsonRead rebuild the same world bit for bit:
 * - joint fields come from the joint's own members (localAnchorA, referenceAngle...), not from
 *   world anchors and angles recomputed through the bodies' transforms, as b2dJson does;
 * - where loading loses information (see b2dJsonRecipes) the writer uses what the reader recorded
 *   while it still reproduces the object, and otherwise searches the few doubles around the
 *   natural candidate for one that reloads exactly (a def velocity that the center-of-mass moves
 *   turn into the current one, a mass-data inertia, a pre-normalized prismatic axis, a mouse
 *   anchor, a box for SetAsBox polygons);
 * - b2dJsonWriteString keeps -0, which JSON.stringify writes as 0.
 * A stepped world reloads with the same positions, angles and angular velocities. Its linear
 * velocities match to rounding: loading adds the center-of-mass corrections to the def velocity,
 * and the sum cannot always land on every double. Plain b2dJson also has no place for contacts,
 * warm-starting impulses, sleep timers, the broad-phase tree or the sweep (the center of mass is
 * recomputed from the position), so from there a plain copy drifts from the original in the last
 * bits. With `{ solverState: true }` the writer adds the `webphysicsState` extension, which
 * carries all of that (b2dJsonState.ts lists it); b2dJsonRead applies it, and the reloaded world
 * steps on bit for bit like the original. Other b2dJson readers skip the extension.
 */

import { b2MulTXV, b2MulXV, b2Rot, b2Vec2 } from '../common/b2Math';
import type { b2Transform } from '../common/b2Math';
import { b2Atan2 } from '../common/b2Trig';
import type { b2ChainShape } from '../collision/shapes/b2ChainShape';
import type { b2CircleShape } from '../collision/shapes/b2CircleShape';
import type { b2EdgeShape } from '../collision/shapes/b2EdgeShape';
import { b2PolygonShape } from '../collision/shapes/b2PolygonShape';
import { b2MassData, b2Shape } from '../collision/shapes/b2Shape';
import { b2Body, b2BodyType } from '../dynamics/b2Body';
import type { b2Fixture } from '../dynamics/b2Fixture';
import { b2World } from '../dynamics/b2World';
import type { b2DistanceJoint } from '../dynamics/joints/b2DistanceJoint';
import type { b2FrictionJoint } from '../dynamics/joints/b2FrictionJoint';
import type { b2GearJoint } from '../dynamics/joints/b2GearJoint';
import { b2JointType } from '../dynamics/joints/b2Joint';
import type { b2Joint } from '../dynamics/joints/b2Joint';
import type { b2MouseJoint } from '../dynamics/joints/b2MouseJoint';
import type { b2PrismaticJoint } from '../dynamics/joints/b2PrismaticJoint';
import type { b2PulleyJoint } from '../dynamics/joints/b2PulleyJoint';
import type { b2RevoluteJoint } from '../dynamics/joints/b2RevoluteJoint';
import type { b2RopeJoint } from '../dynamics/joints/b2RopeJoint';
import type { b2WeldJoint } from '../dynamics/joints/b2WeldJoint';
import type { b2WheelJoint } from '../dynamics/joints/b2WheelJoint';
import { b2dJsonBodyRecipeFor, b2dJsonBoxRecipeFor, b2dJsonJointRecipeFor } from './b2dJsonRecipes';
import type { b2dJsonBoxRecipe } from './b2dJsonRecipes';
import { b2dJsonWriteState, b2dJson_stateKey } from './b2dJsonState';
import {
  b2dJsonBodiesInCreationOrder,
  b2dJsonError,
  b2dJsonFixturesInCreationOrder,
  b2dJsonJointsInCreationOrder,
  b2dJsonScene,
  b2dJson_defaultStepSettings,
} from './b2dJsonScene';
import type { b2dJsonCustomProperty, b2dJsonItem, b2dJsonObject, b2dJsonValue } from './b2dJsonScene';

// Scratch objects for the exactness checks.
const s_polygon = new b2PolygonShape();
const s_massData = new b2MassData();
const s_vec = new b2Vec2();
const s_center = new b2Vec2();
const s_rot = new b2Rot();
const s_bits = new Float64Array(1);
const s_bitsInt = new BigInt64Array(s_bits.buffer);

function vec(v: Readonly<b2Vec2>): b2dJsonObject {
  return { x: v.x, y: v.y };
}

function vertexList(vertices: readonly Readonly<b2Vec2>[], count: number): b2dJsonObject {
  const x: number[] = [];
  const y: number[] = [];
  for (let i = 0; i < count; ++i) {
    x.push(vertices[i].x);
    y.push(vertices[i].y);
  }
  return { x, y };
}

function sameVec(a: Readonly<b2Vec2>, b: Readonly<b2Vec2>): boolean {
  return Object.is(a.x, b.x) && Object.is(a.y, b.y);
}

/** The next double above x. */
function nextUp(x: number): number {
  if (x === 0) return Number.MIN_VALUE;
  s_bits[0] = x;
  s_bitsInt[0] += x > 0 ? 1n : -1n;
  return s_bits[0];
}

/** x and its neighbours up to two doubles away, nearest first. */
function nearby(x: number): number[] {
  const up = nextUp(x);
  const down = -nextUp(-x);
  return [x, up, down, nextUp(up), -nextUp(-down)];
}

/** The first value near `start` that `accepts` takes, or null. */
function searchNear(start: number, accepts: (x: number) => boolean): number | null {
  for (const x of nearby(start)) {
    if (accepts(x)) return x;
  }
  return null;
}

/** The first vector near `start` (each coordinate within two doubles) that `accepts` takes, or null. */
function searchNearVec(start: Readonly<b2Vec2>, accepts: (v: Readonly<b2Vec2>) => boolean): b2Vec2 | null {
  const candidate = new b2Vec2();
  for (const x of nearby(start.x)) {
    for (const y of nearby(start.y)) {
      if (accepts(candidate.Set(x, y))) return candidate;
    }
  }
  return null;
}

function writeCustomProperty(p: b2dJsonCustomProperty): b2dJsonObject {
  switch (p.type) {
    case 'vec2':
      return { name: p.name, vec2: vec(p.value) };
    case 'color':
      return { name: p.name, color: p.value.slice() };
    default:
      return { name: p.name, [p.type]: p.value };
  }
}

/** Add name and customProperties (named first and last by b2dJson convention). */
function withMetadata(scene: b2dJsonScene | null, item: b2dJsonItem, fields: b2dJsonObject): b2dJsonObject {
  if (scene === null) return fields;
  const name = scene.getName(item);
  const properties = scene.getCustomProperties(item);
  const o: b2dJsonObject = name === '' ? {} : { name };
  Object.assign(o, fields);
  if (properties.length > 0) o.customProperties = properties.map(writeCustomProperty);
  return o;
}

// Polygons

function samePolygon(a: b2PolygonShape, b: b2PolygonShape): boolean {
  if (a.m_vertexCount !== b.m_vertexCount || !sameVec(a.m_centroid, b.m_centroid)) return false;
  for (let i = 0; i < a.m_vertexCount; ++i) {
    if (!sameVec(a.m_vertices[i], b.m_vertices[i]) || !sameVec(a.m_normals[i], b.m_normals[i])) return false;
  }
  return true;
}

function boxReproduces(shape: b2PolygonShape, hx: number, hy: number, center: Readonly<b2Vec2> | null, angle: number): boolean {
  // SetAsBox takes positive half-widths only (a box turned by pi can look like negative ones).
  if (!(hx > 0.0 && hy > 0.0)) return false;
  if (center === null) s_polygon.SetAsBox(hx, hy);
  else s_polygon.SetAsBox(hx, hy, center, angle);
  return samePolygon(shape, s_polygon);
}

function boxJson(hx: number, hy: number, center: Readonly<b2Vec2> | null, angle: number): b2dJsonObject {
  return center === null ? { hx, hy } : { hx, hy, center: vec(center), angle };
}

/** The SetAsBox call that rebuilds this polygon exactly, or null to rebuild it with Set. */
function polygonBox(shape: b2PolygonShape): b2dJsonObject | null {
  const recipe: b2dJsonBoxRecipe | null = b2dJsonBoxRecipeFor(shape);
  if (recipe !== null && boxReproduces(shape, recipe.hx, recipe.hy, recipe.center, recipe.angle)) {
    return boxJson(recipe.hx, recipe.hy, recipe.center, recipe.angle);
  }
  if (shape.m_vertexCount !== 4) return null;
  // Axis-aligned about the origin: vertex 2 is (hx, hy).
  const v2 = shape.m_vertices[2];
  if (boxReproduces(shape, v2.x, v2.y, null, 0)) return boxJson(v2.x, v2.y, null, 0);
  // Oriented: SetAsBox stores the center as the centroid and rotates normal 1 to (cos, sin).
  // atan2 of that normal is an angle whose sin/cos are those within rounding; try its neighbours.
  const n1 = shape.m_normals[1];
  s_center.Assign(shape.m_centroid);
  const dx = v2.x - s_center.x;
  const dy = v2.y - s_center.y;
  for (const angle of nearby(b2Atan2(n1.y, n1.x))) {
    const q = s_rot.Set(angle);
    if (!Object.is(q.c, n1.x) || !Object.is(q.s, n1.y)) continue;
    // Vertex 2 is center + q (hx, hy).
    const hx0 = q.c * dx + q.s * dy;
    const hy0 = -q.s * dx + q.c * dy;
    for (const hx of nearby(hx0)) {
      for (const hy of nearby(hy0)) {
        if (boxReproduces(shape, hx, hy, s_center, angle)) return boxJson(hx, hy, s_center, angle);
      }
    }
  }
  return null;
}

// Shapes, fixtures, bodies

function writeShape(shape: b2Shape, path: string): [string, b2dJsonObject] {
  switch (shape.m_type) {
    case b2Shape.e_circle: {
      const circle = shape as b2CircleShape;
      return ['circle', { radius: circle.m_radius, center: vec(circle.m_p) }];
    }
    case b2Shape.e_edge: {
      const edge = shape as b2EdgeShape;
      const o: b2dJsonObject = {
        vertex1: vec(edge.m_vertex1),
        vertex2: vec(edge.m_vertex2),
        hasVertex0: edge.m_hasVertex0,
        hasVertex3: edge.m_hasVertex3,
      };
      if (edge.m_hasVertex0) o.vertex0 = vec(edge.m_vertex0);
      if (edge.m_hasVertex3) o.vertex3 = vec(edge.m_vertex3);
      return ['edge', o];
    }
    case b2Shape.e_chain: {
      const chain = shape as b2ChainShape;
      const o: b2dJsonObject = {
        vertices: vertexList(chain.m_vertices, chain.m_count),
        hasPrevVertex: chain.m_hasPrevVertex,
        hasNextVertex: chain.m_hasNextVertex,
      };
      if (chain.m_hasPrevVertex) o.prevVertex = vec(chain.m_prevVertex);
      if (chain.m_hasNextVertex) o.nextVertex = vec(chain.m_nextVertex);
      return ['chain', o];
    }
    case b2Shape.e_polygon: {
      const polygon = shape as b2PolygonShape;
      const o: b2dJsonObject = { vertices: vertexList(polygon.m_vertices, polygon.m_vertexCount) };
      const box = polygonBox(polygon);
      if (box !== null) o.box = box;
      return ['polygon', o];
    }
    default:
      throw new b2dJsonError(path, `cannot write shape type ${shape.m_type}`, 'b2dJsonWrite');
  }
}

function writeFixture(scene: b2dJsonScene | null, fixture: b2Fixture, path: string): b2dJsonObject {
  const [shapeKey, shape] = writeShape(fixture.m_shape, path);
  return withMetadata(scene, fixture, {
    friction: fixture.m_friction,
    restitution: fixture.m_restitution,
    density: fixture.m_density,
    sensor: fixture.m_isSensor,
    'filter-categoryBits': fixture.m_filter.categoryBits,
    'filter-maskBits': fixture.m_filter.maskBits,
    'filter-groupIndex': fixture.m_filter.groupIndex,
    [shapeKey]: shape,
  });
}

type MassSums = [mass: number, cx: number, cy: number, I: number];

/** The mass, local center and centroidal inertia b2Body.ResetMassData computes from these fixtures (list order). */
function resetMass(fixtures: readonly b2Fixture[], fixedRotation: boolean): MassSums {
  let mass = 0.0;
  let cx = 0.0;
  let cy = 0.0;
  let I = 0.0;
  for (const f of fixtures) {
    if (f.m_density === 0.0) continue;
    f.GetMassData(s_massData);
    mass += s_massData.mass;
    cx += s_massData.mass * s_massData.center.x;
    cy += s_massData.mass * s_massData.center.y;
    I += s_massData.I;
  }
  if (mass > 0.0) {
    const invMass = 1.0 / mass;
    cx *= invMass;
    cy *= invMass;
  } else {
    mass = 1.0;
  }
  if (I > 0.0 && !fixedRotation) {
    I -= mass * (cx * cx + cy * cy);
  } else {
    I = 0.0;
  }
  return [mass, cx, cy, I];
}

/** Whether the body's mass is what its fixtures give, i.e. SetMassData was not used. */
function massFromFixtures(body: b2Body, fixtures: readonly b2Fixture[]): boolean {
  const [mass, cx, cy, I] = resetMass(fixtures.slice().reverse(), (body.m_flags & b2Body.e_fixedRotationFlag) !== 0);
  const lc = body.m_sweep.localCenter;
  return Object.is(mass, body.m_mass) && Object.is(cx, lc.x) && Object.is(cy, lc.y) && Object.is(I, body.m_I);
}

/** massData-* for a body whose mass was set with SetMassData, with an I that SetMassData maps back to m_I. */
function currentMassData(body: b2Body): b2MassData {
  const m = body.m_mass;
  const lc = body.m_sweep.localCenter;
  const d = lc.x * lc.x + lc.y * lc.y;
  const massData = new b2MassData();
  massData.mass = m;
  massData.center.Assign(lc);
  if (body.m_I !== 0.0) {
    const start = body.m_I + m * d;
    massData.I = searchNear(start, (x) => Object.is(x - m * d, body.m_I)) ?? start;
  }
  return massData;
}

/**
 * The def linear velocity that loading turns into the body's current one. Loading a dynamic body
 * moves its center from the position to each new center of mass (every CreateFixture with density,
 * then SetMassData), and each move adds b2Cross(w, newCenter - oldCenter) to the velocity.
 */
function defLinearVelocity(body: b2Body, fixtures: readonly b2Fixture[], massData: b2MassData | null): b2Vec2 {
  const v = body.m_linearVelocity;
  if (body.m_type !== b2BodyType.b2_dynamicBody) return v.Clone();
  const xf = body.m_xf;
  const w = body.m_angularVelocity;
  const fixedRotation = (body.m_flags & b2Body.e_fixedRotationFlag) !== 0;
  const xs: number[] = [];
  const ys: number[] = [];
  let cx = xf.p.x;
  let cy = xf.p.y;
  const moveCenter = (lx: number, ly: number) => {
    const nx = xf.q.c * lx - xf.q.s * ly + xf.p.x;
    const ny = xf.q.s * lx + xf.q.c * ly + xf.p.y;
    xs.push(-w * (ny - cy));
    ys.push(w * (nx - cx));
    cx = nx;
    cy = ny;
  };
  for (let k = 0; k < fixtures.length; ++k) {
    if (fixtures[k].m_density > 0.0) {
      const [, lx, ly] = resetMass(fixtures.slice(0, k + 1).reverse(), fixedRotation);
      moveCenter(lx, ly);
    }
  }
  if (massData !== null) moveCenter(massData.center.x, massData.center.y);

  const replay = (start: number, offsets: readonly number[]) => offsets.reduce((sum, o) => sum + o, start);
  const invert = (target: number, offsets: readonly number[]) => {
    const start = target - (replay(target, offsets) - target);
    return searchNear(start, (x) => Object.is(replay(x, offsets), target)) ?? start;
  };
  return new b2Vec2(invert(v.x, xs), invert(v.y, ys));
}

function writeBody(scene: b2dJsonScene | null, body: b2Body, path: string): b2dJsonObject {
  const fixtures = b2dJsonFixturesInCreationOrder(body);
  const recipe = b2dJsonBodyRecipeFor(body);
  let massData: b2MassData | null;
  let linearVelocity: Readonly<b2Vec2>;
  if (recipe !== null) {
    massData = recipe.massData;
    linearVelocity = recipe.linearVelocity;
  } else {
    const custom = body.m_type === b2BodyType.b2_dynamicBody && !massFromFixtures(body, fixtures);
    massData = custom ? currentMassData(body) : null;
    linearVelocity = defLinearVelocity(body, fixtures, massData);
  }
  const flags = body.m_flags;
  const o: b2dJsonObject = {
    type: body.m_type,
    position: vec(recipe !== null ? recipe.position : body.m_xf.p),
    angle: recipe !== null ? recipe.angle : body.m_sweep.a,
    linearVelocity: vec(linearVelocity),
    angularVelocity: recipe !== null ? recipe.angularVelocity : body.m_angularVelocity,
    linearDamping: body.m_linearDamping,
    angularDamping: body.m_angularDamping,
    gravityScale: body.m_gravityScale,
    bullet: (flags & b2Body.e_bulletFlag) !== 0,
    allowSleep: (flags & b2Body.e_autoSleepFlag) !== 0,
    awake: (flags & b2Body.e_awakeFlag) !== 0,
    active: (flags & b2Body.e_activeFlag) !== 0,
    fixedRotation: (flags & b2Body.e_fixedRotationFlag) !== 0,
    fixture: fixtures.map((f, i) => writeFixture(scene, f, `${path}.fixture[${i}]`)),
  };
  if (massData !== null) {
    o['massData-mass'] = massData.mass;
    o['massData-center'] = vec(massData.center);
    o['massData-I'] = massData.I;
  }
  return withMetadata(scene, body, o);
}

// Joints

/** A prismatic def axis that the joint's constructor normalizes to exactly m_localXAxisA. */
function prismaticAxis(joint: b2PrismaticJoint): Readonly<b2Vec2> {
  const axis = joint.m_localXAxisA;
  const normalizesToAxis = (v: Readonly<b2Vec2>) => {
    s_vec.Assign(v).Normalize();
    return sameVec(s_vec, axis);
  };
  const recorded = b2dJsonJointRecipeFor(joint)?.localAxisA ?? null;
  if (recorded !== null && normalizesToAxis(recorded)) return recorded;
  return searchNearVec(axis, normalizesToAxis) ?? axis;
}

/** A world point that b2MouseJoint's constructor maps exactly to m_localAnchorB. */
function mouseAnchorB(joint: b2MouseJoint): Readonly<b2Vec2> {
  const xf: Readonly<b2Transform> = joint.m_bodyB.m_xf;
  const local = joint.m_localAnchorB;
  const mapsToLocal = (w: Readonly<b2Vec2>) => sameVec(b2MulTXV(xf, w, s_vec), local);
  const recorded = b2dJsonJointRecipeFor(joint)?.mouseAnchorB ?? null;
  if (recorded !== null && mapsToLocal(recorded)) return recorded;
  const start = b2MulXV(xf, local, new b2Vec2());
  return searchNearVec(start, mapsToLocal) ?? start;
}

function writeJointFields(joint: b2Joint, jointIndex: ReadonlyMap<b2Joint, number>, path: string): b2dJsonObject {
  switch (joint.m_type) {
    case b2JointType.e_revoluteJoint: {
      const j = joint as b2RevoluteJoint;
      return {
        type: 'revolute',
        anchorA: vec(j.m_localAnchorA),
        anchorB: vec(j.m_localAnchorB),
        refAngle: j.m_referenceAngle,
        enableLimit: j.m_enableLimit,
        lowerLimit: j.m_lowerAngle,
        upperLimit: j.m_upperAngle,
        enableMotor: j.m_enableMotor,
        motorSpeed: j.m_motorSpeed,
        maxMotorTorque: j.m_maxMotorTorque,
      };
    }
    case b2JointType.e_prismaticJoint: {
      const j = joint as b2PrismaticJoint;
      return {
        type: 'prismatic',
        anchorA: vec(j.m_localAnchorA),
        anchorB: vec(j.m_localAnchorB),
        localAxisA: vec(prismaticAxis(j)),
        refAngle: j.m_referenceAngle,
        enableLimit: j.m_enableLimit,
        lowerLimit: j.m_lowerTranslation,
        upperLimit: j.m_upperTranslation,
        enableMotor: j.m_enableMotor,
        motorSpeed: j.m_motorSpeed,
        maxMotorForce: j.m_maxMotorForce,
      };
    }
    case b2JointType.e_distanceJoint: {
      const j = joint as b2DistanceJoint;
      return {
        type: 'distance',
        anchorA: vec(j.m_localAnchorA),
        anchorB: vec(j.m_localAnchorB),
        length: j.m_length,
        frequency: j.m_frequencyHz,
        dampingRatio: j.m_dampingRatio,
      };
    }
    case b2JointType.e_pulleyJoint: {
      const j = joint as b2PulleyJoint;
      return {
        type: 'pulley',
        groundAnchorA: vec(j.m_groundAnchorA),
        groundAnchorB: vec(j.m_groundAnchorB),
        anchorA: vec(j.m_localAnchorA),
        anchorB: vec(j.m_localAnchorB),
        lengthA: j.m_lengthA,
        lengthB: j.m_lengthB,
        ratio: j.m_ratio,
      };
    }
    case b2JointType.e_mouseJoint: {
      const j = joint as b2MouseJoint;
      return {
        type: 'mouse',
        target: vec(j.m_targetA),
        anchorB: vec(mouseAnchorB(j)),
        maxForce: j.m_maxForce,
        frequency: j.m_frequencyHz,
        dampingRatio: j.m_dampingRatio,
      };
    }
    case b2JointType.e_gearJoint: {
      const j = joint as b2GearJoint;
      const joint1 = jointIndex.get(j.m_joint1);
      const joint2 = jointIndex.get(j.m_joint2);
      if (joint1 === undefined || joint2 === undefined) {
        throw new b2dJsonError(path, 'a gear joint refers to a joint that is not in the world', 'b2dJsonWrite');
      }
      return { type: 'gear', joint1, joint2, ratio: j.m_ratio };
    }
    case b2JointType.e_wheelJoint: {
      const j = joint as b2WheelJoint;
      return {
        type: 'wheel',
        anchorA: vec(j.m_localAnchorA),
        anchorB: vec(j.m_localAnchorB),
        localAxisA: vec(j.m_localXAxisA),
        enableMotor: j.m_enableMotor,
        motorSpeed: j.m_motorSpeed,
        maxMotorTorque: j.m_maxMotorTorque,
        springFrequency: j.m_frequencyHz,
        springDampingRatio: j.m_dampingRatio,
      };
    }
    case b2JointType.e_weldJoint: {
      const j = joint as b2WeldJoint;
      return {
        type: 'weld',
        anchorA: vec(j.m_localAnchorA),
        anchorB: vec(j.m_localAnchorB),
        refAngle: j.m_referenceAngle,
        frequency: j.m_frequencyHz,
        dampingRatio: j.m_dampingRatio,
      };
    }
    case b2JointType.e_frictionJoint: {
      const j = joint as b2FrictionJoint;
      return {
        type: 'friction',
        anchorA: vec(j.m_localAnchorA),
        anchorB: vec(j.m_localAnchorB),
        maxForce: j.m_maxForce,
        maxTorque: j.m_maxTorque,
      };
    }
    case b2JointType.e_ropeJoint: {
      const j = joint as b2RopeJoint;
      return {
        type: 'rope',
        anchorA: vec(j.m_localAnchorA),
        anchorB: vec(j.m_localAnchorB),
        maxLength: j.m_maxLength,
      };
    }
    default:
      throw new b2dJsonError(path, `cannot write joint type ${b2JointType[joint.m_type] ?? joint.m_type}`, 'b2dJsonWrite');
  }
}

function writeJoint(
  scene: b2dJsonScene | null,
  joint: b2Joint,
  bodyIndex: ReadonlyMap<b2Body, number>,
  jointIndex: ReadonlyMap<b2Joint, number>,
  path: string,
): b2dJsonObject {
  const { type, ...fields } = writeJointFields(joint, jointIndex, path);
  // A gear joint replaces its bodies with those of its joints; the def had its own.
  const recipe = joint.m_type === b2JointType.e_gearJoint ? b2dJsonJointRecipeFor(joint) : null;
  const bodyA = bodyIndex.get(recipe?.bodyA ?? joint.m_bodyA) ?? bodyIndex.get(joint.m_bodyA);
  const bodyB = bodyIndex.get(recipe?.bodyB ?? joint.m_bodyB) ?? bodyIndex.get(joint.m_bodyB);
  if (bodyA === undefined || bodyB === undefined) {
    throw new b2dJsonError(path, 'the joint is attached to a body that is not in the world', 'b2dJsonWrite');
  }
  return withMetadata(scene, joint, {
    type,
    bodyA,
    bodyB,
    collideConnected: joint.m_collideConnected,
    ...fields,
  });
}

/** Options of b2dJsonWrite. */
export interface b2dJsonWriteOptions {
  /**
   * Add the `webphysicsState` extension (see b2dJsonState.ts): contacts, the broad-phase tree,
   * sweeps, sleep timers, joint impulses... so that b2dJsonRead rebuilds a world that steps on bit
   * for bit like this one. Other b2dJson readers ignore it. Default false.
   */
  solverState?: boolean;
}

/**
 * The b2dJson document for a world, or for a scene (adding its names, custom properties, images
 * and step settings). Numbers are kept as they are, -0 included: serialize it with
 * b2dJsonStringify, not JSON.stringify, to keep negative zeros.
 */
export function b2dJsonWrite(source: b2World | b2dJsonScene, options: b2dJsonWriteOptions = {}): b2dJsonObject {
  const scene = source instanceof b2dJsonScene ? source : null;
  const world = source instanceof b2World ? source : (source as b2dJsonScene).world;
  const settings = scene !== null ? scene.stepSettings : b2dJson_defaultStepSettings;

  const bodies = b2dJsonBodiesInCreationOrder(world);
  const joints = b2dJsonJointsInCreationOrder(world);
  const bodyIndex = new Map(bodies.map((b, i) => [b, i]));
  const jointIndex = new Map(joints.map((j, i) => [j, i]));

  const o: b2dJsonObject = {
    gravity: vec(world.m_gravity),
    allowSleep: world.m_allowSleep,
    autoClearForces: (world.m_flags & b2World.e_clearForces) !== 0,
    warmStarting: world.m_warmStarting,
    continuousPhysics: world.m_continuousPhysics,
    subStepping: world.m_subStepping,
    stepsPerSecond: settings.stepsPerSecond,
    velocityIterations: settings.velocityIterations,
    positionIterations: settings.positionIterations,
    body: bodies.map((b, i) => writeBody(scene, b, `body[${i}]`)),
    joint: joints.map((j, i) => writeJoint(scene, j, bodyIndex, jointIndex, `joint[${i}]`)),
  };
  if (scene !== null && scene.images.length > 0) {
    o.image = scene.images.map((image) => {
      const index = image.body === null ? -1 : (bodyIndex.get(image.body) ?? -1);
      return withMetadata(scene, image, { ...structuredClone(image.fields), body: index });
    });
  }
  const document = withMetadata(scene, world, o);
  if (options.solverState === true) document[b2dJson_stateKey] = b2dJsonWriteState(world, bodies, joints);
  return document;
}

function stringifyValue(value: b2dJsonValue, indent: string, current: string, path: string): string {
  if (value === null) return 'null';
  switch (typeof value) {
    case 'number':
      if (!Number.isFinite(value)) {
        throw new b2dJsonError(path === '' ? '(root)' : path, `cannot write the non-finite number ${value}`, 'b2dJsonWrite');
      }
      // String() gives the shortest text that parses back to the same double, but drops the sign of -0.
      return Object.is(value, -0) ? '-0' : String(value);
    case 'string':
      return JSON.stringify(value);
    case 'boolean':
      return value ? 'true' : 'false';
  }
  const inner = current + indent;
  const open = indent === '' ? '' : `\n${inner}`;
  const separator = indent === '' ? ',' : `,\n${inner}`;
  const close = indent === '' ? '' : `\n${current}`;
  if (Array.isArray(value)) {
    if (value.length === 0) return '[]';
    const items = value.map((v, i) => stringifyValue(v, indent, inner, `${path}[${i}]`));
    return `[${open}${items.join(separator)}${close}]`;
  }
  const keys = Object.keys(value).filter((k) => value[k] !== undefined);
  if (keys.length === 0) return '{}';
  const colon = indent === '' ? ':' : ': ';
  const members = keys.map((k) => `${JSON.stringify(k)}${colon}${stringifyValue(value[k], indent, inner, path === '' ? k : `${path}.${k}`)}`);
  return `{${open}${members.join(separator)}${close}}`;
}

/**
 * JSON text for a b2dJson value, like JSON.stringify(value, null, space) but writing -0 as `-0`
 * (which JSON.parse reads back as -0) and refusing non-finite numbers with their path.
 */
export function b2dJsonStringify(value: b2dJsonValue, space: string | number = ''): string {
  const indent = typeof space === 'number' ? ' '.repeat(Math.max(0, Math.min(10, Math.floor(space)))) : space.slice(0, 10);
  return stringifyValue(value, indent, '', '');
}

/** b2dJsonWrite, serialized with b2dJsonStringify. */
export function b2dJsonWriteString(source: b2World | b2dJsonScene, space: string | number = '', options: b2dJsonWriteOptions = {}): string {
  return b2dJsonStringify(b2dJsonWrite(source, options), space);
}
