/*
 * A standalone verlet rope (Rope/b2Rope.h, b2Rope.cpp): point masses joined by stretch (C2) and
 * bend (C3) constraints, solved by position projection. It does not interact with b2World.
 *
 * The arithmetic follows b2Rope.cpp operator by operator; vector expressions are expanded into
 * scalar code with the same IEEE operation sequence, so a float64 build of the C++ gives the same
 * bits. expf is Math.exp and atan2 is b2Atan2, as in the reference build.
 */

import { b2Color } from '../common/b2Draw';
import type { b2Draw } from '../common/b2Draw';
import { b2Vec2, b2Vec2Distance } from '../common/b2Math';
import { b2Assert, b2_pi } from '../common/b2Settings';
import { b2Atan2 } from '../common/b2Trig';

export class b2RopeDef {
  /** The initial vertex positions; the first `count` entries are used. */
  vertices: b2Vec2[] = [];

  count = 0;

  /** One mass per vertex; a mass of zero pins the vertex. */
  masses: number[] = [];

  readonly gravity = new b2Vec2(0.0, 0.0);

  damping = 0.1;

  /** Stretching stiffness */
  k2 = 0.9;

  /** Bending stiffness. Values above 0.5 can make the simulation blow up. */
  k3 = 0.1;
}

const s_d = new b2Vec2();
const s_color = new b2Color(0.4, 0.5, 0.7);

export class b2Rope {
  m_count = 0;
  m_ps: b2Vec2[] = [];
  m_p0s: b2Vec2[] = [];
  m_vs: b2Vec2[] = [];

  /** Inverse masses. */
  m_ims: Float64Array = new Float64Array(0);

  /** Rest lengths of the count - 1 segments. */
  m_Ls: Float64Array = new Float64Array(0);
  /** Rest angles at the count - 2 interior vertices. */
  m_as: Float64Array = new Float64Array(0);

  readonly m_gravity = new b2Vec2();
  m_damping = 0.0;

  m_k2 = 1.0;
  m_k3 = 0.1;

  Initialize(def: Readonly<b2RopeDef>): void {
    b2Assert(def.count >= 3, 'b2Rope.Initialize: count must be at least 3');
    b2Assert(def.vertices.length >= def.count && def.masses.length >= def.count, 'b2Rope.Initialize: vertices and masses need count entries');
    const count = def.count;
    this.m_count = count;
    this.m_ps = new Array<b2Vec2>(count);
    this.m_p0s = new Array<b2Vec2>(count);
    this.m_vs = new Array<b2Vec2>(count);
    this.m_ims = new Float64Array(count);

    for (let i = 0; i < count; ++i) {
      this.m_ps[i] = def.vertices[i].Clone();
      this.m_p0s[i] = def.vertices[i].Clone();
      this.m_vs[i] = new b2Vec2(0.0, 0.0);

      const m = def.masses[i];
      if (m > 0.0) {
        this.m_ims[i] = 1.0 / m;
      } else {
        this.m_ims[i] = 0.0;
      }
    }

    const count2 = count - 1;
    const count3 = count - 2;
    this.m_Ls = new Float64Array(count2);
    this.m_as = new Float64Array(count3);

    for (let i = 0; i < count2; ++i) {
      this.m_Ls[i] = b2Vec2Distance(this.m_ps[i], this.m_ps[i + 1]);
    }

    for (let i = 0; i < count3; ++i) {
      const p1 = this.m_ps[i];
      const p2 = this.m_ps[i + 1];
      const p3 = this.m_ps[i + 2];

      const d1x = p2.x - p1.x;
      const d1y = p2.y - p1.y;
      const d2x = p3.x - p2.x;
      const d2y = p3.y - p2.y;

      const a = d1x * d2y - d1y * d2x;
      const b = d1x * d2x + d1y * d2y;

      this.m_as[i] = b2Atan2(a, b);
    }

    this.m_gravity.Assign(def.gravity);
    this.m_damping = def.damping;
    this.m_k2 = def.k2;
    this.m_k3 = def.k3;
  }

  Step(h: number, iterations: number): void {
    if (h === 0.0) {
      return;
    }

    const d = Math.exp(-h * this.m_damping);

    for (let i = 0; i < this.m_count; ++i) {
      const p = this.m_ps[i];
      const v = this.m_vs[i];
      this.m_p0s[i].Assign(p);
      if (this.m_ims[i] > 0.0) {
        v.x += h * this.m_gravity.x;
        v.y += h * this.m_gravity.y;
      }
      v.x *= d;
      v.y *= d;
      p.x += h * v.x;
      p.y += h * v.y;
    }

    for (let i = 0; i < iterations; ++i) {
      this.SolveC2();
      this.SolveC3();
      this.SolveC2();
    }

    const inv_h = 1.0 / h;
    for (let i = 0; i < this.m_count; ++i) {
      const p = this.m_ps[i];
      const p0 = this.m_p0s[i];
      this.m_vs[i].Set(inv_h * (p.x - p0.x), inv_h * (p.y - p0.y));
    }
  }

