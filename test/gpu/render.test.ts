/*
 * GpuRenderer (src-gpu/render/render.ts): drawing a world stepped on the GPU straight from the
 * solver's buffers into an offscreen texture. The shapes appear where the world has its bodies,
 * in b2World::DrawDebugData's colours by state (or the application's), joints as lines, the camera
 * pans and zooms, no buffer is mapped to draw, and bad arguments are refused with the rule they
 * broke and leave the renderer working.
 */

import { mkdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { expect, it } from 'vitest';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2EdgeShape } from '../../src/collision/shapes/b2EdgeShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2BodyDef, b2_dynamicBody } from '../../src/dynamics/b2Body';
import type { b2Body } from '../../src/dynamics/b2Body';
import { b2World } from '../../src/dynamics/b2World';
import { b2RevoluteJointDef } from '../../src/dynamics/joints/b2RevoluteJoint';
import { WebGPUBackend } from '../../src-gpu/backend/backend';
import type { GpuContext } from '../../src-gpu/device/device';
import { TEXTURE_USAGE, USAGE } from '../../src-gpu/device/layout';
import { GpuRenderer } from '../../src-gpu/render/render';
import { encodePng } from '../support/png';
import { describeGpu } from './support';

/** Frames the tests draw, for people to look at (gitignored). */
const artifacts = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../test-artifacts/gpu');
const SIZE = 256;
const SCALE = 10;

interface Scene {
  world: b2World;
  box: b2Body;
  ball: b2Body;
  pendulum: b2Body;
}

/** A ground box, a falling box, a ball resting on an edge, a pendulum on a revolute joint. */
function scene(): Scene {
  const world = new b2World(new b2Vec2(0, -10));
  world.SetAllowSleeping(false);
  const ground = world.CreateBody(new b2BodyDef());
  const floor = new b2PolygonShape();
  floor.SetAsBox(10, 0.5, new b2Vec2(0, -10), 0);
  ground.CreateFixture(floor, 0);
  const ledge = new b2EdgeShape();
  ledge.Set(new b2Vec2(4, 0), new b2Vec2(10, 0));
  ground.CreateFixture(ledge, 0);

  const dynamic = (x: number, y: number): b2Body => {
    const def = new b2BodyDef();
    def.type = b2_dynamicBody;
    def.position.Set(x, y);
    return world.CreateBody(def);
  };
  const box = dynamic(-5, 4);
  const square = new b2PolygonShape();
  square.SetAsBox(1, 1);
  box.CreateFixture(square, 1);
  const ball = dynamic(7, 1);
  const disc = new b2CircleShape();
  disc.m_radius = 1;
  ball.CreateFixture(disc, 1);
  const pendulum = dynamic(-5, -4);
  const bob = new b2PolygonShape();
  bob.SetAsBox(0.5, 0.5);
  pendulum.CreateFixture(bob, 1);
  const joint = new b2RevoluteJointDef();
  joint.Initialize(ground, pendulum, new b2Vec2(-9, -4));
  world.CreateJoint(joint);
  return { world, box, ball, pendulum };
}

/** The texture's pixels (RGBA bytes, row 0 at the top) after the queue's work, also saved as `name`.png. */
async function pixels(ctx: GpuContext, texture: GPUTexture, name: string): Promise<Uint8Array> {
  const bytesPerRow = SIZE * 4;
  const buffer = ctx.createBuffer('test.pixels', bytesPerRow * SIZE, USAGE.COPY_DST | USAGE.MAP_READ);
  const encoder = ctx.device.createCommandEncoder();
  encoder.copyTextureToBuffer({ texture }, { buffer, bytesPerRow }, [SIZE, SIZE]);
  ctx.device.queue.submit([encoder.finish()]);
  await buffer.mapAsync(1);
  const out = new Uint8Array(buffer.getMappedRange().slice(0));
  buffer.unmap();
  buffer.destroy();
  mkdirSync(artifacts, { recursive: true });
  writeFileSync(path.join(artifacts, `${name}.png`), encodePng(SIZE, SIZE, out));
  return out;
}

/** Mean pixel position of the pixels `match` accepts, and how many there are. */
function centroid(image: Uint8Array, match: (r: number, g: number, b: number) => boolean): { x: number; y: number; n: number } {
  let x = 0;
  let y = 0;
  let n = 0;
  for (let i = 0; i < SIZE * SIZE; ++i) {
    if (!match(image[4 * i], image[4 * i + 1], image[4 * i + 2])) continue;
    x += i % SIZE;
    y += Math.floor(i / SIZE);
    n++;
  }
  return { x: x / n, y: y / n, n };
}

