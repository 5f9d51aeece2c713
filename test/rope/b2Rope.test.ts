import { describe, expect, it } from 'vitest';
import { b2Color, b2Draw } from '../../src/common/b2Draw';
import { b2Vec2 } from '../../src/common/b2Math';
import type { b2Transform } from '../../src/common/b2Math';
import { b2Atan2 } from '../../src/common/b2Trig';
import { b2Rope, b2RopeDef } from '../../src/rope/b2Rope';

function makeRope(points: [number, number][], masses: number[], setup: (def: b2RopeDef) => void = () => {}): b2Rope {
  const def = new b2RopeDef();
  def.vertices = points.map(([x, y]) => new b2Vec2(x, y));
  def.count = points.length;
  def.masses = masses;
  setup(def);
  const rope = new b2Rope();
  rope.Initialize(def);
  return rope;
}

function segmentLength(rope: b2Rope, i: number): number {
  const v = rope.GetVertices();
  return Math.hypot(v[i + 1].x - v[i].x, v[i + 1].y - v[i].y);
}

function bendAngle(rope: b2Rope, i: number): number {
  const v = rope.GetVertices();
  const d1x = v[i + 1].x - v[i].x;
  const d1y = v[i + 1].y - v[i].y;
  const d2x = v[i + 2].x - v[i + 1].x;
  const d2y = v[i + 2].y - v[i + 1].y;
  return Math.atan2(d1x * d2y - d1y * d2x, d1x * d2x + d1y * d2y);
}

