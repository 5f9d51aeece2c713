/*
 * The comparison page's scenes, built with the engine's API from a scene name, a body count and a
 * seed, so that the JavaScript pane and the WebGPU pane (and bench/gpu-compare.ts, which times the
 * page's code on a real GPU) build the same world body for body.
 *
 *   pyramids    pyramids of up to 20 rows (210 boxes of 0.5 m half-size) side by side, 22 m apart,
 *               built at rest on a box ground; the last one cut short to give exactly n boxes.
 *   rain        circles (radius 0.25-0.5 m) and boxes (half-sizes 0.25-0.45 m, random angles) on a
 *               1.5 m grid jittered by up to 0.1 m, four times wider than high, falling with random
 *               velocities into a box with walls.
 *   joint-grid  Box2D v3's joint_grid: a square grid of circles (radius 0.4 m, 1 m apart) joined to
 *               their neighbours above and to the left by revolute joints, hung from the seven middle
 *               bodies of its top row; the circles do not collide with each other.
 *   tumbler     the 2.2.1 Testbed's Tumbler scaled to n boxes (0.125 m half-size): a box of four
 *               walls turning at 0.05 pi rad/s on a revolute motor, its side grown with the square
 *               root of n so the boxes fill about a quarter of it, the boxes stacked in its bottom.
 *   sand        grains (circles of radius 0.09-0.14 m) heaped in a triangle on a box ground, 0.3 m apart
 *               and jittered by up to 0.02 m, rows narrowing upwards: the heap slumps into a pile.
 * All at 1/60 s, 8 velocity and 3 position iterations, density 1, friction 0.6 (joint grid 0.2),
 * gravity (0, -10). The body count is the dynamic bodies (the joint grid's side is rounded from
 * the square root, so its count is the nearest square); the static bodies come on top.
 */

import { b2Vec2 } from '../../src/common/b2Math';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2BodyDef, b2_dynamicBody, b2_staticBody } from '../../src/dynamics/b2Body';
import type { b2Body } from '../../src/dynamics/b2Body';
import { b2FixtureDef } from '../../src/dynamics/b2Fixture';
import { b2World } from '../../src/dynamics/b2World';
import { b2RevoluteJointDef } from '../../src/dynamics/joints/b2RevoluteJoint';
import { rng } from '../../bench/gpu-support';
import { checkConfig, DT, POSITION_ITERATIONS, VELOCITY_ITERATIONS } from './config';
import type { SceneConfig, SceneView } from './config';

export interface BuiltScene {
  world: b2World;
  /** Every body in creation order: a body's index here is its index in both panes' transforms. */
  bodies: b2Body[];
  view: SceneView;
  dt: number;
  velocityIterations: number;
  positionIterations: number;
}

const PYRAMID_ROWS = 20;
const PYRAMID_PITCH = PYRAMID_ROWS + 2;
const RAIN_SPACING = 1.5;
const TUMBLER_BOX = 0.125;
const TUMBLER_SPACING = 0.3;
const SAND_SPACING = 0.3;

function box(hx: number, hy: number, centre?: b2Vec2, angle = 0): b2PolygonShape {
  const shape = new b2PolygonShape();
  if (centre !== undefined) shape.SetAsBox(hx, hy, centre, angle);
  else shape.SetAsBox(hx, hy);
  return shape;
}

function circle(r: number): b2CircleShape {
  const shape = new b2CircleShape();
  shape.m_radius = r;
  return shape;
}

class Builder {
  readonly world: b2World;
  readonly bodies: b2Body[] = [];
  private readonly bd = new b2BodyDef();
  private readonly fd = new b2FixtureDef();

  constructor(sleep: boolean) {
    this.world = new b2World(new b2Vec2(0, -10));
    this.world.SetAllowSleeping(sleep);
  }

  body(type: number, x: number, y: number, angle = 0): b2Body {
    this.bd.type = type;
    this.bd.position.Set(x, y);
    this.bd.angle = angle;
    const body = this.world.CreateBody(this.bd);
    this.bodies.push(body);
    return body;
  }

