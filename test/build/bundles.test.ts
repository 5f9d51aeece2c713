import { readFileSync } from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import vm from 'node:vm';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { buildBundles } from '../support/bundles';

let bundles: { dir: string; remove(): void };
let outDir = '';

beforeAll(() => {
  bundles = buildBundles();
  outDir = bundles.dir;
});

afterAll(() => {
  bundles.remove();
});

/** Drops a 1x1 box from y = 4 for 60 steps with the given namespace-free constructors. */
function dropBox(api: Record<string, any>): number {
  const world = new api.b2World(new api.b2Vec2(0, -10));
  const def = new api.b2BodyDef();
  def.type = api.b2_dynamicBody ?? 2;
  def.position.Set(0, 4);
  const body = world.CreateBody(def);
  const box = new api.b2PolygonShape();
  box.SetAsBox(1, 1);
  body.CreateFixture(box, 1);
  for (let i = 0; i < 60; i++) world.Step(1 / 60, 8, 3);
  return body.GetPosition().y;
}

describe('npm run build', () => {
  it('makes an ES module that runs a world', async () => {
    const mod = await import(pathToFileURL(path.join(outDir, 'webphysics.mjs')).href);
    expect(dropBox(mod)).toBeCloseTo(4 - (10 * 61) / (2 * 60), 12);
  });

  for (const file of ['box2d.js', 'box2d.min.js']) {
    it(`makes ${file}, a classic script that defines the global Box2D with Box2DWeb's namespaces`, () => {
      const context = vm.createContext({});
      vm.runInContext(readFileSync(path.join(outDir, file), 'utf8'), context, { filename: file });
      const Box2D = (context as { Box2D: any }).Box2D;
      expect(typeof Box2D.Dynamics.b2World).toBe('function');
      expect(typeof Box2D.Collision.Shapes.b2PolygonShape).toBe('function');
      expect(typeof Box2D.Dynamics.Joints.b2RevoluteJointDef).toBe('function');
      const y = dropBox({
        b2World: Box2D.Dynamics.b2World,
        b2Vec2: Box2D.Common.Math.b2Vec2,
        b2BodyDef: Box2D.Dynamics.b2BodyDef,
        b2PolygonShape: Box2D.Collision.Shapes.b2PolygonShape,
      });
      expect(y).toBeCloseTo(4 - (10 * 61) / (2 * 60), 12);
    });
  }

  it('writes source maps next to each bundle', () => {
    for (const file of ['webphysics.mjs', 'box2d.js', 'box2d.min.js']) {
      const map = JSON.parse(readFileSync(path.join(outDir, `${file}.map`), 'utf8'));
      expect(map.sources.some((s: string) => s.endsWith('b2World.ts'))).toBe(true);
    }
  });
});
