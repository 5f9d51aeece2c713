import { describe, expect, it } from 'vitest';
import { b2Manifold } from '../../src/collision/b2Collision';
import { b2CollidePolygons } from '../../src/collision/b2CollidePolygon';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Transform, b2Vec2 } from '../../src/common/b2Math';
import { checkManifoldFamily, collisionVectors, describeFamilyResult, makePolygon } from '../support/collisionVectors';

describe('b2CollidePolygons', () => {
  it('reproduces all 300 reference manifolds bit for bit (documented reference-rotation outliers aside)', () => {
    const cases = collisionVectors.collidePolygons;
    expect(cases.length).toBe(300);
    const result = checkManifoldFamily(cases, (manifold, c, xfA, xfB) => b2CollidePolygons(manifold, makePolygon(c.shapeA), xfA, makePolygon(c.shapeB), xfB));
    expect(describeFamilyResult('collidePolygons', result)).toBeNull();
  });

  it('covers separated, one-point, two-point, faceA and faceB reference cases', () => {
    const manifolds = collisionVectors.collidePolygons.map((c) => c.manifold);
    for (const n of [0, 1, 2]) {
      expect(manifolds.some((m) => m.pointCount === n)).toBe(true);
    }
    expect(manifolds.some((m) => m.pointCount > 0 && m.type === b2Manifold.e_faceA)).toBe(true);
    expect(manifolds.some((m) => m.pointCount > 0 && m.type === b2Manifold.e_faceB)).toBe(true);
  });

  it('gives a two-point faceA manifold for a box resting on a box', () => {
    const ground = new b2PolygonShape().SetAsBox(2.0, 0.5);
    const box = new b2PolygonShape().SetAsBox(0.5, 0.5);
    const manifold = new b2Manifold();
    b2CollidePolygons(manifold, ground, new b2Transform(), box, new b2Transform(new b2Vec2(0.0, 0.99)));
    expect(manifold.pointCount).toBe(2);
    expect(manifold.type).toBe(b2Manifold.e_faceA);
    expect(manifold.localNormal.Clone()).toEqual(new b2Vec2(0.0, 1.0));
    expect(manifold.localPoint.Clone()).toEqual(new b2Vec2(0.0, 0.5));
    // The incident face is the box's bottom face (edge 0, vertices 0 and 1), in B's frame.
    expect(manifold.points[0].localPoint.Clone()).toEqual(new b2Vec2(-0.5, -0.5));
    expect(manifold.points[1].localPoint.Clone()).toEqual(new b2Vec2(0.5, -0.5));
    expect(manifold.points[0].id.cf).toMatchObject({ indexA: 2, indexB: 0, typeA: 1, typeB: 0 });
    expect(manifold.points[1].id.cf).toMatchObject({ indexA: 2, indexB: 1, typeA: 1, typeB: 0 });
  });

  it('reports no points when the boxes are separated by more than the skins', () => {
    const a = new b2PolygonShape().SetAsBox(0.5, 0.5);
    const b = new b2PolygonShape().SetAsBox(0.5, 0.5);
    const manifold = new b2Manifold();
    b2CollidePolygons(manifold, a, new b2Transform(), b, new b2Transform(new b2Vec2(1.03, 0.0)));
    expect(manifold.pointCount).toBe(0);
  });
});
