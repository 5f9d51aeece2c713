// The accuracy study's scenes (docs/ACCURACY.md, "Scenes"), each defined once as plain data in the
// benchmark's scene format (bench/scenes.mjs), so that every engine adapter of bench/engines can
// build it; WebPhysics builds it with createBox2D221World and is measured on its b2World too.
// A scene runs for `seconds` of simulated time and reports its measures, what it gets wrong, each
// in its unit, smaller is better: probe(view) takes { position(i) } (an adapter's, by body index)
// and, for a Box2D 2.2.1 world, `world` and `b2` (the engine's exports); measures that need the
// world are left out for other engines. `sample(t)` is called after every frame (1/60 s of
// simulated time, whatever the method's step), `result()` once at the end.

import { createBox2D221World } from '../engines/box2d221.mjs';
import { bounceHeights, pendulumPeriod, projectileRange, slidingDistance } from './analytic.mjs';
import { dynamicBodies as dynamicBodiesOf, energyAndMomentum, jointErrors, penetration, restingDrift, rmsSpeed } from './measures.mjs';
import { REFERENCE, applyMethod, stepFrame } from './methods.mjs';

const G = 10;
const SHAPE = { density: 1, friction: 0.6, restitution: 0, category: 0x0001, mask: 0xffff };

function body(type, x, y, shapes, extra = {}) {
  return { type, x, y, angle: 0, vx: 0, vy: 0, w: 0, bullet: false, allowSleep: true, ...extra, shapes: shapes.map((s) => ({ ...SHAPE, ...s })) };
}

/** A scene in the benchmark's format: 1/60 s steps at 8/3 iterations (the methods change them for WebPhysics). */
function sceneData(id, title, bodies, { joints = [], gravity = [0, -G] } = {}) {
  return { id: `accuracy-${id}`, title, description: title, gravity, dt: 1 / 60, velocityIterations: 8, positionIterations: 3, bodies, joints };
}

const ground = (halfWidth = 40, shape = {}) => body('static', 0, -0.5, [{ kind: 'box', hx: halfWidth, hy: 0.5, density: 0, ...shape }]);

/** The indices of a scene's dynamic bodies. */
function dynamicIndices(data) {
  return data.bodies.flatMap((b, i) => (b.type === 'dynamic' ? [i] : []));
}

/** The dynamic bodies' positions through `view`, x and y interleaved. */
function viewPositions(view, indices) {
  const out = new Float64Array(2 * indices.length);
  indices.forEach((index, k) => {
    const p = view.position(index) ?? [NaN, NaN];
    out[2 * k] = p[0];
    out[2 * k + 1] = p[1];
  });
  return out;
}

/** A column of `height` unit boxes on the ground, placed touching. */
export function stackData(height) {
  const bodies = [ground()];
  for (let i = 0; i < height; ++i) bodies.push(body('dynamic', 0, 0.5 + i, [{ kind: 'box', hx: 0.5, hy: 0.5 }]));
  return sceneData(`stack-${height}`, `a column of ${height} boxes at rest`, bodies);
}

/** A pyramid of unit boxes, `base` wide at the bottom. */
export function pyramidData(base) {
  const bodies = [ground()];
  for (let row = 0; row < base; ++row) {
    for (let i = 0; i < base - row; ++i) bodies.push(body('dynamic', i - (base - row - 1) / 2, 0.5 + row, [{ kind: 'box', hx: 0.5, hy: 0.5 }]));
  }
  return sceneData(`pyramid-${base}`, `a pyramid of ${(base * (base + 1)) / 2} boxes at rest`, bodies);
}