/** Where a world point lands in the texture for a camera at (cx, cy). */
function project(p: { x: number; y: number }, cx: number, cy: number, scale = SCALE): { x: number; y: number } {
  return { x: SIZE / 2 + (p.x - cx) * scale, y: SIZE / 2 - (p.y - cy) * scale };
}

// Fills at half colour and alpha over black: awake dynamic (0.9, 0.7, 0.7) -> about (57, 45, 45),
// static (0.5, 0.9, 0.5) -> about (32, 57, 32).
const awakeFill = (r: number, g: number, b: number) => r >= 50 && r <= 64 && g >= 40 && g <= 50 && b >= 40 && b <= 50;
const staticFill = (r: number, g: number, b: number) => g >= 50 && g <= 64 && r >= 28 && r <= 36 && b >= 28 && b <= 36;
const jointLine = (r: number, g: number, b: number) => r === 128 && g === 204 && b === 204;

describeGpu('GpuRenderer: the world drawn from the GPU buffers', (ctx) => {
  function target(): GPUTexture {
    return ctx.device.createTexture({
      size: [SIZE, SIZE],
      format: 'rgba8unorm',
      usage: TEXTURE_USAGE.RENDER_ATTACHMENT | TEXTURE_USAGE.COPY_SRC,
    });
  }

  it('draws each shape where the world has its body, by state, and joints as lines, mapping no buffer', async () => {
    const { world, box, ball, pendulum } = scene();
    const backend = await WebGPUBackend.create({ context: ctx });
    await world.SetBackend(backend);
    const renderer = new GpuRenderer(backend, null);
    renderer.camera.x = 0;
    renderer.camera.y = 0;
    renderer.camera.scale = SCALE;
    const texture = target();
    const maps: string[] = [];
    const proto = Object.getPrototypeOf(ctx.createBuffer('probe', 16, USAGE.COPY_DST)) as { mapAsync: (...args: unknown[]) => Promise<void> };
    const mapAsync = proto.mapAsync;
    try {
      for (let i = 0; i < 20; ++i) await world.StepAsync(1 / 60, 8, 3);
      proto.mapAsync = function (this: GPUBuffer, ...args: unknown[]) {
        maps.push(this.label);
        return mapAsync.apply(this, args);
      };
      await renderer.drawTo(texture);
      proto.mapAsync = mapAsync;
      expect(maps, 'buffers mapped while drawing').toEqual([]);
      expect(renderer.lastFrame).toMatchObject({ proxies: 5, joints: 1 });

      const image = await pixels(ctx, texture, 'render-by-state');
      await world.Synchronize();
      // The awake dynamic bodies' fills: the box, the ball and the pendulum's bob, each where the
      // GPU has its body.
      const left = centroid(image.map((v, i) => (Math.floor(i / 4) % SIZE < SIZE / 2 && Math.floor(i / 4 / SIZE) < SIZE / 2 ? v : 0)), awakeFill);
      const boxAt = project(box.GetPosition(), 0, 0);
      expect(left.n).toBeGreaterThan(300); // a 20 x 20 pixel square, its outline aside
      expect(left.x).toBeCloseTo(boxAt.x, -0.5);
      expect(left.y).toBeCloseTo(boxAt.y, -0.5);
      const right = centroid(image.map((v, i) => (Math.floor(i / 4) % SIZE >= SIZE / 2 ? v : 0)), awakeFill);
      const ballAt = project(ball.GetPosition(), 0, 0);
      expect(right.n).toBeGreaterThan(250); // a disc of radius 10 pixels: 314, its outline aside
      expect(right.x).toBeCloseTo(ballAt.x, -0.5);
      expect(right.y).toBeCloseTo(ballAt.y, -0.5);
      const ground = centroid(image, staticFill);
      expect(ground.n).toBeGreaterThan(1500); // the 200 x 10 pixel floor
      expect(ground.y).toBeCloseTo(project({ x: 0, y: -10 }, 0, 0).y, -0.5);
      // The joint: lines from the ground's origin to the anchor and from the bob to the anchor.
      const joint = centroid(image, jointLine);
      expect(joint.n).toBeGreaterThan(20);
      const anchor = project({ x: -9, y: -4 }, 0, 0);
      expect(Math.hypot(joint.x - anchor.x, joint.y - anchor.y)).toBeLessThan(60);
      expect(pendulum.GetPosition().y).toBeLessThan(-3.9);
    } finally {
      proto.mapAsync = mapAsync;
      renderer.destroy();
      texture.destroy();
      await world.SetBackend(null);
    }
  }, 120_000);

  it('follows the camera: a pan moves the picture, a zoom scales it', async () => {
    const { world, box } = scene();
    const backend = await WebGPUBackend.create({ context: ctx });
    await world.SetBackend(backend);
    const renderer = new GpuRenderer(backend, null);
    const texture = target();
    try {
      world.Step(1 / 60, 8, 3);
      await world.Synchronize();
      // The box alone: the bob (80 pixels or more below it) and the ball (at the right edge or
      // beyond) are left out.
      const onlyBox = (image: Uint8Array) => centroid(image.map((v, i) => (Math.floor(i / 4) % SIZE < 200 && Math.floor(i / 4 / SIZE) < 180 ? v : 0)), awakeFill);
      Object.assign(renderer.camera, { x: -5, y: 4, scale: SCALE });
      await renderer.drawTo(texture);
      const centred = onlyBox(await pixels(ctx, texture, 'render-camera-1'));
      const at = project(box.GetPosition(), -5, 4);
      expect(centred.x).toBeCloseTo(at.x, -0.5);
      expect(centred.y).toBeCloseTo(at.y, -0.5);

      Object.assign(renderer.camera, { x: -2, y: 4, scale: 2 * SCALE });
      await renderer.drawTo(texture);
      const moved = onlyBox(await pixels(ctx, texture, 'render-camera-2'));
      const movedAt = project(box.GetPosition(), -2, 4, 2 * SCALE);
      expect(moved.x).toBeCloseTo(movedAt.x, -0.5);
      expect(moved.y).toBeCloseTo(movedAt.y, -0.5);
      expect(moved.n / centred.n).toBeGreaterThan(3.5); // twice the scale, four times the area
    } finally {
      renderer.destroy();
      texture.destroy();
      await world.SetBackend(null);
    }
  }, 120_000);

  it("colours bodies by the application's choice, and refuses a bad colour or camera with the rule, drawing on after", async () => {
    const { world, box } = scene();
    const backend = await WebGPUBackend.create({ context: ctx });
    await world.SetBackend(backend);
    const renderer = new GpuRenderer(backend, null);
    renderer.camera.scale = SCALE;
    const texture = target();
    try {
      world.Step(1 / 60, 8, 3);
      renderer.colourBy = 'body';
      renderer.setBodyColour(box, 0xff0000);
      expect(() => renderer.setBodyColour(box, 0x1000000)).toThrow(/setBodyColour: rgb must be an integer 0xRRGGBB in \[0, 0xffffff\], got 16777216/);
      expect(() => renderer.setBodyColour(box, 1.5)).toThrow(RangeError);
      renderer.camera.scale = 0;
      await expect(renderer.drawTo(texture)).rejects.toThrow(/camera\.scale must be a positive number of pixels per metre, got 0/);
      renderer.camera.scale = SCALE;
      const wrong = ctx.device.createTexture({ size: [4, 4], format: 'bgra8unorm', usage: TEXTURE_USAGE.RENDER_ATTACHMENT });
      await expect(renderer.drawTo(wrong)).rejects.toThrow(/texture's format is bgra8unorm, this renderer draws rgba8unorm/);
      wrong.destroy();

      await renderer.drawTo(texture);
      const image = await pixels(ctx, texture, 'render-by-body');
      // Red at a quarter (the fill: half the colour at half alpha), and the box's outline in full red.
      const red = centroid(image, (r, g, b) => r >= 60 && r <= 68 && g === 0 && b === 0);
      await world.Synchronize();
      const at = project(box.GetPosition(), 0, 0);
      expect(red.n).toBeGreaterThan(300);
      expect(red.x).toBeCloseTo(at.x, -0.5);
      expect(red.y).toBeCloseTo(at.y, -0.5);
      expect(centroid(image, (r, g, b) => r === 255 && g === 0 && b === 0).n).toBeGreaterThan(40);
      // The bodies left uncoloured keep their state's colours: the static floor.
      expect(centroid(image, staticFill).n).toBeGreaterThan(1500);
    } finally {
      renderer.destroy();
      texture.destroy();
      await world.SetBackend(null);
    }
  }, 120_000);
});
