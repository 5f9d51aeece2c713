/*
 * b2Rope against Box2D 2.2.1 (C++, float64, fdlibm expf/atan2, built as the golden README says):
 * the Testbed Rope test (40 vertices, two pinned) in three variants, turned with SetAngle as its
 * q/e keys do and stepped 600 times (every 97th step with dt = 0). The C++ printed a running
 * FNV-1a over every vertex's x, y (8 little-endian bytes each) after each step; these are its
 * values after steps 99, 199, ..., 599.
 */

import { describe, expect, it } from 'vitest';
import { b2Max, b2Min, b2Vec2 } from '../../src/common/b2Math';
import { b2_pi } from '../../src/common/b2Settings';
import { b2Rope, b2RopeDef } from '../../src/rope/b2Rope';

const kExpected = [
  ['1ce78696', 'acd4dad0', 'f7b89ec3', 'a982e75d', '7a8ac1e3', '66e24852'],
  ['26c781a9', '77a6386f', 'fea332e1', 'c6dd79df', 'ebb1bb97', 'aebbeb2d'],
  ['fc1e0ab5', '47872d7d', '0a752e8d', 'f0e9fd16', 'f19cfe08', 'e993e6ca'],
];

describe('b2Rope (Box2D 2.2.1 C++, bit for bit)', () => {
  it('follows the C++ Testbed rope in three variants for 600 steps', () => {
    let h = 2166136261;
    const bytes = new DataView(new ArrayBuffer(8));
    const hash = (v: number): void => {
      bytes.setFloat64(0, v, true);
      for (let i = 0; i < 8; ++i) h = Math.imul(h ^ bytes.getUint8(i), 16777619) >>> 0;
    };
    const got: string[][] = [];
    for (let variant = 0; variant < 3; ++variant) {
      const N = 40;
      const vertices: b2Vec2[] = [];
      const masses: number[] = [];
      for (let i = 0; i < N; ++i) {
        vertices.push(new b2Vec2(0.0, 20.0 - 0.25 * i + (variant === 2 ? 0.01 * i * i : 0)));
        masses.push(1.0 + 0.1 * variant * i);
      }
      masses[0] = 0.0;
      masses[1] = 0.0;
      const def = new b2RopeDef();
      def.vertices = vertices;
      def.count = N;
      def.gravity.Set(variant === 1 ? 2.0 : 0.0, -10.0);
      def.masses = masses;
      def.damping = 0.1 * (variant + 1);
      def.k2 = 1.0 - 0.1 * variant;
      def.k3 = 0.5 - 0.1 * variant;
      const rope = new b2Rope();
      rope.Initialize(def);
      let angle = 0.0;
      rope.SetAngle(angle);
      const row: string[] = [];
      for (let s = 0; s < 600; ++s) {
        if (s % 50 === 10) {
          angle = b2Min(b2_pi, angle + 0.05 * b2_pi);
          rope.SetAngle(angle);
        }
        if (s % 120 === 70) {
          angle = b2Max(-b2_pi, angle - 0.15 * b2_pi);
          rope.SetAngle(angle);
        }
        rope.Step(s % 97 === 0 ? 0.0 : 1.0 / 60.0, 1 + variant);
        const vs = rope.GetVertices();
        for (let i = 0; i < rope.GetVertexCount(); ++i) {
          hash(vs[i].x);
          hash(vs[i].y);
        }
        if (s % 100 === 99) row.push(h.toString(16).padStart(8, '0'));
      }
      got.push(row);
    }
    expect(got).toEqual(kExpected);
  });
});