  GetVertexCount(): number {
    return this.m_count;
  }

  GetVertices(): readonly b2Vec2[] {
    return this.m_ps;
  }

  Draw(draw: b2Draw): void {
    for (let i = 0; i < this.m_count - 1; ++i) {
      draw.DrawSegment(this.m_ps[i], this.m_ps[i + 1], s_color);
    }
  }

  SetAngle(angle: number): void {
    const count3 = this.m_count - 2;
    for (let i = 0; i < count3; ++i) {
      this.m_as[i] = angle;
    }
  }

  /** Stretch constraints: project each segment back to its rest length. */
  SolveC2(): void {
    const count2 = this.m_count - 1;

    for (let i = 0; i < count2; ++i) {
      const p1 = this.m_ps[i];
      const p2 = this.m_ps[i + 1];

      // d.Normalize() leaves d unchanged and returns 0 for a degenerate segment, as in C++.
      const d = s_d.Set(p2.x - p1.x, p2.y - p1.y);
      const L = d.Normalize();

      const im1 = this.m_ims[i];
      const im2 = this.m_ims[i + 1];

      if (im1 + im2 === 0.0) {
        continue;
      }

      const s1 = im1 / (im1 + im2);
      const s2 = im2 / (im1 + im2);

      const c1 = this.m_k2 * s1 * (this.m_Ls[i] - L);
      p1.x -= c1 * d.x;
      p1.y -= c1 * d.y;
      const c2 = this.m_k2 * s2 * (this.m_Ls[i] - L);
      p2.x += c2 * d.x;
      p2.y += c2 * d.y;
    }
  }

  /** Bend constraints: rotate each vertex pair toward its rest angle. */
  SolveC3(): void {
    const count3 = this.m_count - 2;

    for (let i = 0; i < count3; ++i) {
      const p1 = this.m_ps[i];
      const p2 = this.m_ps[i + 1];
      const p3 = this.m_ps[i + 2];

      const m1 = this.m_ims[i];
      const m2 = this.m_ims[i + 1];
      const m3 = this.m_ims[i + 2];

      const d1x = p2.x - p1.x;
      const d1y = p2.y - p1.y;
      const d2x = p3.x - p2.x;
      const d2y = p3.y - p2.y;

      const L1sqr = d1x * d1x + d1y * d1y;
      const L2sqr = d2x * d2x + d2y * d2y;

      if (L1sqr * L2sqr === 0.0) {
        continue;
      }

      const a = d1x * d2y - d1y * d2x;
      const b = d1x * d2x + d1y * d2y;

      let angle = b2Atan2(a, b);

      // Jd1 = (-1 / L1sqr) * d1.Skew(), Jd2 = (1 / L2sqr) * d2.Skew(), with Skew(v) = (-v.y, v.x).
      const s1 = -1.0 / L1sqr;
      const Jd1x = s1 * -d1y;
      const Jd1y = s1 * d1x;
      const s2 = 1.0 / L2sqr;
      const Jd2x = s2 * -d2y;
      const Jd2y = s2 * d2x;

      const J1x = -Jd1x;
      const J1y = -Jd1y;
      const J2x = Jd1x - Jd2x;
      const J2y = Jd1y - Jd2y;
      const J3x = Jd2x;
      const J3y = Jd2y;

      let mass = m1 * (J1x * J1x + J1y * J1y) + m2 * (J2x * J2x + J2y * J2y) + m3 * (J3x * J3x + J3y * J3y);
      if (mass === 0.0) {
        continue;
      }

      mass = 1.0 / mass;

      let C = angle - this.m_as[i];

      while (C > b2_pi) {
        angle -= 2 * b2_pi;
        C = angle - this.m_as[i];
      }

      while (C < -b2_pi) {
        angle += 2.0 * b2_pi;
        C = angle - this.m_as[i];
      }

      const impulse = -this.m_k3 * mass * C;

      const i1 = m1 * impulse;
      p1.x += i1 * J1x;
      p1.y += i1 * J1y;
      const i2 = m2 * impulse;
      p2.x += i2 * J2x;
      p2.y += i2 * J2y;
      const i3 = m3 * impulse;
      p3.x += i3 * J3x;
      p3.y += i3 * J3y;
    }
  }
}
