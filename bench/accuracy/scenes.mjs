// The accuracy study's scenes (docs/ACCURACY.md, "Scenes"). Each builds a world with the engine
// it is given (`b2`: the module's exports, the working tree's bundle or src/), runs for `seconds`
// of simulated time, and reports its measures: what it gets wrong, each in its unit, smaller is
// better. `sample(t)` is called after every frame (1/60 s of simulated time, whatever the method's
// step), `result()` once at the end.

import { bounceHeights, pendulumPeriod, slidingDistance } from './analytic.mjs';
import { energyAndMomentum, jointErrors, penetration, positions, restingDrift, rmsSpeed } from './measures.mjs';

const G = 10;

function makeBody(b2, world, x, y, dynamic, angle = 0) {
  const def = new b2.b2BodyDef();
  if (dynamic) def.type = b2.b2_dynamicBody;
  def.position.Set(x, y);
  def.angle = angle;
  return world.CreateBody(def);
}

function addBox(b2, body, hx, hy, density = 1, friction = 0.6, restitution = 0) {
  const shape = new b2.b2PolygonShape();
  shape.SetAsBox(hx, hy);
  const fd = new b2.b2FixtureDef();
  fd.shape = shape;
  fd.density = density;
  fd.friction = friction;
  fd.restitution = restitution;
  return body.CreateFixture(fd);
}

function addCircle(b2, body, radius, density = 1, friction = 0.6, restitution = 0) {
  const shape = new b2.b2CircleShape();
  shape.m_radius = radius;
  const fd = new b2.b2FixtureDef();
  fd.shape = shape;
  fd.density = density;
  fd.friction = friction;
  fd.restitution = restitution;
  return body.CreateFixture(fd);
}

function ground(b2, world, halfWidth = 40, friction = 0.6, restitution = 0) {
  const g = makeBody(b2, world, 0, -0.5, false);
  addBox(b2, g, halfWidth, 0.5, 0, friction, restitution);
  return g;
}

/**
 * A resting scene's measures: penetration (mean and maximum over the last second), the drift of
 * every body between the end of the first second and the end, and the jitter at the end.
 */
function restingProbe(b2, world, seconds) {
  let settled = null;
  let maxDepth = 0;
  let meanDepth = 0;
  let samples = 0;
  return {
    sample(t) {
      if (settled === null && t >= 1) settled = positions(world);
      if (t > seconds - 1) {
        const p = penetration(b2, world);
        if (p.max > maxDepth) maxDepth = p.max;
        meanDepth += p.mean;
        samples++;
      }
    },
    result() {
      return {
        'penetration max': maxDepth,
        'penetration mean': samples > 0 ? meanDepth / samples : 0,
        drift: restingDrift(settled, positions(world)),
        jitter: rmsSpeed(world),
      };
    },
  };
}

/** A column of `height` unit boxes on the ground, placed touching. */
export function buildStack(b2, height) {
  const world = new b2.b2World(new b2.b2Vec2(0, -G));
  ground(b2, world);
  const boxes = [];
  for (let i = 0; i < height; ++i) {
    const b = makeBody(b2, world, 0, 0.5 + i, true);
    addBox(b2, b, 0.5, 0.5);
    boxes.push(b);
  }
  return { world, boxes };
}

/** A pyramid of unit boxes, `base` wide at the bottom. */
export function buildPyramid(b2, base) {
  const world = new b2.b2World(new b2.b2Vec2(0, -G));
  ground(b2, world);
  const boxes = [];
  for (let row = 0; row < base; ++row) {
    for (let i = 0; i < base - row; ++i) {
      const b = makeBody(b2, world, i - (base - row - 1) / 2, 0.5 + row, true);
      addBox(b2, b, 0.5, 0.5);
      boxes.push(b);
    }
  }
  return { world, boxes };
}

