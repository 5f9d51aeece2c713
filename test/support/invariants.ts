/*
 * World invariants, a full-state digest and pool sizes, shared by the reliability tests, the
 * property tests and the soak run (scripts/soak.ts).
 */

import { b2BroadPhase } from '../../src/collision/b2BroadPhase';
import { b2_nullNode } from '../../src/collision/b2DynamicTree';
import type { b2Body } from '../../src/dynamics/b2Body';
import { b2BodyType } from '../../src/dynamics/b2Body';
import type { b2Fixture } from '../../src/dynamics/b2Fixture';
import type { b2World } from '../../src/dynamics/b2World';
import type { b2Contact } from '../../src/dynamics/contacts/b2Contact';
import type { b2Joint } from '../../src/dynamics/joints/b2Joint';

/** Value classes whose numbers are joint state (anything else a joint holds is a reference). */
const kValueClasses = new Set(['b2Vec2', 'b2Vec3', 'b2Mat22', 'b2Mat33', 'b2Rot', 'b2Jacobian']);

/** Visit the numbers (and booleans, as 0/1) of an object's own fields, nested value objects included. */
export function forEachNumber(object: object, visit: (name: string, value: number) => void, prefix = ''): void {
  for (const key of Object.keys(object)) {
    const value = (object as Record<string, unknown>)[key];
    const name = prefix === '' ? key : `${prefix}.${key}`;
    if (typeof value === 'number') visit(name, value);
    else if (typeof value === 'boolean') visit(name, value ? 1 : 0);
    else if (typeof value === 'object' && value !== null && kValueClasses.has(value.constructor.name)) {
      forEachNumber(value, visit, name);
    }
  }
}

const s_bytes = new DataView(new ArrayBuffer(8));

/** 32-bit FNV-1a over doubles (their 8 IEEE bytes, so -0, NaN payloads and all bits count). */
class Digest {
  h = 2166136261;

  add(x: number): void {
    s_bytes.setFloat64(0, x, true);
    for (let i = 0; i < 8; ++i) this.h = Math.imul(this.h ^ s_bytes.getUint8(i), 16777619) >>> 0;
  }

  addVec(v: { x: number; y: number }): void {
    this.add(v.x);
    this.add(v.y);
  }

  hex(): string {
    return this.h.toString(16).padStart(8, '0');
  }
}

export function bodiesOf(world: b2World): b2Body[] {
  const bodies: b2Body[] = [];
  for (let b = world.m_bodyList; b !== null; b = b.m_next) bodies.push(b);
  return bodies;
}

export function jointsOf(world: b2World): b2Joint[] {
  const joints: b2Joint[] = [];
  for (let j = world.m_jointList; j !== null; j = j.m_next) joints.push(j);
  return joints;
}

export function contactsOf(world: b2World): b2Contact[] {
  const contacts: b2Contact[] = [];
  for (let c = world.m_contactManager.m_contactList; c !== null; c = c.m_next) contacts.push(c);
  return contacts;
}

export function fixturesOf(body: b2Body): b2Fixture[] {
  const fixtures: b2Fixture[] = [];
  for (let f = body.m_fixtureList; f !== null; f = f.m_next) fixtures.push(f);
  return fixtures;
}

/**
 * A digest of everything that decides the world's future: bodies (transform, sweep, velocities,
 * forces, mass, flags, sleep time), fixtures (material, filter, proxies), joints (every number
 * they hold), contacts (list order, flags, TOI, material, manifold with impulses), the broad-phase
 * tree and the world's own step state. Two worlds with equal digests step identically.
 */