describe('b2Rope', () => {
  it('Initialize stores inverse masses (0 pins a vertex), rest lengths and rest angles', () => {
    const rope = makeRope(
      [
        [0, 0],
        [3, 4],
        [3, 8],
      ],
      [0, 2, 4],
    );
    expect(rope.GetVertexCount()).toBe(3);
    expect(Array.from(rope.m_ims)).toEqual([0, 0.5, 0.25]);
    expect(Array.from(rope.m_Ls)).toEqual([5, 4]);
    // d1 = (3, 4), d2 = (0, 4): cross 12, dot 16.
    expect(Object.is(rope.m_as[0], b2Atan2(12, 16))).toBe(true);
  });

  it('Initialize rejects fewer than 3 vertices', () => {
    expect(() =>
      makeRope(
        [
          [0, 0],
          [1, 0],
        ],
        [1, 1],
      ),
    ).toThrow(/count must be at least 3/);
  });

  it('a free straight rope falls under gravity as one piece (exact for representable values)', () => {
    const rope = makeRope(
      [
        [0, 0],
        [1, 0],
        [2, 0],
      ],
      [1, 1, 1],
      (def) => {
        def.gravity.Set(0, -8);
        def.damping = 0;
      },
    );
    rope.Step(0.5, 1);
    // v = h g = (0, -4), p = p0 + h v = p0 + (0, -2); the constraints are already satisfied.
    expect(rope.GetVertices().map((p) => [p.x, p.y])).toEqual([
      [0, -2],
      [1, -2],
      [2, -2],
    ]);
    expect(rope.m_vs.map((v) => [v.x, v.y])).toEqual([
      [0, -4],
      [0, -4],
      [0, -4],
    ]);
  });

  it('damping scales the velocity by exp(-h * damping) each step and pinned vertices stay put', () => {
    const h = 1 / 60;
    const rope = makeRope(
      [
        [0, 0],
        [0, -1],
        [0, -2],
      ],
      [0, 1, 1],
      (def) => {
        def.gravity.Set(0, -10);
        def.damping = 0.5;
      },
    );
    rope.Step(h, 1);
    const pinned = rope.GetVertices()[0];
    expect([pinned.x, pinned.y]).toEqual([0, 0]);
    // A hanging vertical rope stays straight: the free vertices fall, then the stretch
    // constraint pulls them back toward the pinned end, so the speed is at most h g e^(-h c).
    const vFree = -10 * h * Math.exp(-h * 0.5);
    const tip = rope.m_vs[2];
    expect(tip.x).toBe(0);
    expect(tip.y).toBeLessThan(0);
    expect(tip.y).toBeGreaterThanOrEqual(vFree * (1 + 1e-12));
  });

  it('the first step of a free fall matches v = h g e^(-h c), p = p0 + h v', () => {
    const h = 0.1;
    const rope = makeRope(
      [
        [0, 0],
        [1, 0],
        [2, 0],
      ],
      [1, 1, 1],
      (def) => {
        def.gravity.Set(0, -10);
        def.damping = 0.25;
      },
    );
    rope.Step(h, 1);
    const v = h * -10 * Math.exp(-h * 0.25);
    const p = h * v;
    for (const vertex of rope.GetVertices()) expect(vertex.y).toBe(p);
    // Velocity is recomputed from the position change, (p - p0) / h.
    for (const vel of rope.m_vs) expect(vel.y).toBe((1 / h) * p);
  });

  it('the stretch constraint projects a stretched segment back to its rest length', () => {
    // Two pinned vertices and a free end: gravity stretches only the last segment.
    const hanging = (k2: number) =>
      makeRope(
        [
          [0, 0],
          [1, 0],
          [2, 0],
        ],
        [0, 0, 1],
        (def) => {
          def.gravity.Set(0, -10);
          def.damping = 0;
          def.k2 = k2;
          def.k3 = 0;
        },
      );
    const free = hanging(0);
    free.Step(0.1, 1);
    // Without the constraint the free end falls h^2 g = 0.1 and the segment stretches.
    const tip = free.GetVertices()[2];
    expect([tip.x, tip.y]).toEqual([2, -0.1]);
    expect(segmentLength(free, 1)).toBe(Math.hypot(1, 0.1));

    const rope = hanging(1);
    rope.Step(0.1, 1);
    // With k2 = 1 the end moves back along the segment (1, -0.1) to unit length.
    const v = rope.GetVertices();
    expect(segmentLength(rope, 1)).toBeCloseTo(1, 15);
    expect((v[2].y - v[1].y) / (v[2].x - v[1].x)).toBeCloseTo(-0.1, 14);
    // The pinned pair is skipped (both inverse masses are zero).
    expect([v[0].x, v[0].y, v[1].x, v[1].y]).toEqual([0, 0, 1, 0]);
  });

  it('a hanging chain keeps its segment lengths over many steps', () => {
    const points: [number, number][] = [];
    for (let i = 0; i < 8; ++i) points.push([i * 0.5, 0]);
    const rope = makeRope(points, [0, 1, 1, 1, 1, 1, 1, 1], (def) => {
      def.gravity.Set(0, -10);
      def.k2 = 1;
      def.k3 = 0.1;
    });
    for (let i = 0; i < 300; ++i) rope.Step(1 / 60, 8);
    const v = rope.GetVertices();
    // It swung down: the tip is well below the pin, and no segment stretched by more than 1%.
    expect(v[7].y).toBeLessThan(-2);
    for (let i = 0; i < 7; ++i) expect(Math.abs(segmentLength(rope, i) - 0.5)).toBeLessThan(0.005);
  });

  it('the bend constraint applies the impulse -k3 C / (sum m |J|^2) along the angle gradient', () => {
    const k3 = 0.5;
    const rope = makeRope(
      [
        [0, 0],
        [1, 0],
        [2, 0],
      ],
      [1, 1, 1],
      (def) => {
        def.damping = 0;
        def.k2 = 0;
        def.k3 = k3;
      },
    );
    rope.SetAngle(0.5);
    rope.Step(1, 1);
    // Straight rope, unit segments: J1 = (0, 1), J2 = (0, -2), J3 = (0, 1), so sum m|J|^2 = 6
    // and C = 0 - 0.5. With k2 = 0 the stretch passes move nothing.
    const impulse = -k3 * (1.0 / 6) * (0 - 0.5);
    const v = rope.GetVertices();
    expect([v[0].x, v[0].y]).toEqual([0, impulse]);
    expect([v[1].x, v[1].y]).toEqual([1, -2 * impulse]);
    expect([v[2].x, v[2].y]).toEqual([2, impulse]);
  });

  it('the bend constraint restores the rest angle after a disturbance', () => {
    // Initialized bent by 90 degrees at the middle; then gravity on a rope pinned at the middle.
    const rope = makeRope(
      [
        [0, 0],
        [1, 0],
        [1, 1],
      ],
      [1, 0, 1],
      (def) => {
        def.damping = 0;
        def.k2 = 1;
        def.k3 = 0.5;
      },
    );
    const rest = rope.m_as[0];
    expect(rest).toBeCloseTo(Math.PI / 2, 12);
    // Push the first vertex so the angle is off by 0.3 rad, keeping the segment length.
    const p = rope.m_ps[0];
    p.Set(1 - Math.cos(0.3), -Math.sin(0.3));
    rope.m_p0s[0].Assign(p);
    const before = Math.abs(bendAngle(rope, 0) - rest);
    expect(before).toBeCloseTo(0.3, 12);
    for (let i = 0; i < 60; ++i) rope.Step(1 / 60, 2);
    expect(Math.abs(bendAngle(rope, 0) - rest)).toBeLessThan(before * 0.01);
  });

  it('SetAngle sets every rest angle and the rope bends toward it', () => {
    const points: [number, number][] = [];
    for (let i = 0; i < 6; ++i) points.push([i, 0]);
    const rope = makeRope(points, [0, 1, 1, 1, 1, 1], (def) => {
      def.damping = 0.1;
      def.k2 = 1;
      def.k3 = 0.2;
    });
    rope.SetAngle(0.25);
    expect(Array.from(rope.m_as)).toEqual([0.25, 0.25, 0.25, 0.25]);
    for (let i = 0; i < 600; ++i) rope.Step(1 / 60, 4);
    for (let i = 0; i < 4; ++i) expect(bendAngle(rope, i)).toBeCloseTo(0.25, 3);
  });

  it('the angle error is wrapped into (-pi, pi] before the bend impulse', () => {
    // Rest angle near +pi, actual angle near -pi: the short way round is a small correction.
    const rope = makeRope(
      [
        [0, 0],
        [1, 0],
        [2, 0],
      ],
      [1, 1, 1],
      (def) => {
        def.damping = 0;
        def.k2 = 0;
        def.k3 = 0.1;
      },
    );
    rope.m_ps[2].Set(0, -0.01);
    rope.SetAngle(3.1);
    const before = rope.GetVertices().map((v) => v.Clone());
    rope.Step(1, 1);
    const moved = rope.GetVertices().map((v, i) => Math.hypot(v.x - before[i].x, v.y - before[i].y));
    // Unwrapped, C would be about -6.27 rad and the vertices would jump by metres.
    expect(Math.max(...moved)).toBeLessThan(0.05);
  });

  it('Step with h = 0 changes nothing', () => {
    const rope = makeRope(
      [
        [0, 0],
        [1, 0],
        [2, 1],
      ],
      [1, 1, 1],
      (def) => def.gravity.Set(0, -10),
    );
    rope.Step(0, 8);
    expect(rope.GetVertices().map((p) => [p.x, p.y])).toEqual([
      [0, 0],
      [1, 0],
      [2, 1],
    ]);
  });

  it('Draw emits one segment per rope segment in the rope color', () => {
    const segments: number[][] = [];
    const colors: b2Color[] = [];
    class Recorder extends b2Draw {
      DrawPolygon(): void {}
      DrawSolidPolygon(): void {}
      DrawCircle(): void {}
      DrawSolidCircle(): void {}
      DrawSegment(p1: b2Vec2, p2: b2Vec2, color: b2Color): void {
        segments.push([p1.x, p1.y, p2.x, p2.y]);
        colors.push(color);
      }
      DrawTransform(_xf: b2Transform): void {}
    }
    const rope = makeRope(
      [
        [0, 0],
        [1, 0],
        [2, 0],
        [3, 0],
      ],
      [1, 1, 1, 1],
    );
    rope.Draw(new Recorder());
    expect(segments).toEqual([
      [0, 0, 1, 0],
      [1, 0, 2, 0],
      [2, 0, 3, 0],
    ]);
    expect(colors.map((c) => [c.r, c.g, c.b])).toEqual([
      [0.4, 0.5, 0.7],
      [0.4, 0.5, 0.7],
      [0.4, 0.5, 0.7],
    ]);
  });
});
