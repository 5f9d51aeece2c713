// phaser-box2d (Phaser Studio): Box2D v3 (3.1) ported to JavaScript. Its package "main" points at a
// missing index.js, so the harness imports dist/PhaserBox2D.js. 4 substeps, as box2d3-wasm.
// b2World_GetCounters is an empty stub in this build, so it reports no contact count.
//
// World slots: a module instance has 32 worlds (B2_MAX_WORLDS), and b2DestroyWorld never frees one
// (it assigns the fresh b2World to a local variable and leaves the slot marked in use), so after 32
// worlds b2CreateWorld fails. The harness builds more than that, so the adapter loads several
// instances of the module (the same file under different query strings) and moves to a fresh one
// between scenes once half the slots are used (or mid-scene, should one run out). Each instance is JIT-compiled on its own; the
// warm-up steps of the scene's first round cover that.
import { packageVersion, oneSidedChain, repoRoot } from './common.mjs';
import { V3_SUBSTEPS } from './box2d3-wasm.mjs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const SLOTS = 32;
const INSTANCES = 6;
export default {
  id: 'phaser-box2d',
  name: 'phaser-box2d',
  pkg: 'phaser-box2d',
  family: 'Box2D v3.1, JavaScript',
  version: packageVersion('phaser-box2d'),
  notes: [`${V3_SUBSTEPS} substeps instead of velocity/position iterations (v3 has none)`, 'contact events off; chains one-sided, oriented to face the bodies'],

  async load() {
    const url = pathToFileURL(path.join(repoRoot, 'node_modules', 'phaser-box2d', 'dist', 'PhaserBox2D.js')).href;
    const instances = [];
    for (let i = 0; i < INSTANCES; i++) {
      const P = await import(i === 0 ? url : `${url}?instance=${i}`);
      P.b2CreateWorldArray(); // the world registry, which b2CreateWorld needs first
      instances.push(P);
    }
    return { instances, current: 0, used: 0, lastScene: null };
  },

  supports() {
    return null;
  },

  create(holder, scene, { sleep }) {
    if ((scene.id !== holder.lastScene && holder.used > SLOTS / 2) || holder.used >= SLOTS) {
      holder.current++;
      holder.used = 0;
      if (holder.current >= holder.instances.length) throw new Error('phaser-box2d: out of world slots');
    }
    holder.lastScene = scene.id;
    holder.used++;
    const P = holder.instances[holder.current];
    const wd = P.b2DefaultWorldDef();
    wd.gravity = new P.b2Vec2(scene.gravity[0], scene.gravity[1]);
    wd.enableSleep = sleep;
    const worldId = P.b2CreateWorld(wd);
    if (worldId.index1 === 0) throw new Error('phaser-box2d: b2CreateWorld found no free world slot');
    const bodies = [];
    const types = { static: P.b2BodyType.b2_staticBody, kinematic: P.b2BodyType.b2_kinematicBody, dynamic: P.b2BodyType.b2_dynamicBody };
    const vec = (p) => new P.b2Vec2(p[0], p[1]);

    const add = (d) => {
      const bd = P.b2DefaultBodyDef();
      bd.type = types[d.type];
      bd.position = new P.b2Vec2(d.x, d.y);
      bd.rotation = P.b2MakeRot(d.angle);
      bd.linearVelocity = new P.b2Vec2(d.vx, d.vy);
      bd.angularVelocity = d.w;
      bd.isBullet = d.bullet;
      bd.enableSleep = d.allowSleep;
      const id = P.b2CreateBody(worldId, bd);
      for (const s of d.shapes) {
        if (s.kind === 'chain') {
          const c = oneSidedChain(s);
          const cd = P.b2DefaultChainDef();
          const pts = c.loop ? c.points : [c.prev, ...c.points, c.next];
          cd.points = pts.map(vec);
          cd.count = pts.length;
          cd.isLoop = c.loop;
          cd.friction = s.friction;
          cd.restitution = s.restitution;
          P.b2CreateChain(id, cd);
          continue;
        }
        const sd = P.b2DefaultShapeDef();
        sd.density = s.density;
        sd.friction = s.friction;
        sd.restitution = s.restitution;
        sd.enableContactEvents = false;
        sd.filter.categoryBits = s.category;
        sd.filter.maskBits = s.mask === 0xffff ? sd.filter.maskBits : s.mask;
        if (s.kind === 'box') {
          const poly = s.cx === undefined ? P.b2MakeBox(s.hx, s.hy) : P.b2MakeOffsetBox(s.hx, s.hy, new P.b2Vec2(s.cx, s.cy), s.angle);
          P.b2CreatePolygonShape(id, sd, poly);
        } else if (s.kind === 'polygon') {
          const hull = P.b2ComputeHull(s.vertices.map(vec), s.vertices.length);
          P.b2CreatePolygonShape(id, sd, P.b2MakePolygon(hull, 0));
        } else if (s.kind === 'circle') {
          P.b2CreateCircleShape(id, sd, new P.b2Circle(new P.b2Vec2(s.cx ?? 0, s.cy ?? 0), s.r));
        } else if (s.kind === 'edge') {
          P.b2CreateSegmentShape(id, sd, new P.b2Segment(vec(s.v1), vec(s.v2)));
        }
      }
      bodies.push(id);
    };
    for (const d of scene.bodies) add(d);
    for (const j of scene.joints) {
      const jd = P.b2DefaultRevoluteJointDef();
      jd.bodyIdA = bodies[j.a];
      jd.bodyIdB = bodies[j.b];
      jd.localAnchorA = new P.b2Vec2(j.ax, j.ay);
      jd.localAnchorB = new P.b2Vec2(j.bx, j.by);
      jd.referenceAngle = j.refAngle;
      jd.collideConnected = j.collideConnected;
      if (j.motor) {
        jd.enableMotor = true;
        jd.motorSpeed = j.motor.speed;
        jd.maxMotorTorque = j.motor.maxTorque;
      }
      P.b2CreateRevoluteJoint(worldId, jd);
    }

    const dt = scene.dt;
    return {
      step: () => P.b2World_Step(worldId, dt, V3_SUBSTEPS),
      add,
      bodyCount: () => bodies.length,
      contactCount: () => null,
      position: (i) => {
        const id = bodies[i];
        if (!id) return null;
        const p = P.b2Body_GetPosition(id);
        return [p.x, p.y];
      },
      destroy: () => {
        P.b2DestroyWorld(worldId);
        bodies.length = 0;
      },
    };
  },
};
