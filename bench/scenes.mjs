// The benchmark scenes, each defined once as plain data that every engine adapter builds natively.
//
// A scene is { id, title, description, gravity, dt, velocityIterations, positionIterations,
// bodies, joints, spawn?, protocol, track, check }:
// - bodies: { type: 'static' | 'dynamic', x, y, angle, vx, vy, w, bullet, allowSleep, shapes }, each
//   shape one of
//     { kind: 'box', hx, hy, cx, cy, angle }       (Box2D SetAsBox; cx/cy/angle place it on the body)
//     { kind: 'circle', r, cx, cy }
//     { kind: 'polygon', vertices: [[x, y], ...] } (convex, counter-clockwise)
//     { kind: 'edge', v1: [x, y], v2: [x, y], side }
//     { kind: 'chain', vertices, loop, prev, next, side }
//   with density, friction, restitution, category, mask (16-bit, Box2D filter) on every shape.
//   `side: 'left'` says the bodies meet an edge or chain from the left of its direction: engines
//   whose chains are one-sided (Box2D 2.4, v3) reverse the points so the solid side faces them, and
//   engines with no usable edge shape (Box2DWeb 2.1a, matter-js) build a static box 1 m thick on
//   the other side.
// - joints: { kind: 'revolute', a, b, ax, ay, bx, by, refAngle, collideConnected, motor }, a and b
//   indices into bodies, (ax, ay) and (bx, by) the local anchors, motor { speed, maxTorque } or null.
// - spawn(step): bodies to create right after step `step` (1-based) has run, or nothing.
// - protocol: { preroll, steps, rounds, allocSteps? } — per round a fresh world is built, stepped
//   `preroll` times untimed (the warm-up; spawning happens there), then `steps` steps are timed one
//   by one; allocSteps more steps count allocations on the last round (default min(steps, 32)).
// - track: indices of the bodies whose positions the sanity check reads; check(before, after) gets
//   their positions ([x, y] or null) before the first step and after the last, and returns
//   { ok, detail }.
import { readFileSync, existsSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));

/** The golden folder: $WEBPHYSICS_GOLDEN, or ../shared/golden beside the checkout. */
export function goldenDir() {
  return process.env.WEBPHYSICS_GOLDEN ?? path.resolve(here, '..', '..', 'shared', 'golden');
}

const DEFAULT_SHAPE = { density: 0, friction: 0.2, restitution: 0, category: 0x0001, mask: 0xffff };

function body(type, x, y, shapes, extra = {}) {
  return {
    type,
    x,
    y,
    angle: 0,
    vx: 0,
    vy: 0,
    w: 0,
    bullet: false,
    allowSleep: true,
    ...extra,
    shapes: shapes.map((s) => ({ ...DEFAULT_SHAPE, ...s })),
  };
}

const dist = (p, q) => (p && q ? Math.hypot(p[0] - q[0], p[1] - q[1]) : NaN);
const finite = (p) => p !== null && Number.isFinite(p[0]) && Number.isFinite(p[1]);

/** Rows of boxes, bottom row first, the way Box2D v3's pyramid benchmarks lay them out. */
function pyramidBoxes(baseCount, h, centerX, shape) {
  const out = [];
  for (let i = 0; i < baseCount; i++) {
    const y = (2 * i + 1) * h;
    for (let j = i; j < baseCount; j++) {
      const x = centerX + (i + 1) * h + 2 * (j - i) * h - h * baseCount;
      out.push(body('dynamic', x, y, [{ kind: 'box', hx: h, hy: h, ...shape }]));
    }
  }
  return out;
}

/**
 * A pyramid should settle rather than explode or collapse: each apex ends within 5% of its starting
 * height of where it started (a stack compresses and sways under low iteration counts or a soft
 * solver; a collapse or explosion moves it further), each base corner within 0.6 m. The first
 * `apexes` tracked bodies are apexes, the rest base corners.
 */
function pyramidCheck(label, apexes) {
  return (before, after) => {
    // Apexes: 5% of their starting height; base corners: 0.6 m.
    const limits = before.map((p, k) => (k < apexes ? Math.max(1, 0.05 * p[1]) : 0.6));
    const moved = before.map((p, k) => dist(p, after[k]));
    const ok = moved.every((d, k) => finite(after[k]) && d < limits[k]);
    const limit = [...new Set(limits.map((l) => l.toFixed(2)))].join('/');
    return { ok, detail: `${label} moved ${moved.map((d) => d.toFixed(2)).join(', ')} m (limits ${limit} m)` };
  };
}

