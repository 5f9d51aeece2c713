// box2d-wasm (Birch-san): Box2D 2.4.1 compiled by Emscripten to WebAssembly, the stand-in for native
// Box2D. Node picks the SIMD build when the runtime validates SIMD (Node 20 does). Its Emscripten
// loader tries fetch() for the .wasm file in Node 18+, so the harness passes the bytes itself
// (`wasmBinary`). Chains are one-sided in 2.4, as in @box2d/core.
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';
import { packageVersion, oneSidedChain, repoRoot } from './common.mjs';

const require = createRequire(path.join(repoRoot, 'package.json'));

export default {
  id: 'box2d-wasm',
  name: 'box2d-wasm',
  pkg: 'box2d-wasm',
  family: 'Box2D 2.4.1, C++ to WebAssembly',
  version: packageVersion('box2d-wasm'),
  notes: ['chains one-sided (Box2D 2.4): points ordered so the solid side faces the bodies'],

  async load() {
    const hasSIMD = WebAssembly.validate(
      new Uint8Array([0, 97, 115, 109, 1, 0, 0, 0, 1, 5, 1, 96, 0, 1, 123, 3, 2, 1, 0, 10, 10, 1, 8, 0, 65, 0, 253, 15, 253, 98, 11]),
    );
    const base = path.join(path.dirname(require.resolve('box2d-wasm')), hasSIMD ? 'Box2D.simd' : 'Box2D');
    const factory = require(base + '.js');
    const B = await factory({ wasmBinary: readFileSync(base + '.wasm') });
    B.simd = hasSIMD;
    return B;
  },

  supports() {
    return null;
  },

  create(B, scene, { sleep }) {
    const temp = [];
    const vec = (x, y) => {
      const v = new B.b2Vec2(x, y);
      temp.push(v);
      return v;
    };
    const vecArray = (points) => {
      const buf = B._malloc(points.length * 8);
      const f32 = B.HEAPF32;
      points.forEach((p, i) => {
        f32[(buf >> 2) + 2 * i] = p[0];
        f32[(buf >> 2) + 2 * i + 1] = p[1];
      });
      return buf;
    };
    const freeTemp = () => {
      for (const o of temp) B.destroy(o);
      temp.length = 0;
    };

    const world = new B.b2World(vec(scene.gravity[0], scene.gravity[1]));
    world.SetAllowSleeping(sleep);
    const bodies = [];
    const types = { static: B.b2_staticBody, kinematic: B.b2_kinematicBody, dynamic: B.b2_dynamicBody };

    const add = (d) => {
      const bd = new B.b2BodyDef();
      bd.set_type(types[d.type]);
      bd.set_position(vec(d.x, d.y));
      bd.set_angle(d.angle);
      bd.set_linearVelocity(vec(d.vx, d.vy));
      bd.set_angularVelocity(d.w);
      bd.set_bullet(d.bullet);
      bd.set_allowSleep(d.allowSleep);
      const b = world.CreateBody(bd);
      B.destroy(bd);
      for (const s of d.shapes) {
        let shape;
        if (s.kind === 'box') {
          shape = new B.b2PolygonShape();
          if (s.cx !== undefined) shape.SetAsBox(s.hx, s.hy, vec(s.cx, s.cy), s.angle);
          else shape.SetAsBox(s.hx, s.hy);
        } else if (s.kind === 'polygon') {
          shape = new B.b2PolygonShape();
          const buf = vecArray(s.vertices);
          shape.Set(B.wrapPointer(buf, B.b2Vec2), s.vertices.length);
          B._free(buf);
        } else if (s.kind === 'circle') {
          shape = new B.b2CircleShape();
          shape.set_m_radius(s.r);
          shape.set_m_p(vec(s.cx ?? 0, s.cy ?? 0));
        } else if (s.kind === 'edge') {
          shape = new B.b2EdgeShape();
          shape.SetTwoSided(vec(s.v1[0], s.v1[1]), vec(s.v2[0], s.v2[1]));
        } else if (s.kind === 'chain') {
          const c = oneSidedChain(s);
          shape = new B.b2ChainShape();
          const buf = vecArray(c.points);
          if (c.loop) shape.CreateLoop(B.wrapPointer(buf, B.b2Vec2), c.points.length);
          else shape.CreateChain(B.wrapPointer(buf, B.b2Vec2), c.points.length, vec(c.prev[0], c.prev[1]), vec(c.next[0], c.next[1]));
          B._free(buf);
        }
        const fd = new B.b2FixtureDef();
        fd.set_shape(shape);
        fd.set_density(s.density);
        fd.set_friction(s.friction);
        fd.set_restitution(s.restitution);
        const filter = new B.b2Filter();
        filter.set_categoryBits(s.category);
        filter.set_maskBits(s.mask);
        filter.set_groupIndex(0);
        fd.set_filter(filter);
        b.CreateFixture(fd);
        B.destroy(filter);
        B.destroy(fd);
        B.destroy(shape);
      }
      freeTemp();
      bodies.push(b);
    };
    for (const d of scene.bodies) add(d);
    for (const j of scene.joints) {
      const jd = new B.b2RevoluteJointDef();
      jd.set_bodyA(bodies[j.a]);
      jd.set_bodyB(bodies[j.b]);
      jd.set_localAnchorA(vec(j.ax, j.ay));
      jd.set_localAnchorB(vec(j.bx, j.by));
      jd.set_referenceAngle(j.refAngle);
      jd.set_collideConnected(j.collideConnected);
      if (j.motor) {
        jd.set_enableMotor(true);
        jd.set_motorSpeed(j.motor.speed);
        jd.set_maxMotorTorque(j.motor.maxTorque);
      }
      world.CreateJoint(jd);
      B.destroy(jd);
      freeTemp();
    }
    freeTemp();

    const { dt } = scene;
    let { velocityIterations: vi, positionIterations: pi } = scene;
    return {
      step: () => world.Step(dt, vi, pi),
      setIterations: (v, p) => {
        vi = v;
        pi = p;
      },
      add,
      bodyCount: () => world.GetBodyCount(),
      contactCount: () => world.GetContactCount(),
      position: (i) => {
        const b = bodies[i];
        if (!b) return null;
        const p = b.GetPosition();
        return [p.get_x(), p.get_y()];
      },
      wasmBytes: () => B.HEAPU8.buffer.byteLength,
      destroy: () => {
        B.destroy(world);
        bodies.length = 0;
      },
    };
  },
};
