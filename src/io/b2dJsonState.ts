/*
 * The `webphysicsState` extension of b2dJson: the solver state that plain b2dJson has no place for,
 * so that a world written mid-run and read back steps on bit for bit like the original.
 *
 * Plain b2dJson describes a world as its definitions: it cannot hold contacts (with their
 * warm-starting impulses, manifolds, TOI counts and flags), the broad-phase tree (whose proxy ids
 * and shape fix the order of new pairs, hence of contacts and of the solver), sleep timers, sweeps
 * (c0, a0, alpha0), accumulated forces, exact mass data, the joints' accumulated impulses and
 * limit states, or the world's step state (inv_dt0 for warm-starting ratios, an unfinished
 * sub-stepped TOI phase). `b2dJsonWrite(world, { solverState: true })` adds all of this under the
 * top-level key `webphysicsState`; b2dJson readers that do not know it ignore it (unknown keys are
 * skipped by iforce2d's b2dJson and R.U.B.E.), and the rest of the document is unchanged plain
 * b2dJson. b2dJsonRead applies it after building the world from the plain part, overwriting:
 * - the world's flags, inv_dt0 and stepComplete;
 * - every body's flags (awake, island...), transform, sweep, velocities, force and torque, mass
 *   data, damping, gravity scale, sleep time and island index;
 * - every fixture's proxy ids and proxy AABBs, and every polygon's normals and centroid (which
 *   Set() would recompute, perhaps differently in the last bit from a polygon built otherwise);
 * - every number and flag a joint holds (impulses, limit states, motor and spring settings...);
 * - the broad-phase: the dynamic tree node for node (ids, links, heights, fat AABBs, free list)
 *   and the move buffer;
 * - the contacts, recreated in their creation order (which rebuilds the world's list and every
 *   body's edge list in the original order) with flags, TOI state, friction, restitution and the
 *   manifold with its impulses and feature ids.
 * Not carried: listeners, filters, the destruction listener and debug draw (code, not data; set
 * them again), user data, and the profile and timers (which do not affect results).
 * The arrays are in b2dJson's creation order: `bodies[i]` is `body[i]`, `joints[i]` is `joint[i]`.
 */

import { b2Mat22, b2Mat33, b2Rot, b2Vec2, b2Vec3 } from '../common/b2Math';
import type { b2PolygonShape } from '../collision/shapes/b2PolygonShape';
import { b2Shape } from '../collision/shapes/b2Shape';
import { b2TreeNode } from '../collision/b2DynamicTree';
import type { b2Body } from '../dynamics/b2Body';
import type { b2Fixture } from '../dynamics/b2Fixture';
import type { b2World } from '../dynamics/b2World';
import { b2Contact } from '../dynamics/contacts/b2Contact';
import { b2Jacobian } from '../dynamics/joints/b2Joint';
import type { b2Joint } from '../dynamics/joints/b2Joint';
import { b2dJsonError, b2dJsonFixturesInCreationOrder } from './b2dJsonScene';
import type { b2dJsonObject, b2dJsonValue } from './b2dJsonScene';

/** The extension's key in the document, and its version. */
export const b2dJson_stateKey = 'webphysicsState';
export const b2dJson_stateVersion = 1;

function isValueObject(value: unknown): boolean {
  return (
    value instanceof b2Vec2 ||
    value instanceof b2Vec3 ||
    value instanceof b2Mat22 ||
    value instanceof b2Mat33 ||
    value instanceof b2Rot ||
    value instanceof b2Jacobian
  );
}

/**
 * Visit the numbers and booleans of an object's own fields, recursing into the math value objects
 * (b2Vec2, b2Vec3, b2Mat22, b2Mat33, b2Rot, b2Jacobian) it owns; references to other engine
 * objects (bodies, joints, edges) and user data are skipped. The names are dotted paths.
 */
export function b2dJsonForEachField(object: object, visit: (name: string, value: number | boolean) => void, prefix = ''): void {
  for (const key of Object.keys(object)) {
    const value = (object as Record<string, unknown>)[key];
    const name = prefix === '' ? key : `${prefix}.${key}`;
    if (typeof value === 'number' || typeof value === 'boolean') {
      if (key !== 'm_userData') visit(name, value);
    } else if (isValueObject(value)) {
      b2dJsonForEachField(value as object, visit, name);
    }
  }
}

