// Box2DWeb 2.1a (hecht-software/box2dweb), the engine WebPhysics' Box2DWeb API replaces.
//
// How it is loaded: the `box2dweb` npm package (2.1.0) is that 2.1a build (Box2D.js) with its last
// four lines, which run the deferred static initialisers queued in `Box2D.postDefs`, replaced by
// `module.exports = Box2D`. `require('box2dweb')` therefore loads, but the first `new b2World()`
// throws (b2ContactFactory.AddType reads the never-initialised shape-type constants). So the
// harness reads node_modules/box2dweb/box2d.js, evaluates it as a classic script inside a function
// that defines `module` and `exports` (vm.runInThisContext, so it is compiled like any other code in
// this process), and then runs `Box2D.postDefs` as the 2.1a build's own tail does.
//
// Box2DWeb 2.1a has edge shapes but no edge collision (b2PolyAndEdgeContact and
// b2EdgeAndCircleContact are empty) and no chains, so edges and chains are built as static boxes
// 1 m thick behind the segment.
import { readFileSync } from 'node:fs';
import path from 'node:path';
import vm from 'node:vm';
import { repoRoot, packageVersion, segmentsOf, boxForSegment, isSegmentShape } from './common.mjs';

export function loadBox2DWeb() {
  const file = path.join(repoRoot, 'node_modules', 'box2dweb', 'box2d.js');
  const src = readFileSync(file, 'utf8');
  // The build's first lines test `Object.prototype.defineProperty` (always undefined) instead of
  // `Object.defineProperty`, and so replace the global Object.defineProperty with a shim built on
  // __defineGetter__ that ignores value descriptors. That breaks other code in the process (here,
  // embind's generated bindings in box2d3-wasm), so the real one is put back afterwards; Box2DWeb
  // itself only defines accessors, which the real one handles.
  const defineProperty = Object.defineProperty;
  let Box2D;
  try {
    const factory = vm.runInThisContext(`(function (module, exports) {${src}\n;return Box2D;\n})`, { filename: file });
    const module = { exports: {} };
    Box2D = factory(module, module.exports);
  } finally {
    Object.defineProperty = defineProperty;
  }
  if (Array.isArray(Box2D.postDefs)) {
    for (const init of Box2D.postDefs) init();
    delete Box2D.postDefs;
  }
  return Box2D;
}

export default {
  id: 'box2dweb',
  name: 'Box2DWeb 2.1a',
  pkg: 'box2dweb',
  family: 'Box2D 2.1a (Box2DFlash), JavaScript',
  version: packageVersion('box2dweb'),
  notes: ['edges and chains as static 1 m thick boxes (2.1a has no edge collision)', 'world.ClearForces() after each Step (2.1a does not clear forces itself)'],

  async load() {
    return loadBox2DWeb();
  },

  supports() {
    return null;
  },

  create(Box2D, scene, { sleep }) {
    const { b2Vec2 } = Box2D.Common.Math;
    const { b2World, b2BodyDef, b2Body, b2FixtureDef } = Box2D.Dynamics;
    const { b2PolygonShape, b2CircleShape } = Box2D.Collision.Shapes;
    const { b2RevoluteJointDef } = Box2D.Dynamics.Joints;
    const world = new b2World(new b2Vec2(scene.gravity[0], scene.gravity[1]), sleep);
    const bodies = [];
    const types = { static: b2Body.b2_staticBody, kinematic: b2Body.b2_kinematicBody, dynamic: b2Body.b2_dynamicBody };

    const fixture = (b, shape, s) => {
      const fd = new b2FixtureDef();
      fd.shape = shape;
      fd.density = s.density;
      fd.friction = s.friction;
      fd.restitution = s.restitution;
      fd.filter.categoryBits = s.category;
      fd.filter.maskBits = s.mask;
      b.CreateFixture(fd);
    };
    const orientedBox = (box) => {
      const shape = new b2PolygonShape();
      shape.SetAsOrientedBox(box.hx, box.hy, new b2Vec2(box.cx, box.cy), box.angle);
      return shape;
    };

    const add = (d) => {
      const bd = new b2BodyDef();
      bd.type = types[d.type];
      bd.position.Set(d.x, d.y);
      bd.angle = d.angle;
      bd.linearVelocity.Set(d.vx, d.vy);
      bd.angularVelocity = d.w;
      bd.bullet = d.bullet;
      bd.allowSleep = d.allowSleep;
      const b = world.CreateBody(bd);
      for (const s of d.shapes) {
        if (isSegmentShape(s)) {
          for (const seg of segmentsOf(s)) fixture(b, orientedBox(boxForSegment(seg, s.side)), s);
          continue;
        }
        let shape;
        if (s.kind === 'box') {
          if (s.cx !== undefined) shape = orientedBox(s);
          else {
            shape = new b2PolygonShape();
            shape.SetAsBox(s.hx, s.hy);
          }
        } else if (s.kind === 'polygon') {
          shape = new b2PolygonShape();
          shape.SetAsArray(
            s.vertices.map((p) => new b2Vec2(p[0], p[1])),
            s.vertices.length,
          );
        } else if (s.kind === 'circle') {
          shape = new b2CircleShape(s.r);
          shape.SetLocalPosition(new b2Vec2(s.cx ?? 0, s.cy ?? 0));
        }
        fixture(b, shape, s);
      }
      bodies.push(b);
    };
    for (const d of scene.bodies) add(d);
    for (const j of scene.joints) {
      const jd = new b2RevoluteJointDef();
      jd.bodyA = bodies[j.a];
      jd.bodyB = bodies[j.b];
      jd.localAnchorA.Set(j.ax, j.ay);
      jd.localAnchorB.Set(j.bx, j.by);
      jd.referenceAngle = j.refAngle;
      jd.collideConnected = j.collideConnected;
      if (j.motor) {
        jd.enableMotor = true;
        jd.motorSpeed = j.motor.speed;
        jd.maxMotorTorque = j.motor.maxTorque;
      }
      world.CreateJoint(jd);
    }

    const { dt } = scene;
    let { velocityIterations: vi, positionIterations: pi } = scene;
    return {
      step: () => {
        world.Step(dt, vi, pi);
        world.ClearForces();
      },
      setIterations: (v, p) => {
        vi = v;
        pi = p;
      },
      add,
      bodyCount: () => world.GetBodyCount(),
      // 2.1a's GetContactCount() only grows (its counter misses destroyed contacts): walk the list.
      contactCount: () => {
        let n = 0;
        for (let c = world.GetContactList(); c; c = c.GetNext()) n++;
        return n;
      },
      position: (i) => {
        const b = bodies[i];
        if (!b) return null;
        const p = b.GetPosition();
        return [p.x, p.y];
      },
      destroy: () => {
        bodies.length = 0;
      },
    };
  },
};