// bench2d (joelgwebber/bench2d, its Box2D C++ version): a 40-row pyramid of 0.5 m boxes, 820 in all,
// on an 80 m edge; x starts at (-7, 0.75), each row moves (0.5625, 1), boxes in a row are 1.125 m
// apart. Density 5, friction 0.2, 3 velocity and 3 position iterations. The golden scene
// bench2d-pyramid.scene.json is this world (test/bench checks the layout against it).
function bench2d({ quick }) {
  const count = quick ? 20 : 40;
  const bodies = [body('static', 0, 0, [{ kind: 'edge', v1: [-40, 0], v2: [40, 0], side: 'left' }])];
  let x0 = -7;
  let y0 = 0.75;
  for (let i = 0; i < count; i++) {
    let x = x0;
    for (let j = i; j < count; j++) {
      bodies.push(body('dynamic', x, y0, [{ kind: 'box', hx: 0.5, hy: 0.5, density: 5 }]));
      x += 1.125;
    }
    x0 += 0.5625;
    y0 += 1;
  }
  return {
    id: 'bench2d',
    title: 'bench2d pyramid',
    description:
      "joelgwebber's bench2d: a 40-row pyramid of 820 boxes (0.5 m half-size, density 5) dropped 0.25 m onto an edge; 3 velocity / 3 position iterations",
    gravity: [0, -10],
    dt: 1 / 60,
    velocityIterations: 3,
    positionIterations: 3,
    bodies,
    joints: [],
    protocol: { preroll: 64, steps: 128, rounds: 3 },
    quick: { preroll: 8, steps: 16, rounds: 1 },
    track: [bodies.length - 1, 1, count],
    check: pyramidCheck('apex, two base corners', 1),
  };
}

// Box2D v3's large_pyramid benchmark: 100 rows, 5,050 boxes of 0.5 m half-size touching edge to
// edge, resting on a static 200 x 2 m box whose top is y = 0; density 1, friction 0.6 (v3's
// default). Box2D 2.x engines: 8 velocity / 3 position iterations.
function largePyramid({ quick }) {
  const rows = quick ? 20 : 100;
  const shape = { density: 1, friction: 0.6 };
  const bodies = [body('static', 0, -1, [{ kind: 'box', hx: 100, hy: 1, friction: 0.6 }])];
  bodies.push(...pyramidBoxes(rows, 0.5, 0, shape));
  return {
    id: 'large-pyramid',
    title: 'large pyramid',
    description:
      "Box2D v3's large_pyramid: 100 rows, 5,050 boxes (0.5 m half-size, density 1, friction 0.6) resting on a box ground; 8 velocity / 3 position iterations",
    gravity: [0, -10],
    dt: 1 / 60,
    velocityIterations: 8,
    positionIterations: 3,
    bodies,
    joints: [],
    protocol: { preroll: 4, steps: 16, rounds: 2, allocSteps: 8 },
    quick: { preroll: 8, steps: 8, rounds: 1 },
    track: [bodies.length - 1, 1, rows],
    check: pyramidCheck('apex, two base corners', 1),
  };
}

// 20 pyramids of 20 rows (210 boxes each, 4,200 in all) side by side, 2 m apart, on one static box
// ground; boxes as in large-pyramid.
function manyPyramids({ quick }) {
  const shape = { density: 1, friction: 0.6 };
  const count = quick ? 4 : 20;
  const rows = quick ? 10 : 20;
  const pitch = rows + 2;
  const bodies = [body('static', 0, -1, [{ kind: 'box', hx: (count * pitch) / 2 + 5, hy: 1, friction: 0.6 }])];
  const apexes = [];
  for (let k = 0; k < count; k++) {
    bodies.push(...pyramidBoxes(rows, 0.5, (k - (count - 1) / 2) * pitch, shape));
    apexes.push(bodies.length - 1);
  }
  return {
    id: 'many-pyramids',
    title: 'many pyramids',
    description:
      '20 pyramids of 20 rows (4,200 boxes, 0.5 m half-size, density 1, friction 0.6) side by side on one box ground; 8 velocity / 3 position iterations',
    gravity: [0, -10],
    dt: 1 / 60,
    velocityIterations: 8,
    positionIterations: 3,
    bodies,
    joints: [],
    protocol: { preroll: 4, steps: 16, rounds: 2, allocSteps: 8 },
    quick: { preroll: 8, steps: 8, rounds: 1 },
    track: apexes,
    check: pyramidCheck(`the ${count} apexes`, count),
  };
}

