import { describe, expect, it } from 'vitest';
import { b2Manifold } from '../../src/collision/b2Collision';
import { b2CollideCircles, b2CollidePolygonAndCircle } from '../../src/collision/b2CollideCircle';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Transform, b2Vec2 } from '../../src/common/b2Math';
import { collisionVectors, checkManifoldFamily, describeFamilyResult, makeCircle, makePolygon } from '../support/collisionVectors';

describe('b2CollideCircles', () => {
  it('reproduces all 300 reference manifolds bit for bit', () => {
    const cases = collisionVectors.collideCircles;
    expect(cases.length).toBe(300);
    const result = checkManifoldFamily(cases, (manifold, c, xfA, xfB) => b2CollideCircles(manifold, makeCircle(c.shapeA), xfA, makeCircle(c.shapeB), xfB));
    expect(describeFamilyResult('collideCircles', result)).toBeNull();
  });

  it('exercises both touching and separated reference cases', () => {
    const counts = collisionVectors.collideCircles.map((c) => c.manifold.pointCount);
    expect(counts.filter((n) => n === 0).length).toBeGreaterThan(0);
    expect(counts.filter((n) => n === 1).length).toBeGreaterThan(0);
  });

  it('counts circles that exactly touch as colliding, with zero key and local centers', () => {
    const a = new b2CircleShape();
    a.m_radius = 0.5;
    a.m_p.Set(0.25, 0.0);
    const b = new b2CircleShape();
    b.m_radius = 0.5;
    const xfA = new b2Transform();
    const xfB = new b2Transform(new b2Vec2(1.25, 0.0));
    const manifold = new b2Manifold();
    manifold.points[0].id.cf.indexA = 7;
    b2CollideCircles(manifold, a, xfA, b, xfB);
    expect(manifold.pointCount).toBe(1);
    expect(manifold.type).toBe(b2Manifold.e_circles);
    expect(manifold.localPoint.Clone()).toEqual(new b2Vec2(0.25, 0.0));
    expect(manifold.points[0].id.key).toBe(0);
    expect(manifold.points[0].id.cf.indexA).toBe(0);

    xfB.p.x = 1.2500001;
    b2CollideCircles(manifold, a, xfA, b, xfB);
    expect(manifold.pointCount).toBe(0);
  });
});

describe('b2CollidePolygonAndCircle', () => {
  it('reproduces all 300 reference manifolds bit for bit (documented reference-rotation outliers aside)', () => {
    const cases = collisionVectors.collidePolygonAndCircle;
    expect(cases.length).toBe(300);
    const result = checkManifoldFamily(cases, (manifold, c, xfA, xfB) =>
      b2CollidePolygonAndCircle(manifold, makePolygon(c.shapeA), xfA, makeCircle(c.shapeB), xfB),
    );
    expect(describeFamilyResult('collidePolygonAndCircle', result)).toBeNull();
  });

  it('uses the face normal for a circle whose center is inside the box', () => {
    const box = new b2PolygonShape().SetAsBox(1.0, 0.5);
    const circle = new b2CircleShape();
    circle.m_radius = 0.1;
    const manifold = new b2Manifold();
    b2CollidePolygonAndCircle(manifold, box, new b2Transform(), circle, new b2Transform(new b2Vec2(0.0, 0.4)));
    expect(manifold.pointCount).toBe(1);
    expect(manifold.type).toBe(b2Manifold.e_faceA);
    // Face 2 (+y) has the largest separation, -0.1.
    expect(manifold.localNormal.Clone()).toEqual(new b2Vec2(0.0, 1.0));
    expect(manifold.localPoint.Clone()).toEqual(new b2Vec2(0.0, 0.5));
  });

  it('uses the vertex region normal near a corner and misses beyond the radius', () => {
    const box = new b2PolygonShape().SetAsBox(1.0, 1.0);
    const circle = new b2CircleShape();
    circle.m_radius = 0.5;
    const manifold = new b2Manifold();
    // Circle center at (1.3, 1.4) is in the corner region of vertex 2 (1, 1): distance 0.5 < 0.5 + 0.01.
    b2CollidePolygonAndCircle(manifold, box, new b2Transform(), circle, new b2Transform(new b2Vec2(1.3, 1.4)));
    expect(manifold.pointCount).toBe(1);
    expect(manifold.localPoint.Clone()).toEqual(new b2Vec2(1.0, 1.0));
    const nx = 1.3 - 1.0;
    const ny = 1.4 - 1.0;
    const len = Math.sqrt(nx * nx + ny * ny);
    expect(manifold.localNormal.x).toBe(nx * (1.0 / len));
    expect(manifold.localNormal.y).toBe(ny * (1.0 / len));

    b2CollidePolygonAndCircle(manifold, box, new b2Transform(), circle, new b2Transform(new b2Vec2(1.4, 1.4)));
    expect(manifold.pointCount).toBe(0);
  });
});
