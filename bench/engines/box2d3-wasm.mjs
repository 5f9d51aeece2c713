// box2d3-wasm (Birch-san): Box2D v3 compiled by Emscripten to WebAssembly (embind API). In Node its
// entry point picks the "deluxe" build (SIMD, pthreads-capable); the world is created with the
// default single worker and no task system, so it runs on one thread like every other engine here.
// v3 has no velocity/position iteration counts: it steps with 4 substeps (its recommended default).
import { packageVersion, oneSidedChain } from './common.mjs';

export const V3_SUBSTEPS = 4;

export default {
  id: 'box2d3-wasm',
  name: 'box2d3-wasm',
  pkg: 'box2d3-wasm',
  family: 'Box2D v3, C to WebAssembly',
  version: packageVersion('box2d3-wasm'),
  notes: [
    `${V3_SUBSTEPS} substeps instead of velocity/position iterations (v3 has none)`,
    'contact events off (no listener, as in the other engines); chains one-sided, oriented to face the bodies',
  ],

  async load() {
    const factory = (await import('box2d3-wasm')).default;
    return factory();
  },

  supports() {
    return null;
  },

  create(B, scene, { sleep }) {
    const wd = B.b2DefaultWorldDef();
    wd.gravity.Set(scene.gravity[0], scene.gravity[1]);
    wd.enableSleep = sleep;
    const worldId = B.b2CreateWorld(wd);
    wd.delete();
    const bodies = [];
    const types = { static: B.b2BodyType.b2_staticBody, kinematic: B.b2BodyType.b2_kinematicBody, dynamic: B.b2BodyType.b2_dynamicBody };

    const shapeDef = (s) => {
      const sd = B.b2DefaultShapeDef();
      sd.density = s.density;
      sd.material.friction = s.friction;
      sd.material.restitution = s.restitution;
      sd.enableContactEvents = false;
      if (s.category !== 1 || s.mask !== 0xffff) {
        sd.filter.setCategoryBits64(String(s.category));
        sd.filter.setMaskBits64(String(s.mask));
      }
      return sd;
    };

    const add = (d) => {
      const bd = B.b2DefaultBodyDef();
      bd.type = types[d.type];
      bd.position.Set(d.x, d.y);
      const rot = B.b2MakeRot(d.angle);
      bd.rotation = rot;
      rot.delete();
      bd.linearVelocity.Set(d.vx, d.vy);
      bd.angularVelocity = d.w;
      bd.isBullet = d.bullet;
      bd.enableSleep = d.allowSleep;
      const id = B.b2CreateBody(worldId, bd);
      bd.delete();
      for (const s of d.shapes) {
        if (s.kind === 'chain') {
          const c = oneSidedChain(s);
          const cd = B.b2DefaultChainDef();
          const pts = c.loop ? c.points : [c.prev, ...c.points, c.next];
          cd.SetPoints(pts.map((p) => ({ x: p[0], y: p[1] })));
          cd.isLoop = c.loop;
          cd.SetMaterials([{ friction: s.friction, restitution: s.restitution }]);
          B.b2CreateChain(id, cd);
          cd.delete();
          continue;
        }
        const sd = shapeDef(s);
        if (s.kind === 'box' || s.kind === 'polygon') {
          let poly;
          if (s.kind === 'box' && s.cx === undefined) poly = B.b2MakeBox(s.hx, s.hy);
          else if (s.kind === 'box') {
            const c = new B.b2Vec2(s.cx, s.cy);
            const r = B.b2MakeRot(s.angle);
            poly = B.b2MakeOffsetBox(s.hx, s.hy, c, r);
            c.delete();
            r.delete();
          } else {
            const hull = B.b2ComputeHull(s.vertices.map((p) => ({ x: p[0], y: p[1] })));
            poly = B.b2MakePolygon(hull, 0);
            hull.delete();
          }
          B.b2CreatePolygonShape(id, sd, poly);
          poly.delete();
        } else if (s.kind === 'circle') {
          const circle = new B.b2Circle();
          circle.center.Set(s.cx ?? 0, s.cy ?? 0);
          circle.radius = s.r;
          B.b2CreateCircleShape(id, sd, circle);
          circle.delete();
        } else if (s.kind === 'edge') {
          const seg = new B.b2Segment();
          seg.point1.Set(s.v1[0], s.v1[1]);
          seg.point2.Set(s.v2[0], s.v2[1]);
          B.b2CreateSegmentShape(id, sd, seg);
          seg.delete();
        }
        sd.delete();
      }
      bodies.push(id);
    };
    for (const d of scene.bodies) add(d);
    for (const j of scene.joints) {
      const jd = B.b2DefaultRevoluteJointDef();
      jd.base.bodyIdA = bodies[j.a];
      jd.base.bodyIdB = bodies[j.b];
      jd.base.localFrameA.p.Set(j.ax, j.ay);
      jd.base.localFrameB.p.Set(j.bx, j.by);
      jd.base.collideConnected = j.collideConnected;
      if (j.motor) {
        jd.enableMotor = true;
        jd.motorSpeed = j.motor.speed;
        jd.maxMotorTorque = j.motor.maxTorque;
      }
      B.b2CreateRevoluteJoint(worldId, jd);
      jd.delete();
    }

    const dt = scene.dt;
    const counters = () => {
      const c = B.b2World_GetCounters(worldId);
      const out = { bodies: c.bodyCount, contacts: c.contactCount };
      c.delete();
      return out;
    };
    return {
      step: () => B.b2World_Step(worldId, dt, V3_SUBSTEPS),
      add,
      bodyCount: () => counters().bodies,
      contactCount: () => counters().contacts,
      position: (i) => {
        const id = bodies[i];
        if (!id) return null;
        const p = B.b2Body_GetPosition(id);
        const out = [p.x, p.y];
        p.delete();
        return out;
      },
      wasmBytes: () => B.HEAPU8.buffer.byteLength,
      destroy: () => {
        B.b2DestroyWorld(worldId);
        bodies.length = 0;
      },
    };
  },
};