/** A chain of `links` 1 x 0.2 m boxes hanging from a pivot, a disc of `ratio` times a link's mass at its end. */
export function chainData(links, ratio = 1) {
  const bodies = [body('static', 0, 20, [])];
  const joints = [];
  for (let i = 0; i < links; ++i) {
    bodies.push(body('dynamic', 0.5 + i, 20, [{ kind: 'box', hx: 0.5, hy: 0.1 }]));
    joints.push({ kind: 'revolute', a: i, b: i + 1, ax: i === 0 ? 0 : 0.5, ay: 0, bx: -0.5, by: 0, refAngle: 0, collideConnected: false, motor: null });
  }
  // A link is 1 x 0.2 m at density 1; the weight a disc of radius 0.25 m.
  bodies.push(body('dynamic', links + 0.25, 20, [{ kind: 'circle', r: 0.25, density: (ratio * 0.2) / (Math.PI * 0.25 * 0.25) }]));
  joints.push({ kind: 'revolute', a: links, b: links + 1, ax: 0.5, ay: 0, bx: -0.25, by: 0, refAngle: 0, collideConnected: false, motor: null });
  return sceneData(`chain-${links}`, `a chain of ${links} links with a weight of ${ratio} links`, bodies, { joints });
}

/** A 0.05 m plate at x = 5 and a ball of radius 0.1 m at `x0` flying at it at `speed`, without gravity. */
export function plateData(speed, x0) {
  return sceneData(
    'plate',
    'a ball flying at a thin plate',
    [body('static', 5, 0, [{ kind: 'box', hx: 0.025, hy: 5, density: 0 }]), body('dynamic', x0, 0, [{ kind: 'circle', r: 0.1 }], { vx: speed })],
    { gravity: [0, 0] },
  );
}

/**
 * A resting scene's measures: drift of every body between the end of the first second and the
 * end (any engine); with the world, penetration (maximum and mean over the last second) and the
 * jitter at the end.
 */
function restingProbe(data, seconds) {
  return (view) => {
    const indices = dynamicIndices(data);
    let settled = null;
    let maxDepth = 0;
    let meanDepth = 0;
    let samples = 0;
    return {
      sample(t) {
        if (settled === null && t >= 1) settled = viewPositions(view, indices);
        if (view.world && t > seconds - 1) {
          const p = penetration(view.b2, view.world);
          if (p.max > maxDepth) maxDepth = p.max;
          meanDepth += p.mean;
          samples++;
        }
      },
      result() {
        const drift = restingDrift(settled, viewPositions(view, indices));
        if (!view.world) return { drift };
        return { 'penetration max': maxDepth, 'penetration mean': samples > 0 ? meanDepth / samples : 0, drift, jitter: rmsSpeed(view.world) };
      },
    };
  };
}

/**
 * The mechanisms scene: a bridge of 12 planks pinned at both ends, a ragdoll with joint limits
 * dropped on the ground, two geared discs (the large one spinning), a box falling onto the limit
 * of a vertical prismatic joint, two unequal boxes on a pulley, and a cantilever of three welded
 * beams. Every joint kind of 2.2.1 that has a position constraint except the wheel and rope.
 */
