/*
 * Not in the C++: a standard load for measuring what a step costs (a backend's calibration,
 * webphysics/gpu's AutoBackend): pyramids of boxes on one ground, the testbed's Pyramid laid side
 * by side, so that the body count grows with the copies while each pyramid's work stays the same.
 */

import { b2PolygonShape } from '../collision/shapes/b2PolygonShape';
import { b2Vec2 } from '../common/b2Math';
import { b2BodyDef, b2_dynamicBody } from './b2Body';
import { b2World } from './b2World';

/** Box half-size (m); pyramids stand this many box widths apart beyond their base. */
const HALF = 0.5;
const GAP = 2;

/**
 * A new world, gravity (0, -10), of `copies` pyramids of `rows` rows of boxes (rows * (rows + 1) / 2
 * dynamic bodies each) standing on one static ground body.
 */
export function b2CreatePyramidWorld(rows: number, copies: number): b2World {
  const world = new b2World(new b2Vec2(0, -10));
  const pitch = (rows + GAP) * 2 * HALF;
  const groundShape = new b2PolygonShape();
  groundShape.SetAsBox((copies * pitch) / 2, 1, new b2Vec2((copies * pitch) / 2, -1), 0);
  world.CreateBody(new b2BodyDef()).CreateFixture(groundShape, 0);
  const box = new b2PolygonShape();
  box.SetAsBox(HALF, HALF);
  const def = new b2BodyDef();
  def.type = b2_dynamicBody;
  for (let p = 0; p < copies; ++p) {
    const left = p * pitch + GAP * HALF;
    for (let row = 0; row < rows; ++row) {
      for (let k = 0; k < rows - row; ++k) {
        def.position.Set(left + (row + 2 * k + 1) * HALF, HALF + row * 2 * HALF);
        world.CreateBody(def).CreateFixture(box, 1);
      }
    }
  }
  return world;
}
