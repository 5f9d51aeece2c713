// matter-js: a JavaScript engine with its own (position-based, Verlet) solver, in pixel units with y
// down. The scene is scaled 1 m = 50 px (so a 1 m box is the 50 px box matter is tuned for), y and
// angles flipped, gravity set to the scene's 10 m/s^2, air friction off; the velocity and position
// iteration counts are passed as matter's own. Circles are matter's polygons of up to 25 sides;
// revolute joints are zero-length stiff constraints; edges and chains are static boxes 1 m thick.
// Not expressible: motorised joints (matter constraints have no motor), so no tumbler; no
// continuous collision (bullets are ordinary bodies).
import { packageVersion, segmentsOf, boxForSegment, isSegmentShape } from './common.mjs';

const S = 50; // pixels per metre

export default {
  id: 'matter',
  name: 'matter-js',
  pkg: 'matter-js',
  family: 'matter-js, JavaScript',
  version: packageVersion('matter-js'),
  notes: ['1 m = 50 px; own solver with the scene iteration counts', 'edges/chains as 1 m boxes; joints as zero-length constraints; no CCD'],

  async load() {
    return (await import('matter-js')).default;
  },

  supports(scene) {
    if (scene.joints.some((j) => j.motor)) return 'no motorised joint in matter-js (constraints have no motor)';
    for (const b of scene.bodies) {
      if (b.type !== 'static' && b.shapes.length !== 1) return 'compound dynamic bodies not built';
    }
    return null;
  },

  create(M, scene, { sleep }) {
    const engine = M.Engine.create({
      enableSleeping: sleep,
      positionIterations: scene.positionIterations,
      velocityIterations: scene.velocityIterations,
    });
    engine.gravity.scale = 1;
    engine.gravity.x = (scene.gravity[0] * S) / 1e6;
    engine.gravity.y = (-scene.gravity[1] * S) / 1e6;
    const bodies = [];
    const dtMs = scene.dt * 1000;

    const options = (s, d, isStatic) => ({
      isStatic,
      density: s.density > 0 ? s.density * 1e-3 : 1e-3,
      friction: s.friction,
      restitution: s.restitution,
      frictionAir: 0,
      collisionFilter: { group: 0, category: s.category, mask: s.mask },
    });
    // World-space (pixel) rectangle for a box in body (d) coordinates.
    const rect = (d, box, opts) => {
      const c = Math.cos(d.angle);
      const sn = Math.sin(d.angle);
      const cx = box.cx ?? 0;
      const cy = box.cy ?? 0;
      const x = d.x + c * cx - sn * cy;
      const y = d.y + sn * cx + c * cy;
      return M.Bodies.rectangle(x * S, -y * S, 2 * box.hx * S, 2 * box.hy * S, { ...opts, angle: -(d.angle + (box.angle ?? 0)) });
    };

    const add = (d) => {
      const isStatic = d.type === 'static';
      const made = [];
      for (const s of d.shapes) {
        const opts = options(s, d, isStatic);
        if (isSegmentShape(s)) {
          for (const seg of segmentsOf(s)) made.push(rect(d, boxForSegment(seg, s.side), opts));
        } else if (s.kind === 'box') {
          made.push(rect(d, s, opts));
        } else if (s.kind === 'circle') {
          const c = Math.cos(d.angle);
          const sn = Math.sin(d.angle);
          const x = d.x + c * (s.cx ?? 0) - sn * (s.cy ?? 0);
          const y = d.y + sn * (s.cx ?? 0) + c * (s.cy ?? 0);
          made.push(M.Bodies.circle(x * S, -y * S, s.r * S, opts));
        } else if (s.kind === 'polygon') {
          const c = Math.cos(d.angle);
          const sn = Math.sin(d.angle);
          const verts = s.vertices.map(([vx, vy]) => ({ x: (d.x + c * vx - sn * vy) * S, y: -(d.y + sn * vx + c * vy) * S }));
          const centre = M.Vertices.centre(verts);
          made.push(M.Bodies.fromVertices(centre.x, centre.y, [verts], opts));
        }
      }
      for (const b of made) {
        if (!isStatic) {
          M.Body.setVelocity(b, { x: (d.vx * S) / 60, y: (-d.vy * S) / 60 });
          M.Body.setAngularVelocity(b, -d.w / 60);
        }
      }
      M.Composite.add(engine.world, made);
      bodies.push(made[0] ?? null);
    };
    for (const d of scene.bodies) add(d);
    const constraints = [];
    for (const j of scene.joints) {
      constraints.push(
        M.Constraint.create({
          bodyA: bodies[j.a],
          bodyB: bodies[j.b],
          pointA: { x: j.ax * S, y: -j.ay * S },
          pointB: { x: j.bx * S, y: -j.by * S },
          length: 0,
          stiffness: 1,
          damping: 0,
        }),
      );
    }
    if (constraints.length) M.Composite.add(engine.world, constraints);

    return {
      step: () => M.Engine.update(engine, dtMs),
      add,
      bodyCount: () => M.Composite.allBodies(engine.world).length,
      contactCount: () => engine.pairs.list.length,
      position: (i) => {
        const b = bodies[i];
        if (!b) return null;
        return [b.position.x / S, -b.position.y / S];
      },
      destroy: () => {
        M.Composite.clear(engine.world, false, true);
        M.Engine.clear(engine);
        bodies.length = 0;
      },
    };
  },
};
