// Helpers shared by the engine adapters: shape geometry that some engines cannot take as it is.
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');

/** The installed version of an npm package (read from its package.json in node_modules). */
export function packageVersion(name) {
  try {
    return JSON.parse(readFileSync(path.join(repoRoot, 'node_modules', name, 'package.json'), 'utf8')).version;
  } catch {
    return null;
  }
}

/** The segments of an edge or chain shape, as [[x1, y1], [x2, y2]] pairs (a loop closes). */
export function segmentsOf(shape) {
  if (shape.kind === 'edge') return [[shape.v1, shape.v2]];
  const v = shape.vertices;
  const out = [];
  for (let i = 0; i + 1 < v.length; i++) out.push([v[i], v[i + 1]]);
  if (shape.loop) out.push([v[v.length - 1], v[0]]);
  return out;
}

/**
 * A static box standing in for one segment, for engines with no usable edge shape: `half` metres
 * thick each way from its centre line, lying wholly on the side away from the bodies, so its face
 * is the segment itself. Returns { cx, cy, hx, hy, angle } in the body's frame.
 */
export function boxForSegment([p, q], side, half = 0.5) {
  const dx = q[0] - p[0];
  const dy = q[1] - p[1];
  const len = Math.hypot(dx, dy);
  // Right-hand normal of the direction p -> q; bodies on the left means the box goes right.
  const nx = dy / len;
  const ny = -dx / len;
  const off = side === 'left' ? half : side === 'right' ? -half : 0;
  return {
    cx: (p[0] + q[0]) / 2 + nx * off,
    cy: (p[1] + q[1]) / 2 + ny * off,
    hx: len / 2,
    hy: half,
    angle: Math.atan2(dy, dx),
  };
}

/**
 * A chain for an engine whose chains collide on one side only (the right of the point order, as in
 * Box2D 2.4 and v3): the points reversed when the bodies are on the left, with ghost vertices made
 * explicit (given ones, or the end segments extended) for open chains. Returns { points, loop,
 * prev, next }.
 */
export function oneSidedChain(shape) {
  let points = shape.vertices.map((p) => [p[0], p[1]]);
  let prev = shape.prev;
  let next = shape.next;
  if (shape.side === 'left') {
    points = points.reverse();
    [prev, next] = [next, prev];
  }
  if (!shape.loop) {
    const n = points.length;
    prev ??= [2 * points[0][0] - points[1][0], 2 * points[0][1] - points[1][1]];
    next ??= [2 * points[n - 1][0] - points[n - 2][0], 2 * points[n - 1][1] - points[n - 2][1]];
  }
  return { points, loop: shape.loop, prev, next };
}

/** The four corners of a box shape in the body's frame, counter-clockwise. */
export function boxCorners(s) {
  const c = Math.cos(s.angle ?? 0);
  const sn = Math.sin(s.angle ?? 0);
  const cx = s.cx ?? 0;
  const cy = s.cy ?? 0;
  return [
    [-s.hx, -s.hy],
    [s.hx, -s.hy],
    [s.hx, s.hy],
    [-s.hx, s.hy],
  ].map(([x, y]) => [cx + c * x - sn * y, cy + sn * x + c * y]);
}

/** True when a shape is an edge or chain. */
export const isSegmentShape = (s) => s.kind === 'edge' || s.kind === 'chain';