export function worldDigest(world: b2World): string {
  const d = new Digest();
  const bodies = bodiesOf(world);
  const bodyIndex = new Map<b2Body, number>(bodies.map((b, i) => [b, i]));
  const fixtureIndex = new Map<b2Fixture, number>();
  d.add(world.m_flags);
  d.addVec(world.m_gravity);
  d.add(world.m_inv_dt0);
  d.add(world.m_stepComplete ? 1 : 0);
  d.add(world.m_allowSleep ? 1 : 0);
  d.add(world.m_warmStarting ? 1 : 0);
  d.add(world.m_continuousPhysics ? 1 : 0);
  d.add(world.m_subStepping ? 1 : 0);
  d.add(bodies.length);
  for (const b of bodies) {
    d.add(b.m_type);
    d.add(b.m_flags);
    d.addVec(b.m_xf.p);
    d.add(b.m_xf.q.s);
    d.add(b.m_xf.q.c);
    const sw = b.m_sweep;
    d.addVec(sw.localCenter);
    d.addVec(sw.c0);
    d.addVec(sw.c);
    d.add(sw.a0);
    d.add(sw.a);
    d.add(sw.alpha0);
    d.addVec(b.m_linearVelocity);
    d.add(b.m_angularVelocity);
    d.addVec(b.m_force);
    d.add(b.m_torque);
    d.add(b.m_mass);
    d.add(b.m_invMass);
    d.add(b.m_I);
    d.add(b.m_invI);
    d.add(b.m_linearDamping);
    d.add(b.m_angularDamping);
    d.add(b.m_gravityScale);
    d.add(b.m_sleepTime);
    d.add(b.m_fixtureCount);
    for (const f of fixturesOf(b)) {
      fixtureIndex.set(f, fixtureIndex.size);
      d.add(f.m_shape.m_type);
      d.add(f.m_shape.m_radius);
      d.add(f.m_density);
      d.add(f.m_friction);
      d.add(f.m_restitution);
      d.add(f.m_isSensor ? 1 : 0);
      d.add(f.m_filter.categoryBits);
      d.add(f.m_filter.maskBits);
      d.add(f.m_filter.groupIndex);
      d.add(f.m_proxyCount);
      for (let i = 0; i < f.m_proxyCount; ++i) {
        const proxy = f.m_proxies[i];
        d.add(proxy.proxyId);
        d.addVec(proxy.aabb.lowerBound);
        d.addVec(proxy.aabb.upperBound);
      }
    }
  }
  const joints = jointsOf(world);
  d.add(joints.length);
  for (const j of joints) {
    d.add(j.m_type);
    d.add(bodyIndex.get(j.m_bodyA) ?? -1);
    d.add(bodyIndex.get(j.m_bodyB) ?? -1);
    forEachNumber(j, (_name, value) => d.add(value));
  }
  const contacts = contactsOf(world);
  d.add(contacts.length);
  for (const c of contacts) {
    d.add(fixtureIndex.get(c.m_fixtureA) ?? -1);
    d.add(fixtureIndex.get(c.m_fixtureB) ?? -1);
    d.add(c.m_indexA);
    d.add(c.m_indexB);
    d.add(c.m_flags);
    d.add(c.m_toiCount);
    d.add(c.m_toi);
    d.add(c.m_friction);
    d.add(c.m_restitution);
    const m = c.m_manifold;
    d.add(m.type);
    d.add(m.pointCount);
    d.addVec(m.localNormal);
    d.addVec(m.localPoint);
    for (let i = 0; i < m.pointCount; ++i) {
      const p = m.points[i];
      d.addVec(p.localPoint);
      d.add(p.normalImpulse);
      d.add(p.tangentImpulse);
      d.add(p.id.key);
    }
  }
  const bp = world.m_contactManager.m_broadPhase;
  const tree = bp.m_tree;
  d.add(bp.m_proxyCount);
  d.add(bp.m_moveCount);
  for (let i = 0; i < bp.m_moveCount; ++i) d.add(bp.m_moveBuffer[i]);
  d.add(tree.m_root);
  d.add(tree.m_nodeCount);
  d.add(tree.m_nodeCapacity);
  d.add(tree.m_freeList);
  for (let i = 0; i < tree.m_nodeCapacity; ++i) {
    const node = tree.GetNode(i);
    d.add(node.parent);
    d.add(node.child1);
    d.add(node.child2);
    d.add(node.height);
    if (node.height >= 0) {
      d.addVec(node.aabb.lowerBound);
      d.addVec(node.aabb.upperBound);
    }
  }
  return d.hex();
}