  fixture(body: b2Body, shape: b2PolygonShape | b2CircleShape, density: number, friction: number, category = 0x0001, mask = 0xffff): void {
    const fd = this.fd;
    fd.shape = shape;
    fd.density = density;
    fd.friction = friction;
    fd.filter.categoryBits = category;
    fd.filter.maskBits = mask;
    body.CreateFixture(fd);
  }

  /** A static box ground with its top at y = 0, and walls of `wallHeight` at its ends when given. */
  ground(halfWidth: number, wallHeight = 0): void {
    const ground = this.body(b2_staticBody, 0, 0);
    this.fixture(ground, box(halfWidth, 1, new b2Vec2(0, -1)), 0, 0.6);
    if (wallHeight > 0) {
      this.fixture(ground, box(1, wallHeight / 2, new b2Vec2(-halfWidth - 1, wallHeight / 2)), 0, 0.6);
      this.fixture(ground, box(1, wallHeight / 2, new b2Vec2(halfWidth + 1, wallHeight / 2)), 0, 0.6);
    }
  }
}

function pyramids(b: Builder, n: number): SceneView {
  const perPyramid = (PYRAMID_ROWS * (PYRAMID_ROWS + 1)) / 2;
  const rows = n >= perPyramid ? PYRAMID_ROWS : Math.ceil((Math.sqrt(8 * n + 1) - 1) / 2);
  const count = Math.ceil(n / perPyramid);
  const halfWidth = (count * PYRAMID_PITCH) / 2 + 5;
  b.ground(halfWidth);
  const h = 0.5;
  const square = box(h, h);
  let made = 0;
  for (let k = 0; k < count; ++k) {
    const centre = (k - (count - 1) / 2) * PYRAMID_PITCH;
    for (let i = 0; i < rows; ++i) {
      for (let j = i; j < rows && made < n; ++j, ++made) {
        const body = b.body(b2_dynamicBody, centre + (i + 1) * h + 2 * (j - i) * h - h * rows, (2 * i + 1) * h);
        b.fixture(body, square, 1, 0.6);
      }
    }
  }
  return { x: 0, y: rows / 2, halfWidth, halfHeight: rows + 2 };
}

function rain(b: Builder, n: number, seed: number): SceneView {
  const r = rng(seed);
  const rows = Math.max(1, Math.round(Math.sqrt(n / 4)));
  const cols = Math.ceil(n / rows);
  const halfWidth = (cols * RAIN_SPACING) / 2 + 1;
  const height = rows * RAIN_SPACING + 1;
  b.ground(halfWidth, height);
  const shapes = [circle(0.25), circle(0.375), circle(0.5), box(0.25, 0.25), box(0.45, 0.3), box(0.35, 0.45)];
  let made = 0;
  for (let row = 0; row < rows && made < n; ++row) {
    for (let col = 0; col < cols && made < n; ++col, ++made) {
      const x = (col - (cols - 1) / 2) * RAIN_SPACING + (r() - 0.5) * 0.2;
      const y = 1.5 + row * RAIN_SPACING + (r() - 0.5) * 0.2;
      const body = b.body(b2_dynamicBody, x, y, r() * 2 * Math.PI);
      b.fixture(body, shapes[Math.floor(r() * shapes.length)], 1, 0.6);
      body.SetLinearVelocity(new b2Vec2((r() - 0.5) * 2, -r() * 4));
    }
  }
  return { x: 0, y: height / 2, halfWidth: halfWidth + 2, halfHeight: height / 2 + 2 };
}

function jointGrid(b: Builder, n: number): SceneView {
  const side = Math.max(2, Math.round(Math.sqrt(n)));
  const shape = circle(0.4);
  const jd = new b2RevoluteJointDef();
  const middle = Math.floor(side / 2);
  for (let k = 0; k < side; ++k) {
    for (let i = 0; i < side; ++i) {
      const pinned = i === 0 && k >= middle - 3 && k <= middle + 3;
      const body = b.body(pinned ? b2_staticBody : b2_dynamicBody, k, -i);
      b.fixture(body, shape, 1, 0.2, 0x0002, 0xffff & ~0x0002);
      const index = b.bodies.length - 1;
      if (i > 0) {
        jd.Initialize(b.bodies[index - 1], body, new b2Vec2(k, -i + 0.5));
        b.world.CreateJoint(jd);
      }
      if (k > 0) {
        jd.Initialize(b.bodies[index - side], body, new b2Vec2(k - 0.5, -i));
        b.world.CreateJoint(jd);
      }
    }
  }
  return { x: (side - 1) / 2, y: -side / 2, halfWidth: side * 0.75, halfHeight: side * 0.75 };
}

