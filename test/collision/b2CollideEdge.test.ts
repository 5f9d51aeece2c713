import { describe, expect, it } from 'vitest';
import { b2ContactFeature, b2Manifold } from '../../src/collision/b2Collision';
import { b2CollideEdgeAndCircle, b2CollideEdgeAndPolygon } from '../../src/collision/b2CollideEdge';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2EdgeShape } from '../../src/collision/shapes/b2EdgeShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Rot, b2Transform, b2Vec2 } from '../../src/common/b2Math';
import { collisionVectors, checkManifoldFamily, describeFamilyResult, makeCircle, makeEdge, makePolygon } from '../support/collisionVectors';

function edge(x1: number, y1: number, x2: number, y2: number): b2EdgeShape {
  const shape = new b2EdgeShape();
  shape.Set(new b2Vec2(x1, y1), new b2Vec2(x2, y2));
  return shape;
}

function circle(radius: number): b2CircleShape {
  const shape = new b2CircleShape();
  shape.m_radius = radius;
  return shape;
}

function box(hx: number, hy: number): b2PolygonShape {
  const shape = new b2PolygonShape();
  shape.SetAsBox(hx, hy);
  return shape;
}

function at(x: number, y: number, angle = 0.0): b2Transform {
  return new b2Transform(new b2Vec2(x, y), new b2Rot(angle));
}

const identity = new b2Transform();

describe('b2CollideEdgeAndCircle', () => {
  it('reproduces all 300 reference edge-circle manifolds bit for bit', () => {
    const cases = collisionVectors.collideEdgeAndCircle;
    expect(cases.length).toBe(300);
    const result = checkManifoldFamily(cases, (manifold, c, xfA, xfB) => b2CollideEdgeAndCircle(manifold, makeEdge(c.shapeA), xfA, makeCircle(c.shapeB), xfB));
    expect(describeFamilyResult('collideEdgeAndCircle', result)).toBeNull();
  });

  it('makes a face contact with the edge normal on the circle side of the edge interior', () => {
    const manifold = new b2Manifold();
    const c = circle(0.5);
    c.m_p.Set(0.1, 0.0);
    b2CollideEdgeAndCircle(manifold, edge(-2, 0, 2, 0), identity, c, at(0.0, -0.4));
    expect(manifold.pointCount).toBe(1);
    expect(manifold.type).toBe(b2Manifold.e_faceA);
    expect([manifold.localNormal.x, manifold.localNormal.y]).toEqual([0, -1]);
    expect([manifold.localPoint.x, manifold.localPoint.y]).toEqual([-2, 0]);
    expect([manifold.points[0].localPoint.x, manifold.points[0].localPoint.y]).toEqual([0.1, 0.0]);
    const cf = manifold.points[0].id.cf;
    expect([cf.indexA, cf.typeA, cf.indexB, cf.typeB]).toEqual([0, b2ContactFeature.e_face, 0, b2ContactFeature.e_vertex]);
  });

  it('makes a vertex contact past an end, unless the neighbouring edge owns the circle', () => {
    const manifold = new b2Manifold();
    const shape = edge(0, 0, 2, 0);
    b2CollideEdgeAndCircle(manifold, shape, identity, circle(0.5), at(2.3, 0.2));
    expect(manifold.pointCount).toBe(1);
    expect(manifold.type).toBe(b2Manifold.e_circles);
    expect([manifold.localPoint.x, manifold.localPoint.y]).toEqual([2, 0]);
    expect(manifold.points[0].id.key).toBe(1);

    // A following edge that continues to the right is in front of the circle: no contact here.
    shape.m_vertex3.Set(4, 0);
    shape.m_hasVertex3 = true;
    b2CollideEdgeAndCircle(manifold, shape, identity, circle(0.5), at(2.3, 0.2));
    expect(manifold.pointCount).toBe(0);
  });

  it('reports nothing when the circle is out of reach', () => {
    const manifold = new b2Manifold();
    b2CollideEdgeAndCircle(manifold, edge(-1, 0, 1, 0), identity, circle(0.5), at(0.0, 0.52));
    expect(manifold.pointCount).toBe(0);
  });
});

describe('b2CollideEdgeAndPolygon', () => {
  it('reproduces all 300 reference edge-polygon manifolds bit for bit (documented reference-rotation outliers aside)', () => {
    const cases = collisionVectors.collideEdgeAndPolygon;
    expect(cases.length).toBe(300);
    const result = checkManifoldFamily(cases, (manifold, c, xfA, xfB) =>
      b2CollideEdgeAndPolygon(manifold, makeEdge(c.shapeA), xfA, makePolygon(c.shapeB), xfB),
    );
    expect(describeFamilyResult('collideEdgeAndPolygon', result)).toBeNull();
  });

  it('clips a box resting on an edge to two face-A points', () => {
    const manifold = new b2Manifold();
    // The box bottom is 0.015 above the edge: within the collider's 2 * b2_polygonRadius.
    b2CollideEdgeAndPolygon(manifold, edge(-5, 0, 5, 0), identity, box(0.5, 0.5), at(1.0, 0.515));
    expect(manifold.pointCount).toBe(2);
    expect(manifold.type).toBe(b2Manifold.e_faceA);
    expect(manifold.localNormal.x).toBeCloseTo(0.0, 15);
    expect(manifold.localNormal.y).toBeCloseTo(1.0, 15);
    const xs = [manifold.points[0].localPoint.x, manifold.points[1].localPoint.x].sort((a, b) => a - b);
    expect(xs[0]).toBeCloseTo(-0.5, 14);
    expect(xs[1]).toBeCloseTo(0.5, 14);
    expect(manifold.points[0].localPoint.y).toBeCloseTo(-0.5, 14);
    expect(manifold.points[0].id.key).not.toBe(manifold.points[1].id.key);
  });

  it('ignores a polygon beyond the collision skin', () => {
    const manifold = new b2Manifold();
    b2CollideEdgeAndPolygon(manifold, edge(-5, 0, 5, 0), identity, box(0.5, 0.5), at(1.0, 0.53));
    expect(manifold.pointCount).toBe(0);
  });

  it('uses the back face for a polygon below a one-sided edge without neighbours', () => {
    const manifold = new b2Manifold();
    b2CollideEdgeAndPolygon(manifold, edge(-5, 0, 5, 0), identity, box(0.5, 0.5), at(0.0, -0.5));
    expect(manifold.pointCount).toBe(2);
    expect(manifold.type).toBe(b2Manifold.e_faceA);
    expect(manifold.localNormal.y).toBeCloseTo(-1.0, 15);
    expect(manifold.points[0].id.cf.indexA).toBe(0);
  });
});
