// @box2d/core (Lusito's box2d.ts): Box2D 2.4.1 in TypeScript. Its chains are one-sided, so the
// scene's chains are given with their solid side facing the bodies.
import { packageVersion, oneSidedChain } from './common.mjs';

export default {
  id: 'box2d-core',
  name: '@box2d/core',
  pkg: '@box2d/core',
  family: 'Box2D 2.4.1, TypeScript',
  version: packageVersion('@box2d/core'),
  notes: ['chains one-sided (Box2D 2.4): points ordered so the solid side faces the bodies'],

  async load() {
    return import('@box2d/core');
  },

  supports() {
    return null;
  },

  create(B, scene, { sleep }) {
    const world = B.b2World.Create({ x: scene.gravity[0], y: scene.gravity[1] });
    world.SetAllowSleeping(sleep);
    const bodies = [];
    const xy = (p) => ({ x: p[0], y: p[1] });
    const types = { static: B.b2BodyType.b2_staticBody, kinematic: B.b2BodyType.b2_kinematicBody, dynamic: B.b2BodyType.b2_dynamicBody };

    const add = (d) => {
      const b = world.CreateBody({
        type: types[d.type],
        position: { x: d.x, y: d.y },
        angle: d.angle,
        linearVelocity: { x: d.vx, y: d.vy },
        angularVelocity: d.w,
        bullet: d.bullet,
        allowSleep: d.allowSleep,
      });
      for (const s of d.shapes) {
        let shape;
        if (s.kind === 'box') {
          shape = new B.b2PolygonShape();
          if (s.cx !== undefined) shape.SetAsBox(s.hx, s.hy, { x: s.cx, y: s.cy }, s.angle);
          else shape.SetAsBox(s.hx, s.hy);
        } else if (s.kind === 'polygon') {
          shape = new B.b2PolygonShape();
          shape.Set(s.vertices.map(xy));
        } else if (s.kind === 'circle') {
          shape = new B.b2CircleShape(s.r);
          shape.m_p.Set(s.cx ?? 0, s.cy ?? 0);
        } else if (s.kind === 'edge') {
          shape = new B.b2EdgeShape();
          shape.SetTwoSided(xy(s.v1), xy(s.v2));
        } else if (s.kind === 'chain') {
          const c = oneSidedChain(s);
          shape = new B.b2ChainShape();
          if (c.loop) shape.CreateLoop(c.points.map(xy));
          else shape.CreateChain(c.points.map(xy), c.points.length, xy(c.prev), xy(c.next));
        }
        b.CreateFixture({
          shape,
          density: s.density,
          friction: s.friction,
          restitution: s.restitution,
          filter: { categoryBits: s.category, maskBits: s.mask, groupIndex: 0 },
        });
      }
      bodies.push(b);
    };
    for (const d of scene.bodies) add(d);
    for (const j of scene.joints) {
      const jd = new B.b2RevoluteJointDef();
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

    const dt = scene.dt;
    const iterations = { velocityIterations: scene.velocityIterations, positionIterations: scene.positionIterations };
    return {
      step: () => world.Step(dt, iterations),
      setIterations: (v, p) => {
        iterations.velocityIterations = v;
        iterations.positionIterations = p;
      },
      add,
      bodyCount: () => world.GetBodyCount(),
      contactCount: () => world.GetContactCount(),
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
