// Rapier2D (@dimforge/rapier2d-compat): Rust compiled to WebAssembly, the .wasm inlined as base64.
// Its solver is a substepping soft-constraint solver with no velocity/position iteration split: it
// runs with its default 4 solver iterations (the counterpart of v3's 4 substeps). Sleeping is per
// body (canSleep); continuous collision only for bodies marked bullet; restitution combines by max
// as in Box2D. The revolute motor is Rapier's velocity motor (damping factor 1e3, max force 1e8).
import { packageVersion, segmentsOf } from './common.mjs';

export default {
  id: 'rapier',
  name: 'Rapier2D',
  pkg: '@dimforge/rapier2d-compat',
  family: 'Rapier, Rust to WebAssembly',
  version: packageVersion('@dimforge/rapier2d-compat'),
  notes: ['4 solver iterations (Rapier default; no velocity/position split)', 'CCD only on bullets; no contact count in the JS API'],

  async load() {
    const R = (await import('@dimforge/rapier2d-compat')).default;
    // init() logs a deprecation notice about its argument form; silence it for the tables.
    const warn = console.warn;
    console.warn = () => {};
    try {
      await R.init();
    } finally {
      console.warn = warn;
    }
    return R;
  },

  supports() {
    return null;
  },

  create(R, scene, { sleep }) {
    const world = new R.World({ x: scene.gravity[0], y: scene.gravity[1] });
    world.timestep = scene.dt;
    const bodies = [];

    const add = (d) => {
      let desc = d.type === 'dynamic' ? R.RigidBodyDesc.dynamic() : d.type === 'kinematic' ? R.RigidBodyDesc.kinematicVelocityBased() : R.RigidBodyDesc.fixed();
      desc = desc
        .setTranslation(d.x, d.y)
        .setRotation(d.angle)
        .setLinvel(d.vx, d.vy)
        .setAngvel(d.w)
        .setCanSleep(sleep && d.allowSleep);
      if (d.bullet) desc = desc.setCcdEnabled(true);
      const body = world.createRigidBody(desc);
      for (const s of d.shapes) {
        const cds = [];
        if (s.kind === 'box') {
          const c = R.ColliderDesc.cuboid(s.hx, s.hy);
          if (s.cx !== undefined) c.setTranslation(s.cx, s.cy).setRotation(s.angle);
          cds.push(c);
        } else if (s.kind === 'polygon') {
          cds.push(R.ColliderDesc.convexHull(new Float32Array(s.vertices.flat())));
        } else if (s.kind === 'circle') {
          cds.push(R.ColliderDesc.ball(s.r).setTranslation(s.cx ?? 0, s.cy ?? 0));
        } else if (s.kind === 'edge') {
          cds.push(R.ColliderDesc.segment({ x: s.v1[0], y: s.v1[1] }, { x: s.v2[0], y: s.v2[1] }));
        } else if (s.kind === 'chain') {
          const points = s.vertices.flat();
          const segs = segmentsOf(s);
          const indices = new Uint32Array(segs.length * 2);
          for (let i = 0; i < segs.length; i++) {
            indices[2 * i] = i;
            indices[2 * i + 1] = (i + 1) % s.vertices.length;
          }
          cds.push(R.ColliderDesc.polyline(new Float32Array(points), indices));
        }
        for (const c of cds) {
          c.setDensity(s.density).setFriction(s.friction).setRestitution(s.restitution).setRestitutionCombineRule(R.CoefficientCombineRule.Max);
          if (s.category !== 1 || s.mask !== 0xffff) c.setCollisionGroups(((s.category & 0xffff) << 16) | (s.mask & 0xffff));
          world.createCollider(c, body);
        }
      }
      bodies.push(body);
    };
    for (const d of scene.bodies) add(d);
    for (const j of scene.joints) {
      const params = R.JointData.revolute({ x: j.ax, y: j.ay }, { x: j.bx, y: j.by });
      const joint = world.createImpulseJoint(params, bodies[j.a], bodies[j.b], true);
      joint.setContactsEnabled(j.collideConnected);
      if (j.motor) {
        joint.configureMotorVelocity(j.motor.speed, 1e3);
        joint.setMotorMaxForce(j.motor.maxTorque);
      }
    }

    return {
      step: () => world.step(),
      add,
      bodyCount: () => world.bodies.len(),
      contactCount: () => null,
      position: (i) => {
        const b = bodies[i];
        if (!b) return null;
        const p = b.translation();
        return [p.x, p.y];
      },
      destroy: () => {
        world.free();
        bodies.length = 0;
      },
    };
  },
};