// Body layout: one array of numbers per body.
const kBodyFields = 30;

function writeBodyState(b: b2Body): number[] {
  const sw = b.m_sweep;
  return [
    b.m_type,
    b.m_flags,
    b.m_islandIndex,
    b.m_xf.p.x,
    b.m_xf.p.y,
    b.m_xf.q.s,
    b.m_xf.q.c,
    sw.localCenter.x,
    sw.localCenter.y,
    sw.c0.x,
    sw.c0.y,
    sw.c.x,
    sw.c.y,
    sw.a0,
    sw.a,
    sw.alpha0,
    b.m_linearVelocity.x,
    b.m_linearVelocity.y,
    b.m_angularVelocity,
    b.m_force.x,
    b.m_force.y,
    b.m_torque,
    b.m_mass,
    b.m_invMass,
    b.m_I,
    b.m_invI,
    b.m_linearDamping,
    b.m_angularDamping,
    b.m_gravityScale,
    b.m_sleepTime,
  ];
}

function readBodyState(b: b2Body, s: readonly number[]): void {
  let i = 0;
  b.m_type = s[i++];
  b.m_flags = s[i++];
  b.m_islandIndex = s[i++];
  b.m_xf.p.x = s[i++];
  b.m_xf.p.y = s[i++];
  b.m_xf.q.s = s[i++];
  b.m_xf.q.c = s[i++];
  const sw = b.m_sweep;
  sw.localCenter.x = s[i++];
  sw.localCenter.y = s[i++];
  sw.c0.x = s[i++];
  sw.c0.y = s[i++];
  sw.c.x = s[i++];
  sw.c.y = s[i++];
  sw.a0 = s[i++];
  sw.a = s[i++];
  sw.alpha0 = s[i++];
  b.m_linearVelocity.x = s[i++];
  b.m_linearVelocity.y = s[i++];
  b.m_angularVelocity = s[i++];
  b.m_force.x = s[i++];
  b.m_force.y = s[i++];
  b.m_torque = s[i++];
  b.m_mass = s[i++];
  b.m_invMass = s[i++];
  b.m_I = s[i++];
  b.m_invI = s[i++];
  b.m_linearDamping = s[i++];
  b.m_angularDamping = s[i++];
  b.m_gravityScale = s[i++];
  b.m_sleepTime = s[i++];
}

function writeFixtureState(f: b2Fixture): b2dJsonObject {
  const proxies: number[][] = [];
  for (let i = 0; i < f.m_proxyCount; ++i) {
    const p = f.m_proxies[i];
    proxies.push([p.proxyId, p.childIndex, p.aabb.lowerBound.x, p.aabb.lowerBound.y, p.aabb.upperBound.x, p.aabb.upperBound.y]);
  }
  const o: b2dJsonObject = { proxies };
  if (f.m_shape.m_type === b2Shape.e_polygon) {
    const polygon = f.m_shape as b2PolygonShape;
    const normals: number[] = [];
    for (let i = 0; i < polygon.m_vertexCount; ++i) normals.push(polygon.m_normals[i].x, polygon.m_normals[i].y);
    o.polygon = { radius: polygon.m_radius, centroid: [polygon.m_centroid.x, polygon.m_centroid.y], normals };
  }
  return o;
}

function writeJointState(j: b2Joint): b2dJsonObject {
  const o: b2dJsonObject = {};
  b2dJsonForEachField(j, (name, value) => {
    o[name] = value;
  });
  return o;
}

