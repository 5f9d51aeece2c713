// Rope.h (in 2.2.1's TestEntries.cpp only in commented-out lines): a b2Rope of 40 vertices, the
// first two pinned. Keys: q/e adjust the target bend angle.
import { b2Max, b2Min, b2Rope, b2RopeDef, b2Vec2, b2_pi } from '../../src/index';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

export class Rope extends Test {
  readonly m_rope = new b2Rope();
  m_angle: number;

  constructor() {
    super();
    const N = 40;
    const vertices: b2Vec2[] = [];
    const masses: number[] = [];

    for (let i = 0; i < N; ++i) {
      vertices.push(new b2Vec2(0.0, 20.0 - 0.25 * i));
      masses.push(1.0);
    }
    masses[0] = 0.0;
    masses[1] = 0.0;

    const def = new b2RopeDef();
    def.vertices = vertices;
    def.count = N;
    def.gravity.Set(0.0, -10.0);
    def.masses = masses;
    def.damping = 0.1;
    def.k2 = 1.0;
    def.k3 = 0.5;

    this.m_rope.Initialize(def);

    this.m_angle = 0.0;
    this.m_rope.SetAngle(this.m_angle);
  }

  override Keyboard(key: string): void {
    switch (key) {
      case 'q':
        this.m_angle = b2Max(-b2_pi, this.m_angle - 0.05 * b2_pi);
        this.m_rope.SetAngle(this.m_angle);
        break;

      case 'e':
        this.m_angle = b2Min(b2_pi, this.m_angle + 0.05 * b2_pi);
        this.m_rope.SetAngle(this.m_angle);
        break;
    }
  }

  override Step(settings: Settings): void {
    let dt = settings.hz > 0.0 ? 1.0 / settings.hz : 0.0;

    if (settings.pause === 1 && settings.singleStep === 0) {
      dt = 0.0;
    }

    this.m_rope.Step(dt, 1);

    super.Step(settings);

    this.m_rope.Draw(this.m_debugDraw);

    this.m_debugDraw.DrawString(5, this.m_textLine, 'Press (q,e) to adjust target angle');
    this.m_textLine += 15;
    this.m_debugDraw.DrawString(5, this.m_textLine, 'Target angle = %g degrees', (this.m_angle * 180.0) / b2_pi);
    this.m_textLine += 15;
  }

  static Create(): Test {
    return new Rope();
  }
}