/** Reads a golden b2dJson scene into this file's format (the subset the mixed-rain scene uses). */
export function sceneFromB2dJson(json) {
  const bodies = [];
  for (const b of json.body) {
    if (b.fixture.length === 0) continue; // Box2D's empty static "ground" body carries nothing here
    const shapes = b.fixture.map((f) => {
      const common = {
        density: f.density,
        friction: f.friction,
        restitution: f.restitution,
        category: f['filter-categoryBits'],
        mask: f['filter-maskBits'],
      };
      if (f.circle) return { ...common, kind: 'circle', r: f.circle.radius, cx: f.circle.center.x, cy: f.circle.center.y };
      if (f.polygon && f.polygon.box) {
        const bx = f.polygon.box;
        // SetAsBox(hx, hy) unless a centre is given (b2dJson's `box` extension, as the golden loader).
        if (!bx.center) return { ...common, kind: 'box', hx: bx.hx, hy: bx.hy };
        return { ...common, kind: 'box', hx: bx.hx, hy: bx.hy, cx: bx.center.x, cy: bx.center.y, angle: bx.angle ?? 0 };
      }
      if (f.polygon) {
        const { x, y } = f.polygon.vertices;
        return { ...common, kind: 'polygon', vertices: x.map((vx, i) => [vx, y[i]]) };
      }
      if (f.edge) {
        const e = f.edge;
        return { ...common, kind: 'edge', v1: [e.vertex1.x, e.vertex1.y], v2: [e.vertex2.x, e.vertex2.y], side: 'left' };
      }
      if (f.chain) {
        const c = f.chain;
        let vertices = c.vertices.x.map((vx, i) => [vx, c.vertices.y[i]]);
        const first = vertices[0];
        const last = vertices[vertices.length - 1];
        const loop = c.hasPrevVertex && c.hasNextVertex && first[0] === last[0] && first[1] === last[1];
        if (loop) vertices = vertices.slice(0, -1); // b2dJson stores a loop with its closing vertex
        return {
          ...common,
          kind: 'chain',
          vertices,
          loop,
          prev: !loop && c.hasPrevVertex ? [c.prevVertex.x, c.prevVertex.y] : null,
          next: !loop && c.hasNextVertex ? [c.nextVertex.x, c.nextVertex.y] : null,
          side: 'left',
        };
      }
      throw new Error('unsupported fixture ' + Object.keys(f).join(','));
    });
    bodies.push(
      body(b.type === 2 ? 'dynamic' : b.type === 1 ? 'kinematic' : 'static', b.position.x, b.position.y, shapes, {
        angle: b.angle,
        vx: b.linearVelocity.x,
        vy: b.linearVelocity.y,
        w: b.angularVelocity,
        bullet: b.bullet,
        allowSleep: b.allowSleep,
      }),
    );
  }
  return bodies;
}

// The golden mixed-rain scene: 300 dynamic bodies (circles, boxes and convex polygons, 9 of them
// bullets, random sizes, materials and velocities) in a 40 x 40 m chain box with a slanted edge and
// a staircase chain. 8 velocity / 3 position iterations.
function mixedRain() {
  const file = path.join(goldenDir(), 'scenes', 'mixed-rain.scene.json');
  if (!existsSync(file)) return null;
  const json = JSON.parse(readFileSync(file, 'utf8'));
  const bodies = sceneFromB2dJson(json);
  const dynamic = bodies.map((b, i) => (b.type === 'dynamic' ? i : -1)).filter((i) => i >= 0);
  return {
    id: 'mixed-rain',
    title: 'mixed rain',
    description:
      'golden mixed-rain.scene.json: 300 circles, boxes and polygons (9 bullets) thrown into a chain box with an edge and a chain staircase; 8 velocity / 3 position iterations',
    gravity: [json.gravity.x, json.gravity.y],
    dt: 1 / json.stepsPerSecond,
    velocityIterations: json.velocityIterations,
    positionIterations: json.positionIterations,
    bodies,
    joints: [],
    protocol: { preroll: 64, steps: 128, rounds: 3 },
    quick: { preroll: 8, steps: 16, rounds: 1 },
    track: dynamic,
    check: (before, after) => {
      // Every body stays inside the container (40 x 40 m, a margin for walls built as boxes).
      const out = after.filter((p) => !finite(p) || p[0] < -21 || p[0] > 21 || p[1] < -1 || p[1] > 41).length;
      return { ok: out === 0, detail: `${after.length - out}/${after.length} bodies inside the box` };
    },
  };
}