function writeContactState(c: b2Contact, fixtureRef: ReadonlyMap<b2Fixture, [number, number]>): b2dJsonObject {
  const m = c.m_manifold;
  const points: number[][] = [];
  for (let i = 0; i < m.pointCount; ++i) {
    const p = m.points[i];
    points.push([p.localPoint.x, p.localPoint.y, p.normalImpulse, p.tangentImpulse, p.id.key]);
  }
  const a = fixtureRef.get(c.m_fixtureA);
  const b = fixtureRef.get(c.m_fixtureB);
  if (a === undefined || b === undefined) {
    throw new b2dJsonError(b2dJson_stateKey, 'a contact refers to a fixture that is not in the world', 'b2dJsonWrite');
  }
  return {
    fixtureA: [a[0], a[1], c.m_indexA],
    fixtureB: [b[0], b[1], c.m_indexB],
    flags: c.m_flags,
    toiCount: c.m_toiCount,
    toi: c.m_toi,
    friction: c.m_friction,
    restitution: c.m_restitution,
    manifold: {
      type: m.type,
      localNormal: [m.localNormal.x, m.localNormal.y],
      localPoint: [m.localPoint.x, m.localPoint.y],
      points,
    },
  };
}

/** The `webphysicsState` object for a world whose bodies and joints are listed in creation order. */
export function b2dJsonWriteState(world: b2World, bodies: readonly b2Body[], joints: readonly b2Joint[]): b2dJsonObject {
  if (world.IsLocked()) {
    throw new b2dJsonError(b2dJson_stateKey, 'cannot capture the solver state in the middle of a time step', 'b2dJsonWrite');
  }
  const fixtureRef = new Map<b2Fixture, [number, number]>();
  const bodyStates: b2dJsonValue[] = [];
  for (let i = 0; i < bodies.length; ++i) {
    const fixtures = b2dJsonFixturesInCreationOrder(bodies[i]);
    fixtures.forEach((f, k) => fixtureRef.set(f, [i, k]));
    bodyStates.push({ state: writeBodyState(bodies[i]), fixtures: fixtures.map(writeFixtureState) });
  }
  // The world's list is prepended: its reverse is creation order.
  const contacts: b2Contact[] = [];
  for (let c = world.m_contactManager.m_contactList; c !== null; c = c.m_next) contacts.push(c);
  contacts.reverse();

  const bp = world.m_contactManager.m_broadPhase;
  const tree = bp.m_tree;
  const nodes: number[][] = [];
  const node = new b2TreeNode();
  for (let i = 0; i < tree.m_nodeCapacity; ++i) {
    const n = tree.GetNode(i, node);
    nodes.push(
      n.height < 0
        ? [n.parent, n.child1, n.child2, n.height]
        : [n.parent, n.child1, n.child2, n.height, n.aabb.lowerBound.x, n.aabb.lowerBound.y, n.aabb.upperBound.x, n.aabb.upperBound.y],
    );
  }
  const moveBuffer: number[] = [];
  for (let i = 0; i < bp.m_moveCount; ++i) moveBuffer.push(bp.m_moveBuffer[i]);

  return {
    version: b2dJson_stateVersion,
    world: { flags: world.m_flags, inv_dt0: world.m_inv_dt0, stepComplete: world.m_stepComplete },
    bodies: bodyStates,
    joints: joints.map(writeJointState),
    contacts: contacts.map((c) => writeContactState(c, fixtureRef)),
    broadPhase: {
      proxyCount: bp.m_proxyCount,
      moveBuffer,
      tree: {
        root: tree.m_root,
        nodeCount: tree.m_nodeCount,
        freeList: tree.m_freeList,
        path: tree.m_path,
        insertionCount: tree.m_insertionCount,
        nodes,
      },
    },
  };
}

// Reading

function fail(path: string, rule: string): never {
  throw new b2dJsonError(path, rule);
}

function obj(value: unknown, path: string): b2dJsonObject {
  if (typeof value !== 'object' || value === null || Array.isArray(value)) fail(path, 'expected an object');
  return value as b2dJsonObject;
}

function arr(value: unknown, path: string, length?: number): unknown[] {
  if (!Array.isArray(value)) fail(path, 'expected an array');
  if (length !== undefined && value.length !== length) fail(path, `expected ${length} entries, got ${value.length}`);
  return value;
}

function num(value: unknown, path: string): number {
  if (typeof value !== 'number' || !Number.isFinite(value)) fail(path, 'expected a finite number');
  return value;
}

