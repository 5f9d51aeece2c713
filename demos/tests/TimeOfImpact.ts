// TimeOfImpact.h: b2TimeOfImpact on two boxes with fixed sweeps, drawn at t = 0, toi and 1.
import * as B from '../../src/index';
import { b2Color, b2MulXV, b2PolygonShape, b2Sweep, b2TimeOfImpact, b2TOIInput, b2TOIOutput, b2Transform, b2Vec2 } from '../../src/index';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

export class TimeOfImpact extends Test {
  readonly m_shapeA = new b2PolygonShape();
  readonly m_shapeB = new b2PolygonShape();

  constructor() {
    super();
    this.m_shapeA.SetAsBox(25.0, 5.0);
    this.m_shapeB.SetAsBox(2.5, 2.5);
  }

  override Step(settings: Settings): void {
    super.Step(settings);

    const sweepA = new b2Sweep();
    sweepA.c0.Set(24.0, -60.0);
    sweepA.a0 = 2.95;
    sweepA.c.Assign(sweepA.c0);
    sweepA.a = sweepA.a0;
    sweepA.localCenter.SetZero();

    const sweepB = new b2Sweep();
    sweepB.c0.Set(53.474274, -50.252514);
    sweepB.a0 = 513.36676; // - 162.0f * b2_pi;
    sweepB.c.Set(54.595478, -51.083473);
    sweepB.a = 513.62781; //  - 162.0f * b2_pi;
    sweepB.localCenter.SetZero();

    //sweepB.a0 -= 300.0f * b2_pi;
    //sweepB.a -= 300.0f * b2_pi;

    const input = new b2TOIInput();
    input.proxyA.Set(this.m_shapeA, 0);
    input.proxyB.Set(this.m_shapeB, 0);
    input.sweepA.Assign(sweepA);
    input.sweepB.Assign(sweepB);
    input.tMax = 1.0;

    const output = new b2TOIOutput();

    b2TimeOfImpact(output, input);

    this.m_debugDraw.DrawString(5, this.m_textLine, 'toi = %g', output.t);
    this.m_textLine += 15;

    this.m_debugDraw.DrawString(5, this.m_textLine, 'max toi iters = %d, max root iters = %d', B.b2_toiMaxIters, B.b2_toiMaxRootIters);
    this.m_textLine += 15;

    const vertices: b2Vec2[] = [];
    const drawShape = (shape: b2PolygonShape, xf: b2Transform, color: b2Color) => {
      vertices.length = 0;
      for (let i = 0; i < shape.m_vertexCount; ++i) {
        vertices.push(b2MulXV(xf, shape.m_vertices[i], new b2Vec2()));
      }
      this.m_debugDraw.DrawPolygon(vertices, shape.m_vertexCount, color);
    };

    const transformA = new b2Transform();
    sweepA.GetTransform(transformA, 0.0);
    drawShape(this.m_shapeA, transformA, new b2Color(0.9, 0.9, 0.9));

    const transformB = new b2Transform();
    sweepB.GetTransform(transformB, 0.0);
    // (The C++ computes the velocity of a point of B here and does not use it.)
    drawShape(this.m_shapeB, transformB, new b2Color(0.5, 0.9, 0.5));

    sweepB.GetTransform(transformB, output.t);
    drawShape(this.m_shapeB, transformB, new b2Color(0.5, 0.7, 0.9));

    sweepB.GetTransform(transformB, 1.0);
    drawShape(this.m_shapeB, transformB, new b2Color(0.9, 0.5, 0.5));
  }

  /**
   * The C++ Testbed opens every test at (0, 20) with 25 m above and below, where this test's
   * shapes (around (35, -55)) are out of view until one pans; the testbed opens it on them.
   */
  override InitialView(): { x: number; y: number; zoom: number } {
    return { x: 30.0, y: -55.0, zoom: 1.2 };
  }

  static Create(): Test {
    return new TimeOfImpact();
  }
}