// Box2D v3's joint_grid benchmark at N = 100: a 100 x 100 grid of circles (radius 0.4, density 1,
// 1 m apart) with revolute joints to the neighbour above and to the left (anchors at the midpoints),
// pinned at the top row by its 7 middle bodies (static), so the net falls and drapes. The circles
// do not collide with each other (category 2, mask ~2): this is a joint-solver benchmark.
// 8 velocity / 3 position iterations.
function jointGrid({ quick }) {
  const N = quick ? 20 : 100;
  const bodies = [];
  const joints = [];
  const shape = { kind: 'circle', r: 0.4, density: 1, category: 0x0002, mask: 0xffff & ~0x0002 };
  for (let k = 0; k < N; k++) {
    for (let i = 0; i < N; i++) {
      const pinned = i === 0 && k >= N / 2 - 3 && k <= N / 2 + 3;
      const index = bodies.length;
      bodies.push(body(pinned ? 'static' : 'dynamic', k, -i, [shape]));
      if (i > 0) joints.push({ kind: 'revolute', a: index - 1, b: index, ax: 0, ay: -0.5, bx: 0, by: 0.5 });
      if (k > 0) joints.push({ kind: 'revolute', a: index - N, b: index, ax: 0.5, ay: 0, bx: -0.5, by: 0 });
    }
  }
  for (const j of joints) Object.assign(j, { refAngle: 0, collideConnected: false, motor: null });
  const corners = [N - 1, N * N - 1, (N / 2) * N + N - 1];
  return {
    id: 'joint-grid',
    title: 'joint grid',
    description:
      "Box2D v3's joint_grid at 100 x 100: 10,000 circles, 19,800 revolute joints, pinned by 7 bodies of the top row; no contacts; 8 velocity / 3 position iterations",
    gravity: [0, -10],
    dt: 1 / 60,
    velocityIterations: 8,
    positionIterations: 3,
    bodies,
    joints,
    protocol: { preroll: 4, steps: 16, rounds: 2, allocSteps: 8 },
    quick: { preroll: 8, steps: 8, rounds: 1 },
    track: corners,
    check: (before, after) => {
      // The net falls and hangs from its pins: the bottom corners end lower than they started, and
      // no joint chain has stretched past the grid's size.
      const fell = after.every((p, k) => finite(p) && p[1] < before[k][1] + 1e-9);
      const sane = after.every((p) => finite(p) && Math.abs(p[0] - 50) < 160 && p[1] > -200);
      const drops = after.map((p, k) => (before[k][1] - p[1]).toFixed(2));
      return { ok: fell && sane, detail: `corners fell ${drops.join(', ')} m` };
    },
  };
}