function int(value: unknown, path: string, min: number, max: number): number {
  const x = num(value, path);
  if (!Number.isInteger(x) || x < min || x > max) fail(path, `expected an integer in [${min}, ${max}], got ${x}`);
  return x;
}

function nums(value: unknown, path: string, length?: number): number[] {
  return arr(value, path, length).map((x, i) => num(x, `${path}[${i}]`));
}

function bool(value: unknown, path: string): boolean {
  if (typeof value !== 'boolean') fail(path, 'expected true or false');
  return value;
}

/** Set the joint's fields from the recorded ones; the two sets of names must be the same. */
function readJointState(j: b2Joint, o: b2dJsonObject, path: string): void {
  const expected = new Map<string, 'number' | 'boolean'>();
  b2dJsonForEachField(j, (name, value) => expected.set(name, typeof value as 'number' | 'boolean'));
  const names = Object.keys(o);
  for (const name of names) {
    const type = expected.get(name);
    if (type === undefined) fail(`${path}.${name}`, 'this joint type has no such field (state written by another version?)');
    const value = type === 'number' ? num(o[name], `${path}.${name}`) : bool(o[name], `${path}.${name}`);
    const parts = name.split('.');
    let target = j as unknown as Record<string, unknown>;
    for (let i = 0; i < parts.length - 1; ++i) target = target[parts[i]] as Record<string, unknown>;
    target[parts[parts.length - 1]] = value;
  }
  if (names.length !== expected.size) {
    const missing = [...expected.keys()].filter((name) => !Object.hasOwn(o, name));
    fail(path, `missing fields: ${missing.join(', ')}`);
  }
}

function fixtureAt(bodies: readonly b2Body[], fixtures: readonly b2Fixture[][], value: unknown, path: string): [b2Fixture, number] {
  const [bi, fi, ci] = arr(value, path, 3);
  const body = int(bi, `${path}[0]`, 0, bodies.length - 1);
  const fixture = fixtures[body][int(fi, `${path}[1]`, 0, fixtures[body].length - 1)];
  const child = int(ci, `${path}[2]`, 0, fixture.m_shape.GetChildCount() - 1);
  return [fixture, child];
}

/**
 * Apply a `webphysicsState` object to a world freshly built from the same document's plain part
 * (`bodies` and `joints` in creation order). Throws b2dJsonError naming the offending path.
 */