export function mechanismsData() {
  const bodies = [ground(40)];
  const joints = [];
  const add = (b) => bodies.push(b) - 1;
  // Anchors on the ground body (at y = -0.5) given in world coordinates.
  const onGround = (x, y) => [x, y + 0.5];
  const revolute = (a, b, [ax, ay], [bx, by], extra = {}) =>
    joints.push({ kind: 'revolute', a, b, ax, ay, bx, by, refAngle: 0, collideConnected: false, motor: null, ...extra }) - 1;
  // The bridge, 5 m up.
  let previous = 0;
  for (let i = 0; i < 12; ++i) {
    const plank = add(body('dynamic', -5.5 + i, 5, [{ kind: 'box', hx: 0.5, hy: 0.125 }]));
    revolute(previous, plank, previous === 0 ? onGround(-6, 5) : [0.5, 0], [-0.5, 0]);
    previous = plank;
  }
  revolute(previous, 0, [0.5, 0], onGround(6, 5));
  // The ragdoll, falling from 4 m at x = -12.
  const torso = add(body('dynamic', -12, 4, [{ kind: 'box', hx: 0.3, hy: 0.6 }]));
  const head = add(body('dynamic', -12, 4.9, [{ kind: 'circle', r: 0.25 }]));
  revolute(torso, head, [0, 0.6], [0, -0.3], { limit: [-0.5, 0.5] });
  for (const side of [-1, 1]) {
    const arm = add(body('dynamic', -12 + side * 0.8, 4.45, [{ kind: 'box', hx: 0.5, hy: 0.1 }]));
    revolute(torso, arm, [side * 0.3, 0.45], [-side * 0.5, 0], { limit: [-1.5, 1.5] });
    const leg = add(body('dynamic', -12 + side * 0.15, 3, [{ kind: 'box', hx: 0.12, hy: 0.5 }]));
    revolute(torso, leg, [side * 0.15, -0.5], [0, 0.5], { limit: [-0.8, 0.8] });
  }
  // The gears: a disc of radius 1 spinning at 4 rad/s drives one of radius 0.5 at ratio 2.
  const large = add(body('dynamic', 12, 3, [{ kind: 'circle', r: 1 }], { w: 4 }));
  const small = add(body('dynamic', 13.6, 3, [{ kind: 'circle', r: 0.5 }]));
  const pinLarge = revolute(0, large, onGround(12, 3), [0, 0]);
  const pinSmall = revolute(0, small, onGround(13.6, 3), [0, 0]);
  joints.push({ kind: 'gear', a: large, b: small, joint1: pinLarge, joint2: pinSmall, ratio: 2 });
  // The elevator: a box 1 m above the lower limit of a vertical prismatic joint.
  const car = add(body('dynamic', 12, 7, [{ kind: 'box', hx: 0.4, hy: 0.4 }]));
  joints.push({
    kind: 'prismatic',
    a: 0,
    b: car,
    ax: 12,
    ay: 7.5,
    bx: 0,
    by: 0,
    axis: [0, 1],
    refAngle: 0,
    collideConnected: false,
    limit: [-1, 0.5],
    motor: null,
  });
  // The pulley: a box of twice the other's mass on the left.
  const heavy = add(body('dynamic', 17, 4, [{ kind: 'box', hx: 0.5, hy: 0.5, density: 2 }]));
  const light = add(body('dynamic', 19, 5, [{ kind: 'box', hx: 0.5, hy: 0.5 }]));
  joints.push({ kind: 'pulley', a: heavy, b: light, groundA: [17, 9], groundB: [19, 9], anchorA: [17, 4], anchorB: [19, 5], ratio: 1 });
  // The cantilever: three 2 m beams welded end to end out of a wall at x = -18, 4 m up.
  let base = 0;
  let baseAnchor = onGround(-20, 4);
  for (let i = 0; i < 3; ++i) {
    const beam = add(body('dynamic', -19 + 2 * i, 4, [{ kind: 'box', hx: 1, hy: 0.1 }]));
    joints.push({ kind: 'weld', a: base, b: beam, ax: baseAnchor[0], ay: baseAnchor[1], bx: -1, by: 0, refAngle: 0, collideConnected: false, motor: null });
    base = beam;
    baseAnchor = [1, 0];
  }
  return sceneData('mechanisms', 'a bridge, a ragdoll, gears, a prismatic lift, a pulley and a welded cantilever', bodies, { joints });
}

const PENDULUM = { L: 2, r: 0.1 };
const PROJECTILE = { v: 10, r: 0.1 };
const BOUNCE = { h0: 4, r: 0.25, e: 0.5 };
const SLIDE = { v0: 5, mu: 0.4 };