// Box2D 2.2.1 Testbed's Tumbler with 1,000 boxes: a 20 x 20 m box of four walls (0.5 m thick,
// density 5) on a revolute motor about (0, 10) turning at 0.05 pi rad/s (max torque 1e8); the box
// body never sleeps. The Testbed adds one 0.25 m box (density 1) at the centre after every step;
// here eight are added after every step, in a 4 x 2 block at x = ±0.25, ±0.75 and y = 10 ± 0.25,
// until 1,000 exist (after step 125). Warm-up is the fill plus 50 steps: timing starts at step 175,
// with the tumbler full.
function tumbler({ quick }) {
  const wall = { density: 5 };
  const bodies = [
    body('static', 0, 0, []),
    body(
      'dynamic',
      0,
      10,
      [
        { kind: 'box', hx: 0.5, hy: 10, cx: 10, cy: 0, angle: 0, ...wall },
        { kind: 'box', hx: 0.5, hy: 10, cx: -10, cy: 0, angle: 0, ...wall },
        { kind: 'box', hx: 10, hy: 0.5, cx: 0, cy: 10, angle: 0, ...wall },
        { kind: 'box', hx: 10, hy: 0.5, cx: 0, cy: -10, angle: 0, ...wall },
      ],
      { allowSleep: false },
    ),
  ];
  const joints = [
    {
      kind: 'revolute',
      a: 0,
      b: 1,
      ax: 0,
      ay: 10,
      bx: 0,
      by: 0,
      refAngle: 0,
      collideConnected: false,
      motor: { speed: 0.05 * 3.14159265359, maxTorque: 1e8 },
    },
  ];
  const total = quick ? 96 : 1000;
  const offsets = [];
  for (const dy of [-0.25, 0.25]) for (const dx of [-0.75, -0.25, 0.25, 0.75]) offsets.push([dx, dy]);
  const perStep = offsets.length;
  const spawn = (step) => {
    if (step * perStep > Math.ceil(total / perStep) * perStep) return null;
    return offsets.map(([dx, dy]) => body('dynamic', dx, 10 + dy, [{ kind: 'box', hx: 0.125, hy: 0.125, density: 1 }]));
  };
  // Tracked: the tumbler body and the first and last boxes added (body indices continue past the
  // scene's own bodies in creation order).
  return {
    id: 'tumbler',
    title: 'tumbler',
    description:
      'Box2D 2.2.1 Testbed Tumbler filled with 1,000 boxes (0.125 m half-size): 8 boxes added per step until step 125, timing from step 175; 8 velocity / 3 position iterations',
    gravity: [0, -10],
    dt: 1 / 60,
    velocityIterations: 8,
    positionIterations: 3,
    bodies,
    joints,
    spawn,
    protocol: { preroll: 175, steps: 60, rounds: 2, allocSteps: 16 },
    quick: { preroll: 20, steps: 8, rounds: 1 },
    track: [1, 2, 2 + total - 1],
    check: (before, after) => {
      // Boxes stay inside the tumbler: within its half-diagonal (14.2 m) of the centre (0, 10).
      const boxes = after.slice(1).filter((p) => p !== null);
      const inside = boxes.filter((p) => finite(p) && dist(p, [0, 10]) < 14.5).length;
      const hub = after[0] && finite(after[0]) && dist(after[0], [0, 10]) < 0.5;
      return {
        ok: inside === boxes.length && Boolean(hub),
        detail: `hub ${after[0] ? dist(after[0], [0, 10]).toFixed(3) : '?'} m off its pivot; ${inside}/${boxes.length} tracked boxes inside`,
      };
    },
  };
}

const FACTORIES = { bench2d, 'large-pyramid': largePyramid, 'many-pyramids': manyPyramids, 'mixed-rain': mixedRain, 'joint-grid': jointGrid, tumbler };

/** Scene ids in running order. */
export const SCENE_IDS = Object.keys(FACTORIES);

/**
 * Builds the description of scene `id` (null when its data file is missing). With quick, the large
 * scenes are built small (bench2d 20 rows, large pyramid 20 rows, 4 pyramids of 10 rows, a 20 x 20
 * joint grid, a tumbler of 100 boxes) for smoke tests; `quick` on the result says so.
 */
export function makeScene(id, { quick = false } = {}) {
  const factory = FACTORIES[id];
  if (!factory) throw new Error(`unknown scene "${id}" (known: ${SCENE_IDS.join(', ')})`);
  const scene = factory({ quick });
  if (scene && quick) scene.quickSize = true;
  return scene;
}

/**
 * Steps world `w` (an engine adapter's world) for scene: `step()` steps once and then adds the
 * bodies the scene spawns after that step (the tumbler's fill); `steps` counts the steps taken.
 */
export function sceneStepper(w, scene) {
  const stepper = {
    steps: 0,
    step() {
      w.step();
      stepper.steps++;
      const more = scene.spawn?.(stepper.steps);
      if (more) for (const b of more) w.add(b);
    },
  };
  return stepper;
}

/** Body count including every body the scene spawns. */
export function totalBodies(scene) {
  let n = scene.bodies.length;
  if (scene.spawn)
    for (let s = 1; ; s++) {
      const more = scene.spawn(s);
      if (!more) break;
      n += more.length;
    }
  return n;
}