/** The six per-body values of the golden digest, over the world's bodies in creation order. */
export function motionDigest(world: b2World): string {
  const d = new Digest();
  for (const b of bodiesOf(world).reverse()) {
    d.addVec(b.m_xf.p);
    d.add(b.m_sweep.a);
    d.addVec(b.m_linearVelocity);
    d.add(b.m_angularVelocity);
  }
  return d.hex();
}

function finite(problems: string[], what: string, x: number): void {
  if (!Number.isFinite(x)) problems.push(`${what} is ${x}`);
}

/**
 * Check the world's structural invariants; returns the problems found (empty when sound):
 * list counts, links and ownership; one broad-phase proxy per child of every fixture of an active
 * body and none for an inactive one; contacts linked into both bodies' edge lists, between live
 * fixtures of active bodies, each in the contact manager's pair set under its proxies and nothing
 * else there; joint edges in both bodies' lists; a valid tree; no NaN or infinity in bodies,
 * joints or contacts.
 */
export function checkWorldInvariants(world: b2World): string[] {
  const problems: string[] = [];
  const bp = world.m_contactManager.m_broadPhase;
  const tree = bp.m_tree;
  const bodies = bodiesOf(world);
  const bodySet = new Set(bodies);
  if (bodies.length !== world.m_bodyCount) problems.push(`body list has ${bodies.length}, m_bodyCount ${world.m_bodyCount}`);
  let proxies = 0;
  const fixtures = new Set<b2Fixture>();
  for (let i = 0; i < bodies.length; ++i) {
    const b = bodies[i];
    const where = `body[${i}]`;
    if (b.m_destroyed) problems.push(`${where} is destroyed but listed`);
    if (b.m_world !== world) problems.push(`${where} belongs to another world`);
    if (b.m_prev !== (i > 0 ? bodies[i - 1] : null)) problems.push(`${where}.m_prev is wrong`);
    if (![b2BodyType.b2_staticBody, b2BodyType.b2_kinematicBody, b2BodyType.b2_dynamicBody].includes(b.m_type)) {
      problems.push(`${where} has type ${b.m_type}`);
    }
    finite(problems, `${where}.x`, b.m_xf.p.x);
    finite(problems, `${where}.y`, b.m_xf.p.y);
    finite(problems, `${where}.q.s`, b.m_xf.q.s);
    finite(problems, `${where}.q.c`, b.m_xf.q.c);
    finite(problems, `${where}.angle`, b.m_sweep.a);
    finite(problems, `${where}.c0.x`, b.m_sweep.c0.x);
    finite(problems, `${where}.c0.y`, b.m_sweep.c0.y);
    finite(problems, `${where}.vx`, b.m_linearVelocity.x);
    finite(problems, `${where}.vy`, b.m_linearVelocity.y);
    finite(problems, `${where}.w`, b.m_angularVelocity);
    finite(problems, `${where}.force.x`, b.m_force.x);
    finite(problems, `${where}.torque`, b.m_torque);
    finite(problems, `${where}.mass`, b.m_mass);
    finite(problems, `${where}.I`, b.m_I);
    if (b.m_type === b2BodyType.b2_dynamicBody && !(b.m_mass > 0)) problems.push(`${where} is dynamic with mass ${b.m_mass}`);
    if (b.m_type !== b2BodyType.b2_dynamicBody && b.m_invMass !== 0) problems.push(`${where} is not dynamic but has invMass`);
    const list = fixturesOf(b);
    if (list.length !== b.m_fixtureCount) problems.push(`${where} lists ${list.length} fixtures, m_fixtureCount ${b.m_fixtureCount}`);
    for (let k = 0; k < list.length; ++k) {
      const f = list[k];
      const fw = `${where}.fixture[${k}]`;
      fixtures.add(f);
      if (f.m_destroyed) problems.push(`${fw} is destroyed but listed`);
      if (f.m_body !== b) problems.push(`${fw}.m_body is another body`);
      const expected = b.IsActive() ? f.m_shape.GetChildCount() : 0;
      if (f.m_proxyCount !== expected) problems.push(`${fw} has ${f.m_proxyCount} proxies, expected ${expected}`);
      for (let p = 0; p < f.m_proxyCount; ++p) {
        const proxy = f.m_proxies[p];
        const id = proxy.proxyId;
        if (id === b2BroadPhase.e_nullProxy || id < 0 || id >= tree.m_nodeCapacity) {
          problems.push(`${fw}.proxy[${p}] has id ${id}`);
          continue;
        }
        const node = tree.GetNode(id);
        if (node.height !== 0 || node.userData !== proxy) problems.push(`${fw}.proxy[${p}] is not its tree leaf`);
        if (proxy.fixture !== f || proxy.childIndex !== p) problems.push(`${fw}.proxy[${p}] names another fixture or child`);
        const fat = node.aabb;
        const a = proxy.aabb;
        if (
          !(fat.lowerBound.x <= a.lowerBound.x && fat.lowerBound.y <= a.lowerBound.y) ||
          !(a.upperBound.x <= fat.upperBound.x && a.upperBound.y <= fat.upperBound.y)
        ) {
          problems.push(`${fw}.proxy[${p}]'s fat AABB does not contain its AABB`);
        }
        ++proxies;
      }
    }
  }
  if (proxies !== bp.m_proxyCount) problems.push(`fixtures hold ${proxies} proxies, the broad-phase ${bp.m_proxyCount}`);
  let leaves = 0;
  for (let i = 0; i < tree.m_nodeCapacity; ++i) if (tree.GetNode(i).height === 0) ++leaves;
  if (leaves !== proxies) problems.push(`the tree has ${leaves} leaves for ${proxies} proxies`);
  try {
    tree.Validate();
  } catch (e) {
    problems.push(`tree: ${(e as Error).message}`);
  }
  if (tree.m_root !== b2_nullNode && tree.GetNode(tree.m_root).parent !== b2_nullNode) problems.push('tree root has a parent');

  const joints = jointsOf(world);
  const jointSet = new Set(joints);
  if (joints.length !== world.m_jointCount) problems.push(`joint list has ${joints.length}, m_jointCount ${world.m_jointCount}`);
  for (let i = 0; i < joints.length; ++i) {
    const j = joints[i];
    const where = `joint[${i}]`;
    if (j.m_destroyed) problems.push(`${where} is destroyed but listed`);
    if (!bodySet.has(j.m_bodyA) || !bodySet.has(j.m_bodyB)) problems.push(`${where} joins a body not in the world`);
    let inA = false;
    for (let e = j.m_bodyA.m_jointList; e !== null; e = e.next) if (e === j.m_edgeA) inA = true;
    let inB = false;
    for (let e = j.m_bodyB.m_jointList; e !== null; e = e.next) if (e === j.m_edgeB) inB = true;
    if (!inA || !inB) problems.push(`${where} is missing from a body's joint list`);
    forEachNumber(j, (name, value) => finite(problems, `${where}.${name}`, value));
  }
  for (let i = 0; i < bodies.length; ++i) {
    for (let e = bodies[i].m_jointList; e !== null; e = e.next) {
      if (!jointSet.has(e.joint)) problems.push(`body[${i}] lists a joint not in the world`);
    }
  }

  const contacts = contactsOf(world);
  const contactSet = new Set(contacts);
  if (contacts.length !== world.m_contactManager.m_contactCount) {
    problems.push(`contact list has ${contacts.length}, m_contactCount ${world.m_contactManager.m_contactCount}`);
  }
  const pairs = new Set<string>();
  const fixtureIds = new Map<b2Fixture, number>();
  for (const f of fixtures) fixtureIds.set(f, fixtureIds.size);
  for (let i = 0; i < contacts.length; ++i) {
    const c = contacts[i];
    const where = `contact[${i}]`;
    const fA = c.m_fixtureA;
    const fB = c.m_fixtureB;
    if (!fixtures.has(fA) || !fixtures.has(fB)) {
      problems.push(`${where} refers to a fixture not in the world`);
      continue;
    }
    const bA = fA.m_body;
    const bB = fB.m_body;
    if (bA === bB) problems.push(`${where} joins a body to itself`);
    if (!bA.IsActive() || !bB.IsActive()) problems.push(`${where} involves an inactive body`);
    let inA = false;
    for (let e = bA.m_contactList; e !== null; e = e.next) if (e === c.m_nodeA) inA = true;
    let inB = false;
    for (let e = bB.m_contactList; e !== null; e = e.next) if (e === c.m_nodeB) inB = true;
    if (!inA || !inB) problems.push(`${where} is missing from a body's contact list`);
    if (c.m_nodeA.other !== bB || c.m_nodeB.other !== bA) problems.push(`${where}'s edges name the wrong bodies`);
    const ids = [fixtureIds.get(fA)!, c.m_indexA, fixtureIds.get(fB)!, c.m_indexB];
    const key = ids[0] < ids[2] ? ids.join(',') : [ids[2], ids[3], ids[0], ids[1]].join(',');
    if (pairs.has(key)) problems.push(`${where} duplicates another contact`);
    pairs.add(key);
    const proxyIdA = fA.m_proxies[c.m_indexA]?.proxyId;
    const proxyIdB = fB.m_proxies[c.m_indexB]?.proxyId;
    if (c.m_proxyIdA !== proxyIdA || c.m_proxyIdB !== proxyIdB) problems.push(`${where} records other proxies than its fixtures'`);
    if (!world.m_contactManager.m_pairs.Has(c.m_proxyIdA, c.m_proxyIdB)) problems.push(`${where} is missing from the pair set`);
    const m = c.m_manifold;
    for (let p = 0; p < m.pointCount; ++p) {
      finite(problems, `${where}.point[${p}].normalImpulse`, m.points[p].normalImpulse);
      finite(problems, `${where}.point[${p}].x`, m.points[p].localPoint.x);
    }
  }
  for (let i = 0; i < bodies.length; ++i) {
    for (let e = bodies[i].m_contactList; e !== null; e = e.next) {
      if (!contactSet.has(e.contact)) problems.push(`body[${i}] lists a contact not in the world`);
    }
  }
  const pairCount = world.m_contactManager.m_pairs.GetCount();
  if (pairCount !== contacts.length) problems.push(`the pair set holds ${pairCount} pairs for ${contacts.length} contacts`);
  return problems;
}