/** The scenes of the study, by id: { title, seconds, trajectory?, data(), probe(view) }. */
export const ACCURACY_SCENES = {
  stack: {
    title: 'a column of 10 boxes at rest',
    seconds: 10,
    data: () => stackData(10),
    probe: restingProbe(stackData(10), 10),
  },
  pyramid: {
    title: 'a pyramid of 55 boxes at rest',
    seconds: 10,
    data: () => pyramidData(10),
    probe: restingProbe(pyramidData(10), 10),
  },
  chain: {
    title: 'a chain of 20 links swinging, a weight of 10 links at its end',
    seconds: 5,
    data: () => chainData(20, 10),
    probe(view) {
      let linear = 0;
      return {
        sample() {
          if (view.world) linear = Math.max(linear, jointErrors(view.world).linear);
        },
        result: () => (view.world ? { 'joint error': linear } : {}),
      };
    },
  },
  mechanisms: {
    title: 'a bridge, a ragdoll, gears, a prismatic lift, a pulley and a welded cantilever',
    seconds: 5,
    // Its measures read the joints of a Box2D 2.2.1 world, and its joints are more than the peers' adapters build.
    worldOnly: true,
    data: () => mechanismsData(),
    probe(view) {
      let linear = 0;
      let angular = 0;
      return {
        sample() {
          const e = jointErrors(view.world);
          linear = Math.max(linear, e.linear);
          angular = Math.max(angular, e.angular);
        },
        result: () => ({ 'joint error': linear, 'joint angle error': angular }),
      };
    },
  },
  projectile: {
    title: 'a ball thrown at 10 m/s and 45 degrees, without drag',
    seconds: 2,
    // Its whole flight, which framing the bodies where they start would not show (the accuracy page's replay).
    view: { x: 7, y: -1.5, half: 6.5 },
    data() {
      // cos and sin of 45 degrees: sqrt is correctly rounded in every JavaScript engine.
      const { v, r } = PROJECTILE;
      return sceneData('projectile', this.title, [body('dynamic', 0, 0, [{ kind: 'circle', r }], { vx: v / Math.sqrt(2), vy: v / Math.sqrt(2) })]);
    },
    probe(view) {
      const expected = projectileRange(PROJECTILE.v, Math.PI / 4, G);
      // Where the ball comes back down through y = 0, interpolated within the frame.
      let range = null;
      let prev = view.position(0);
      return {
        sample() {
          const p = view.position(0);
          if (range === null && prev[1] >= 0 && p[1] < 0) range = prev[0] + ((p[0] - prev[0]) * prev[1]) / (prev[1] - p[1]);
          prev = p;
        },
        result: () => ({ 'range error': range === null ? Infinity : Math.abs(range - expected) / expected }),
      };
    },
  },
  pendulum: {
    title: 'a 2 m pendulum released at 60 degrees',
    seconds: 9,
    data() {
      // sin and cos of 60 degrees: sqrt is correctly rounded in every JavaScript engine.
      const { L, r } = PENDULUM;
      const bob = body('dynamic', (L * Math.sqrt(3)) / 2, -L / 2, [{ kind: 'circle', r }]);
      return sceneData('pendulum', this.title, [body('static', 0, 0, []), bob], {
        joints: [{ kind: 'revolute', a: 0, b: 1, ax: 0, ay: 0, bx: (-L * Math.sqrt(3)) / 2, by: L / 2, refAngle: 0, collideConnected: false, motor: null }],
      });
    },
    probe(view) {
      const { L, r } = PENDULUM;
      const expected = pendulumPeriod((r * r) / 2 / L + L, G, Math.PI / 3);
      // Crossings of x = 0 moving right, interpolated within the frame.
      const crossings = [];
      let prevX = view.position(1)[0];
      let prevT = 0;
      return {
        sample(t) {
          const x = view.position(1)[0];
          if (prevX < 0 && x >= 0) crossings.push(prevT + ((t - prevT) * -prevX) / (x - prevX));
          prevX = x;
          prevT = t;
        },
        result() {
          if (crossings.length < 2) return { 'period error': Infinity };
          const period = (crossings[crossings.length - 1] - crossings[0]) / (crossings.length - 1);
          return { 'period error': Math.abs(period - expected) / expected };
        },
      };
    },
  },
  bounce: {
    title: 'a ball dropped from 4 m with restitution 0.5',
    seconds: 4,
    data() {
      const { h0, r, e } = BOUNCE;
      return sceneData('bounce', this.title, [ground(10, { restitution: e }), body('dynamic', 0, h0 + r, [{ kind: 'circle', r, restitution: e }])]);
    },
    probe(view) {
      const { h0, r, e } = BOUNCE;
      // Box2D mixes restitution as the larger of the two, so the bounce is e.
      const expected = bounceHeights(h0, e, 2)[1];
      let last = view.position(1)[1] - r;
      let rising = false;
      let firstPeak = null;
      return {
        sample() {
          const h = view.position(1)[1] - r;
          if (firstPeak === null) {
            if (!rising && h > last) rising = true;
            else if (rising && h < last) firstPeak = last;
          }
          last = h;
        },
        result: () => ({ 'rebound error': firstPeak === null ? Infinity : Math.abs(firstPeak - expected) / expected }),
      };
    },
  },
  slide: {
    title: 'a box sliding at 5 m/s to rest on friction 0.4',
    seconds: 4,
    data() {
      const { v0, mu } = SLIDE;
      return sceneData('slide', this.title, [
        ground(40, { friction: mu }),
        body('dynamic', 0, 0.5, [{ kind: 'box', hx: 0.5, hy: 0.5, friction: mu }], { vx: v0 }),
      ]);
    },
    probe(view) {
      const { v0, mu } = SLIDE;
      const expected = slidingDistance(v0, mu, G);
      return { sample() {}, result: () => ({ 'stopping error': Math.abs(view.position(1)[0] - expected) / expected }) };
    },
  },
  elastic: {
    title: '40 frictionless, perfectly elastic balls in a box without gravity',
    seconds: 10,
    data() {
      const wall = { density: 0, friction: 0, restitution: 1 };
      const walls = body('static', 0, 0, [
        { kind: 'box', hx: 6, hy: 0.5, cx: 0, cy: -5.5, angle: 0, ...wall },
        { kind: 'box', hx: 6, hy: 0.5, cx: 0, cy: 5.5, angle: 0, ...wall },
        { kind: 'box', hx: 0.5, hy: 6, cx: -5.5, cy: 0, angle: 0, ...wall },
        { kind: 'box', hx: 0.5, hy: 6, cx: 5.5, cy: 0, angle: 0, ...wall },
      ]);
      // A deterministic spread of velocities (a fixed linear congruential sequence).
      let seed = 12345;
      const next = () => {
        seed = (seed * 1103515245 + 12345) % 2147483648;
        return seed / 2147483648;
      };
      const balls = [];
      for (let i = 0; i < 40; ++i) {
        const vx = 6 * next() - 3;
        const vy = 6 * next() - 3;
        balls.push(body('dynamic', -4 + (i % 8), -4 + 2 * Math.floor(i / 8), [{ kind: 'circle', r: 0.3, friction: 0, restitution: 1 }], { vx, vy }));
      }
      return sceneData('elastic', this.title, [walls, ...balls], { gravity: [0, 0] });
    },
    probe(view) {
      if (!view.world) return { sample() {}, result: () => ({}) };
      const start = energyAndMomentum(view.world).total;
      return { sample() {}, result: () => ({ 'energy drift': Math.abs(energyAndMomentum(view.world).total - start) / start }) };
    },
  },
  collide: {
    title: '24 elastic balls colliding in free space, without walls or gravity',
    seconds: 4,
    // Its measures read the world's masses and velocities (the peers' adapters give positions only).
    worldOnly: true,
    data() {
      // Two triangles of frictionless, perfectly elastic balls thrown at each other, slightly off centre.
      const balls = [];
      for (const [side, x0, vx, dy] of [
        [-1, -6, 4, 0],
        [1, 6, -4, 0.15],
      ]) {
        for (let row = 0; row < 6; ++row) {
          for (let k = 0; k <= row && balls.length < (side < 0 ? 12 : 24); ++k) {
            balls.push(body('dynamic', x0 + side * 0.62 * row, dy + 0.64 * (k - row / 2), [{ kind: 'circle', r: 0.3, friction: 0, restitution: 1 }], { vx }));
          }
        }
      }
      return sceneData('collide', this.title, balls, { gravity: [0, 0] });
    },
    probe(view) {
      const start = energyAndMomentum(view.world);
      // Drifts relative to the sums of the bodies' own momenta, which stay of the order of the start's.
      let scaleP = 0;
      let scaleL = 0;
      for (const b of dynamicBodiesOf(view.world)) {
        scaleP += b.m_mass * Math.sqrt(b.m_linearVelocity.x * b.m_linearVelocity.x + b.m_linearVelocity.y * b.m_linearVelocity.y);
        scaleL += Math.abs(b.m_mass * (b.m_sweep.c.x * b.m_linearVelocity.y - b.m_sweep.c.y * b.m_linearVelocity.x) + b.m_I * b.m_angularVelocity);
      }
      return {
        sample() {},
        result() {
          const end = energyAndMomentum(view.world);
          return {
            'energy drift': Math.abs(end.total - start.total) / start.total,
            'momentum drift': Math.hypot(end.momentum.x - start.momentum.x, end.momentum.y - start.momentum.y) / scaleP,
            'angular momentum drift': Math.abs(end.angular - start.angular) / scaleL,
          };
        },
      };
    },
  },
  drop: {
    title: '30 boxes and balls dropped onto the ground, against a converged run',
    // Short enough that the run is not chaotic: the error falls as the step shrinks (at 1 s it no longer does).
    seconds: 0.5,
    trajectory: true,
    data() {
      const bodies = [ground()];
      for (let i = 0; i < 30; ++i) {
        const shape = i % 2 === 0 ? { kind: 'box', hx: 0.4, hy: 0.3 } : { kind: 'circle', r: 0.35 };
        bodies.push(body('dynamic', -2.5 + (i % 6) + 0.1 * (i % 3), 1 + 1.2 * Math.floor(i / 6), [shape], { angle: 0.1 * i }));
      }
      return sceneData('drop', this.title, bodies);
    },
    probe: () => ({ sample() {}, result: () => ({}) }),
  },
};

export const ACCURACY_SCENE_IDS = Object.keys(ACCURACY_SCENES);

/** The dynamic bodies' positions of a scene built from `data`, through `view` (the trajectory error's snapshot). */
export function scenePositions(data, view) {
  return viewPositions(view, dynamicIndices(data));
}

/**
 * Scene `id` built in WebPhysics (`b2`, its exports), sleeping off: its b2World, the adapter view
 * and the probe, which sees the world.
 */
export function buildScene(b2, id) {
  const scene = ACCURACY_SCENES[id];
  const data = scene.data();
  const built = createBox2D221World(b2, data, { sleep: false });
  const view = { position: built.position, world: built.world, b2 };
  return { world: built.world, data, view, probe: scene.probe(view) };
}

/**
 * The final positions of scene `id` under the converged reference (REFERENCE, on WebPhysics `b2`):
 * what the trajectory error of a trajectory scene is measured against.
 */
export function referencePositions(b2, id) {
  const { world, data, view } = buildScene(b2, id);
  applyMethod(world, REFERENCE);
  const frames = Math.round(ACCURACY_SCENES[id].seconds * REFERENCE.frameHz);
  for (let f = 1; f <= frames; ++f) stepFrame(world, REFERENCE);
  return scenePositions(data, view);
}