function tumbler(b: Builder, n: number): SceneView {
  const half = Math.max(10, TUMBLER_BOX * 2 * Math.sqrt(n));
  const wall = half / 20;
  const hinge = b.body(b2_staticBody, 0, half);
  const drum = b.body(b2_dynamicBody, 0, half);
  drum.SetSleepingAllowed(false);
  const density = 5;
  b.fixture(drum, box(wall, half, new b2Vec2(half, 0)), density, 0.6);
  b.fixture(drum, box(wall, half, new b2Vec2(-half, 0)), density, 0.6);
  b.fixture(drum, box(half, wall, new b2Vec2(0, half)), density, 0.6);
  b.fixture(drum, box(half, wall, new b2Vec2(0, -half)), density, 0.6);
  const jd = new b2RevoluteJointDef();
  jd.bodyA = hinge;
  jd.bodyB = drum;
  jd.localAnchorA.Set(0, 0);
  jd.localAnchorB.Set(0, 0);
  jd.referenceAngle = 0;
  jd.motorSpeed = 0.05 * Math.PI;
  // The Testbed's 1e8 N m turns a 20 m drum; torque grows with the drum's mass times its size.
  jd.maxMotorTorque = 1e8 * (half / 10) ** 4;
  jd.enableMotor = true;
  b.world.CreateJoint(jd);
  const square = box(TUMBLER_BOX, TUMBLER_BOX);
  const inner = half - wall - 0.2;
  const cols = Math.floor((2 * inner) / TUMBLER_SPACING);
  for (let made = 0; made < n; ++made) {
    const row = Math.floor(made / cols);
    const col = made % cols;
    const body = b.body(b2_dynamicBody, -inner + (col + 0.5) * TUMBLER_SPACING, wall + 0.2 + (row + 0.5) * TUMBLER_SPACING);
    b.fixture(body, square, 1, 0.6);
  }
  return { x: 0, y: half, halfWidth: half * 1.5, halfHeight: half * 1.5 };
}

function sand(b: Builder, n: number, seed: number): SceneView {
  const r = rng(seed);
  const base = Math.ceil((Math.sqrt(8 * n + 1) - 1) / 2);
  const halfWidth = base * SAND_SPACING;
  const rowHeight = SAND_SPACING * 0.87;
  b.ground(2 * halfWidth);
  const grains = [circle(0.09), circle(0.115), circle(0.14)];
  let made = 0;
  for (let row = 0; row < base && made < n; ++row) {
    const count = base - row;
    for (let i = 0; i < count && made < n; ++i, ++made) {
      const x = (i - (count - 1) / 2) * SAND_SPACING + (r() - 0.5) * 0.04;
      const body = b.body(b2_dynamicBody, x, 0.16 + row * rowHeight + (r() - 0.5) * 0.04);
      b.fixture(body, grains[Math.floor(r() * grains.length)], 1, 0.6);
    }
  }
  const height = base * rowHeight;
  return { x: 0, y: height / 2, halfWidth: 1.2 * halfWidth, halfHeight: height / 2 + 2 };
}

/** Builds the scene a configuration names (checkConfig's errors for a bad one, `maxBodies` its limit). */
export function buildScene(config: SceneConfig, maxBodies?: number): BuiltScene {
  checkConfig(config, maxBodies);
  const b = new Builder(config.sleep);
  let view: SceneView;
  switch (config.scene) {
    case 'pyramids':
      view = pyramids(b, config.bodies);
      break;
    case 'rain':
      view = rain(b, config.bodies, config.seed);
      break;
    case 'joint-grid':
      view = jointGrid(b, config.bodies);
      break;
    case 'tumbler':
      view = tumbler(b, config.bodies);
      break;
    case 'sand':
      view = sand(b, config.bodies, config.seed);
      break;
  }
  return { world: b.world, bodies: b.bodies, view, dt: DT, velocityIterations: VELOCITY_ITERATIONS, positionIterations: POSITION_ITERATIONS };
}