/** Sizes of the world's internal pools and buffers, to check they stay bounded. */
export function poolSizes(world: b2World): Record<string, number> {
  const bp = world.m_contactManager.m_broadPhase;
  const w = world as unknown as {
    m_island: {
      m_bodyCapacity: number;
      m_contactCapacity: number;
      m_jointCapacity: number;
      m_bodies: unknown[];
      m_contacts: unknown[];
      m_joints: unknown[];
      m_positions: Float64Array;
      m_velocities: Float64Array;
    };
    m_stack: unknown[];
    m_queryWrappers: unknown[];
    m_rayCastWrappers: unknown[];
  };
  const island = w.m_island;
  return {
    treeNodeCapacity: bp.m_tree.m_nodeCapacity,
    treeNodeCount: bp.m_tree.m_nodeCount,
    moveCapacity: bp.m_moveCapacity,
    pairCapacity: bp.m_pairCapacity,
    pairBuffer: bp.m_pairBuffer.length,
    islandBodies: island.m_bodies.length,
    islandContacts: island.m_contacts.length,
    islandJoints: island.m_joints.length,
    // records of three doubles a body (see b2SolverData)
    islandPositions: island.m_positions.length / 3,
    islandVelocities: island.m_velocities.length / 3,
    stack: w.m_stack.length,
    queryWrappers: w.m_queryWrappers.length,
    rayCastWrappers: w.m_rayCastWrappers.length,
  };
}

/** Kinetic energy: sum of m |v|^2 / 2 + I w^2 / 2 over dynamic bodies (I about the center of mass). */
export function kineticEnergy(world: b2World): number {
  let e = 0;
  for (let b = world.m_bodyList; b !== null; b = b.m_next) {
    if (b.m_type !== b2BodyType.b2_dynamicBody) continue;
    const v = b.m_linearVelocity;
    e += 0.5 * b.m_mass * (v.x * v.x + v.y * v.y) + 0.5 * b.m_I * b.m_angularVelocity * b.m_angularVelocity;
  }
  return e;
}
