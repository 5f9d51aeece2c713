// planck (planck.js): a JavaScript rewrite of Box2D 2.x. Its package.json asks for Node >= 24, but
// the build runs on Node 20 (checked by this harness: every scene steps and settles).
import { packageVersion } from './common.mjs';

export default {
  id: 'planck',
  name: 'planck',
  pkg: 'planck',
  family: 'Box2D 2.x, JavaScript',
  version: packageVersion('planck'),
  notes: [],

  async load() {
    return import('planck');
  },

  supports() {
    return null;
  },

  create(P, scene, { sleep }) {
    const world = new P.World({ gravity: { x: scene.gravity[0], y: scene.gravity[1] }, allowSleep: sleep });
    const bodies = [];
    const vec = (p) => new P.Vec2(p[0], p[1]);

    const add = (d) => {
      const b = world.createBody({
        type: d.type,
        position: { x: d.x, y: d.y },
        angle: d.angle,
        linearVelocity: { x: d.vx, y: d.vy },
        angularVelocity: d.w,
        bullet: d.bullet,
        allowSleep: d.allowSleep,
      });
      for (const s of d.shapes) {
        let shape;
        if (s.kind === 'box') shape = s.cx !== undefined ? new P.Box(s.hx, s.hy, { x: s.cx, y: s.cy }, s.angle) : new P.Box(s.hx, s.hy);
        else if (s.kind === 'polygon') shape = new P.Polygon(s.vertices.map(vec));
        else if (s.kind === 'circle') shape = new P.Circle({ x: s.cx ?? 0, y: s.cy ?? 0 }, s.r);
        else if (s.kind === 'edge') shape = new P.Edge(vec(s.v1), vec(s.v2));
        else if (s.kind === 'chain') {
          shape = new P.Chain(s.vertices.map(vec), s.loop);
          if (s.prev) shape.setPrevVertex(vec(s.prev));
          if (s.next) shape.setNextVertex(vec(s.next));
        }
        b.createFixture(shape, {
          density: s.density,
          friction: s.friction,
          restitution: s.restitution,
          filterCategoryBits: s.category,
          filterMaskBits: s.mask,
        });
      }
      bodies.push(b);
    };
    for (const d of scene.bodies) add(d);
    for (const j of scene.joints) {
      world.createJoint(
        new P.RevoluteJoint({
          bodyA: bodies[j.a],
          bodyB: bodies[j.b],
          localAnchorA: { x: j.ax, y: j.ay },
          localAnchorB: { x: j.bx, y: j.by },
          referenceAngle: j.refAngle,
          collideConnected: j.collideConnected,
          enableMotor: Boolean(j.motor),
          motorSpeed: j.motor ? j.motor.speed : 0,
          maxMotorTorque: j.motor ? j.motor.maxTorque : 0,
        }),
      );
    }

    const { dt } = scene;
    let { velocityIterations: vi, positionIterations: pi } = scene;
    return {
      step: () => world.step(dt, vi, pi),
      setIterations: (v, p) => {
        vi = v;
        pi = p;
      },
      add,
      bodyCount: () => world.getBodyCount(),
      contactCount: () => world.getContactCount(),
      position: (i) => {
        const b = bodies[i];
        if (!b) return null;
        const p = b.getPosition();
        return [p.x, p.y];
      },
      destroy: () => {
        bodies.length = 0;
      },
    };
  },
};