export function b2dJsonReadState(world: b2World, bodies: readonly b2Body[], joints: readonly b2Joint[], value: unknown): void {
  const root = b2dJson_stateKey;
  const o = obj(value, root);
  const version = o.version;
  if (version !== b2dJson_stateVersion) fail(`${root}.version`, `expected ${b2dJson_stateVersion}, got ${String(version)}`);

  const bodyStates = arr(o.bodies, `${root}.bodies`, bodies.length);
  const jointStates = arr(o.joints, `${root}.joints`, joints.length);
  const contactStates = arr(o.contacts, `${root}.contacts`);
  const bpState = obj(o.broadPhase, `${root}.broadPhase`);
  const treeState = obj(bpState.tree, `${root}.broadPhase.tree`);
  const worldState = obj(o.world, `${root}.world`);

  const bp = world.m_contactManager.m_broadPhase;
  const tree = bp.m_tree;
  if (world.m_contactManager.m_contactList !== null) fail(root, 'the world already has contacts');

  // The tree, node for node.
  const nodesPath = `${root}.broadPhase.tree.nodes`;
  const nodeStates = arr(treeState.nodes, nodesPath);
  const capacity = nodeStates.length;
  if (capacity < 16) fail(nodesPath, `expected at least 16 nodes, got ${capacity}`);
  const nodes: b2TreeNode[] = [];
  for (let i = 0; i < capacity; ++i) {
    const p = `${nodesPath}[${i}]`;
    const n = nums(nodeStates[i], p);
    const node = new b2TreeNode();
    if (n.length !== 4 && n.length !== 8) fail(p, `expected 4 or 8 numbers, got ${n.length}`);
    node.parent = int(n[0], `${p}[0]`, -1, capacity - 1);
    node.child1 = int(n[1], `${p}[1]`, -1, capacity - 1);
    node.child2 = int(n[2], `${p}[2]`, -1, capacity - 1);
    node.height = int(n[3], `${p}[3]`, -1, 0x7fffffff);
    if (n.length === 8) {
      node.aabb.lowerBound.Set(n[4], n[5]);
      node.aabb.upperBound.Set(n[6], n[7]);
    } else if (node.height >= 0) {
      fail(p, 'a node in use needs its AABB');
    }
    nodes.push(node);
  }

  // Bodies and fixtures; proxies become the tree's leaves.
  const fixtures: b2Fixture[][] = [];
  let leaves = 0;
  for (let i = 0; i < bodies.length; ++i) {
    const p = `${root}.bodies[${i}]`;
    const bs = obj(bodyStates[i], p);
    const body = bodies[i];
    readBodyState(body, nums(bs.state, `${p}.state`, kBodyFields));
    const list = b2dJsonFixturesInCreationOrder(body);
    fixtures.push(list);
    const fixtureStates = arr(bs.fixtures, `${p}.fixtures`, list.length);
    for (let k = 0; k < list.length; ++k) {
      const fp = `${p}.fixtures[${k}]`;
      const fs = obj(fixtureStates[k], fp);
      const f = list[k];
      const proxies = arr(fs.proxies, `${fp}.proxies`, f.m_proxyCount);
      for (let c = 0; c < proxies.length; ++c) {
        const pp = `${fp}.proxies[${c}]`;
        const q = nums(proxies[c], pp, 6);
        const proxy = f.m_proxies[c];
        proxy.proxyId = int(q[0], `${pp}[0]`, 0, capacity - 1);
        proxy.childIndex = int(q[1], `${pp}[1]`, 0, f.m_proxies.length - 1);
        proxy.aabb.lowerBound.Set(q[2], q[3]);
        proxy.aabb.upperBound.Set(q[4], q[5]);
        const node = nodes[proxy.proxyId];
        if (node.height !== 0 || node.userData !== null) fail(`${pp}[0]`, `tree node ${proxy.proxyId} is not a free leaf`);
        node.userData = proxy;
        ++leaves;
      }
      if (f.m_shape.m_type === b2Shape.e_polygon) {
        const polygon = f.m_shape as b2PolygonShape;
        const ps = obj(fs.polygon, `${fp}.polygon`);
        polygon.m_radius = num(ps.radius, `${fp}.polygon.radius`);
        const centroid = nums(ps.centroid, `${fp}.polygon.centroid`, 2);
        polygon.m_centroid.Set(centroid[0], centroid[1]);
        const normals = nums(ps.normals, `${fp}.polygon.normals`, 2 * polygon.m_vertexCount);
        for (let n = 0; n < polygon.m_vertexCount; ++n) polygon.m_normals[n].Set(normals[2 * n], normals[2 * n + 1]);
      }
    }
  }
  for (let i = 0; i < capacity; ++i) {
    if (nodes[i].height === 0 && nodes[i].userData === null) fail(`${nodesPath}[${i}]`, 'a leaf that no fixture proxy owns');
  }

  tree.SetNodes(nodes);
  tree.m_root = int(treeState.root, `${root}.broadPhase.tree.root`, -1, capacity - 1);
  tree.m_nodeCount = int(treeState.nodeCount, `${root}.broadPhase.tree.nodeCount`, 0, capacity);
  tree.m_freeList = int(treeState.freeList, `${root}.broadPhase.tree.freeList`, -1, capacity - 1);
  tree.m_path = int(treeState.path, `${root}.broadPhase.tree.path`, 0, 0x7fffffff);
  tree.m_insertionCount = int(treeState.insertionCount, `${root}.broadPhase.tree.insertionCount`, 0, Number.MAX_SAFE_INTEGER);
  try {
    tree.Validate();
  } catch (e) {
    fail(`${root}.broadPhase.tree`, `is not a valid dynamic tree (${e instanceof Error ? e.message : String(e)})`);
  }
  const proxyCount = int(bpState.proxyCount, `${root}.broadPhase.proxyCount`, 0, capacity);
  if (proxyCount !== leaves) fail(`${root}.broadPhase.proxyCount`, `is ${proxyCount} but the fixtures hold ${leaves} proxies`);
  bp.m_proxyCount = proxyCount;
  const moves = nums(bpState.moveBuffer, `${root}.broadPhase.moveBuffer`);
  bp.m_moveCount = 0;
  for (let i = 0; i < moves.length; ++i) bp.BufferMove(int(moves[i], `${root}.broadPhase.moveBuffer[${i}]`, -1, capacity - 1));

  for (let i = 0; i < joints.length; ++i) {
    readJointState(joints[i], obj(jointStates[i], `${root}.joints[${i}]`), `${root}.joints[${i}]`);
  }

  // The restored contacts carry TOI state that SolveTOI's next search must see (b2World.UpdateTOICandidates).
  world.m_toiCandidatesStale = true;

  // Contacts, in creation order, linked as b2ContactManager.AddPair links them (LinkContact).
  const cm = world.m_contactManager;
  for (let i = 0; i < contactStates.length; ++i) {
    const p = `${root}.contacts[${i}]`;
    const cs = obj(contactStates[i], p);
    const [fixtureA, indexA] = fixtureAt(bodies, fixtures, cs.fixtureA, `${p}.fixtureA`);
    const [fixtureB, indexB] = fixtureAt(bodies, fixtures, cs.fixtureB, `${p}.fixtureB`);
    if (fixtureA.m_proxyCount === 0 || fixtureB.m_proxyCount === 0) {
      fail(p, 'joins a fixture that has no broad-phase proxies (its body is inactive)');
    }
    const c = b2Contact.Create(fixtureA, indexA, fixtureB, indexB);
    if (c === null || c.m_fixtureA !== fixtureA || c.m_indexA !== indexA) {
      fail(p, 'these fixtures do not make a contact in this order');
    }
    cm.LinkContact(c);

    c.m_flags = int(cs.flags, `${p}.flags`, 0, 0xffff);
    // A contact written between an island search and the next one carries its island flag,
    // which the world's next Solve must clear (b2World.FlagContact).
    if (c.m_flags & b2Contact.e_islandFlag) world.FlagContact(c);
    c.m_toiCount = int(cs.toiCount, `${p}.toiCount`, 0, 0x7fffffff);
    c.m_toi = num(cs.toi, `${p}.toi`);
    c.m_friction = num(cs.friction, `${p}.friction`);
    c.m_restitution = num(cs.restitution, `${p}.restitution`);
    const ms = obj(cs.manifold, `${p}.manifold`);
    const m = c.m_manifold;
    m.type = int(ms.type, `${p}.manifold.type`, 0, 2);
    // Coordinates written one by one: the manifold's vectors are views onto its record, which
    // engine code keeps away from b2Vec2's methods (docs/PORTING.md, records).
    const ln = nums(ms.localNormal, `${p}.manifold.localNormal`, 2);
    m.localNormal.x = ln[0];
    m.localNormal.y = ln[1];
    const lp = nums(ms.localPoint, `${p}.manifold.localPoint`, 2);
    m.localPoint.x = lp[0];
    m.localPoint.y = lp[1];
    const points = arr(ms.points, `${p}.manifold.points`);
    if (points.length > m.points.length) fail(`${p}.manifold.points`, `expected at most ${m.points.length} points`);
    m.pointCount = points.length;
    for (let k = 0; k < points.length; ++k) {
      const q = nums(points[k], `${p}.manifold.points[${k}]`, 5);
      const mp = m.points[k];
      mp.localPoint.x = q[0];
      mp.localPoint.y = q[1];
      mp.normalImpulse = q[2];
      mp.tangentImpulse = q[3];
      mp.id.key = int(q[4], `${p}.manifold.points[${k}][4]`, 0, 0xffffffff);
    }
  }

  world.m_flags = int(worldState.flags, `${root}.world.flags`, 0, 0xffff);
  world.m_inv_dt0 = num(worldState.inv_dt0, `${root}.world.inv_dt0`);
  world.m_stepComplete = bool(worldState.stepComplete, `${root}.world.stepComplete`);
}