/** A chain of `links` capsule-like boxes hanging from a pivot, with a weight of `ratio` link masses at its end. */
export function buildChain(b2, links, ratio = 1) {
  const world = new b2.b2World(new b2.b2Vec2(0, -G));
  const pivot = makeBody(b2, world, 0, 20, false);
  let prev = pivot;
  const bodies = [];
  for (let i = 0; i < links; ++i) {
    const link = makeBody(b2, world, 0.5 + i, 20, true);
    addBox(b2, link, 0.5, 0.1, 1);
    const jd = new b2.b2RevoluteJointDef();
    jd.Initialize(prev, link, new b2.b2Vec2(i, 20));
    world.CreateJoint(jd);
    bodies.push(link);
    prev = link;
  }
  // The weight: a disc of `ratio` times a link's mass (a link is 1 x 0.2 at density 1).
  const weight = makeBody(b2, world, links + 0.25, 20, true);
  addCircle(b2, weight, 0.25, (ratio * 0.2) / (Math.PI * 0.25 * 0.25));
  const jd = new b2.b2RevoluteJointDef();
  jd.Initialize(prev, weight, new b2.b2Vec2(links, 20));
  world.CreateJoint(jd);
  bodies.push(weight);
  return { world, bodies };
}

/** The scenes of the study, by id. */
export const ACCURACY_SCENES = {
  stack: {
    title: 'a column of 10 boxes at rest',
    seconds: 10,
    build(b2) {
      const { world } = buildStack(b2, 10);
      return { world, probe: restingProbe(b2, world, 10) };
    },
  },
  pyramid: {
    title: 'a pyramid of 55 boxes at rest',
    seconds: 10,
    build(b2) {
      const { world } = buildPyramid(b2, 10);
      return { world, probe: restingProbe(b2, world, 10) };
    },
  },
  chain: {
    title: 'a chain of 20 links swinging, a weight of 10 links at its end',
    seconds: 5,
    build(b2) {
      const { world } = buildChain(b2, 20, 10);
      let linear = 0;
      return {
        world,
        probe: {
          sample() {
            const e = jointErrors(world);
            if (e.linear > linear) linear = e.linear;
          },
          result: () => ({ 'joint error': linear }),
        },
      };
    },
  },
  pendulum: {
    title: 'a 2 m pendulum released at 60 degrees',
    seconds: 9,
    build(b2) {
      const world = new b2.b2World(new b2.b2Vec2(0, -G));
      const pivot = makeBody(b2, world, 0, 0, false);
      const L = 2;
      const r = 0.1;
      const amplitude = Math.PI / 3;
      // The port's own sine and cosine (b2Rot), so that the start is the same bits in every JavaScript engine.
      const q = new b2.b2Rot(amplitude);
      const bob = makeBody(b2, world, L * q.s, -L * q.c, true);
      addCircle(b2, bob, r);
      const jd = new b2.b2RevoluteJointDef();
      jd.Initialize(pivot, bob, new b2.b2Vec2(0, 0));
      world.CreateJoint(jd);
      const expected = pendulumPeriod((r * r) / 2 / L + L, G, amplitude);
      // Crossings of x = 0 moving right, interpolated within the frame.
      const crossings = [];
      let prevX = bob.GetPosition().x;
      let prevT = 0;
      return {
        world,
        probe: {
          sample(t) {
            const x = bob.GetPosition().x;
            if (prevX < 0 && x >= 0) crossings.push(prevT + ((t - prevT) * -prevX) / (x - prevX));
            prevX = x;
            prevT = t;
          },
          result() {
            if (crossings.length < 2) return { 'period error': Infinity };
            const period = (crossings[crossings.length - 1] - crossings[0]) / (crossings.length - 1);
            return { 'period error': Math.abs(period - expected) / expected };
          },
        },
      };
    },
  },
  bounce: {
    title: 'a ball dropped from 4 m with restitution 0.5',
    seconds: 4,
    build(b2) {
      const world = new b2.b2World(new b2.b2Vec2(0, -G));
      ground(b2, world, 10, 0.6, 0.5);
      const r = 0.25;
      const ball = makeBody(b2, world, 0, 4 + r, true);
      addCircle(b2, ball, r, 1, 0.6, 0.5);
      // Box2D mixes restitution as the larger of the two, so the bounce is e = 0.5.
      const expected = bounceHeights(4, 0.5, 2)[1];
      let falling = true;
      let peak = -Infinity;
      let firstPeak = null;
      return {
        world,
        probe: {
          sample() {
            const v = ball.GetLinearVelocity().y;
            const h = ball.GetPosition().y - r;
            if (falling && v > 0) falling = false;
            if (!falling && firstPeak === null) {
              if (h > peak) peak = h;
              else if (v <= 0) firstPeak = peak;
            }
          },
          result: () => ({ 'rebound error': firstPeak === null ? Infinity : Math.abs(firstPeak - expected) / expected }),
        },
      };
    },
  },
  slide: {
    title: 'a box sliding at 5 m/s to rest on friction 0.4',
    seconds: 4,
    build(b2) {
      const world = new b2.b2World(new b2.b2Vec2(0, -G));
      ground(b2, world, 40, 0.4);
      const box = makeBody(b2, world, 0, 0.5, true);
      addBox(b2, box, 0.5, 0.5, 1, 0.4);
      box.SetLinearVelocity(new b2.b2Vec2(5, 0));
      const expected = slidingDistance(5, 0.4, G);
      return {
        world,
        probe: {
          sample() {},
          result: () => ({ 'stopping error': Math.abs(box.GetPosition().x - expected) / expected }),
        },
      };
    },
  },
  elastic: {
    title: '40 frictionless, perfectly elastic balls in a box without gravity',
    seconds: 10,
    build(b2) {
      const world = new b2.b2World(new b2.b2Vec2(0, 0));
      const walls = makeBody(b2, world, 0, 0, false);
      for (const [x, y, hx, hy] of [
        [0, -5.5, 6, 0.5],
        [0, 5.5, 6, 0.5],
        [-5.5, 0, 0.5, 6],
        [5.5, 0, 0.5, 6],
      ]) {
        const shape = new b2.b2PolygonShape();
        shape.SetAsBox(hx, hy, new b2.b2Vec2(x, y), 0);
        const fd = new b2.b2FixtureDef();
        fd.shape = shape;
        fd.friction = 0;
        fd.restitution = 1;
        walls.CreateFixture(fd);
      }
      // A deterministic spread of positions and velocities (a fixed linear congruential sequence).
      let seed = 12345;
      const next = () => {
        seed = (seed * 1103515245 + 12345) % 2147483648;
        return seed / 2147483648;
      };
      for (let i = 0; i < 40; ++i) {
        const ball = makeBody(b2, world, -4 + (i % 8), -4 + 2 * Math.floor(i / 8), true);
        addCircle(b2, ball, 0.3, 1, 0, 1);
        ball.SetLinearVelocity(new b2.b2Vec2(6 * next() - 3, 6 * next() - 3));
      }
      const start = energyAndMomentum(world).total;
      return {
        world,
        probe: {
          sample() {},
          result: () => ({ 'energy drift': Math.abs(energyAndMomentum(world).total - start) / start }),
        },
      };
    },
  },
  drop: {
    title: '30 boxes and balls dropped onto the ground, against a converged run',
    // Short enough that the run is not chaotic: the error falls as the step shrinks (at 1 s it no longer does).
    seconds: 0.5,
    trajectory: true,
    build(b2) {
      const world = new b2.b2World(new b2.b2Vec2(0, -G));
      ground(b2, world);
      for (let i = 0; i < 30; ++i) {
        const b = makeBody(b2, world, -2.5 + (i % 6) + 0.1 * (i % 3), 1 + 1.2 * Math.floor(i / 6), true, 0.1 * i);
        if (i % 2 === 0) addBox(b2, b, 0.4, 0.3);
        else addCircle(b2, b, 0.35);
      }
      return { world, probe: { sample() {}, result: () => ({}) } };
    },
  },
};

export const ACCURACY_SCENE_IDS = Object.keys(ACCURACY_SCENES);
