/*
 * GpuRenderer (src-gpu/render/render.ts): drawing a world stepped on the GPU straight from the
 * solver's buffers into an offscreen texture. The shapes appear where the world has its bodies,
 * in b2World::DrawDebugData's colours by state (or the application's), joints as lines, the camera
 * pans and zooms, no buffer is mapped to draw, and bad arguments are refused with the rule they
 * broke and leave the renderer working. The cull pass draws what is in view and only that, a
 * shape too small to see as one pixel, and every shape type through the list that fits it.
 */

import { mkdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { expect, it } from 'vitest';
import { b2ChainShape } from '../../src/collision/shapes/b2ChainShape';
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
import { RENDER_DRAW_ARGS_WORDS, RENDER_LIST, RENDER_LIST_COUNT, RENDER_POINT_PIXELS, TEXTURE_USAGE, USAGE } from '../../src-gpu/device/layout';
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

/** The instance count of each draw list (RENDER_LIST) of the renderer's last frame. */
async function listCounts(ctx: GpuContext, renderer: GpuRenderer): Promise<Record<keyof typeof RENDER_LIST, number>> {
  const args = renderer['cull'].args;
  const buffer = ctx.createBuffer('test.drawArgs', args.size, USAGE.COPY_DST | USAGE.MAP_READ);
  const encoder = ctx.device.createCommandEncoder();
  encoder.copyBufferToBuffer(args, 0, buffer, 0, args.size);
  ctx.device.queue.submit([encoder.finish()]);
  await buffer.mapAsync(1);
  const words = new Uint32Array(buffer.getMappedRange().slice(0));
  buffer.unmap();
  buffer.destroy();
  expect(words.length).toBe(RENDER_LIST_COUNT * RENDER_DRAW_ARGS_WORDS);
  const out = {} as Record<keyof typeof RENDER_LIST, number>;
  for (const [name, list] of Object.entries(RENDER_LIST)) out[name as keyof typeof RENDER_LIST] = words[RENDER_DRAW_ARGS_WORDS * list + 1];
  return out;
}

/** A static body at (x, y) holding `shape`. */
function staticBody(world: b2World, x: number, y: number, shape: b2PolygonShape | b2CircleShape | b2EdgeShape | b2ChainShape): b2Body {
  const def = new b2BodyDef();
  def.position.Set(x, y);
  const body = world.CreateBody(def);
  body.CreateFixture(shape, 0);
  return body;
}

function box(h: number): b2PolygonShape {
  const shape = new b2PolygonShape();
  shape.SetAsBox(h, h);
  return shape;
}

/** A regular polygon of `n` vertices at distance `r` from its centre. */
function regular(n: number, r: number): b2PolygonShape {
  const vertices: b2Vec2[] = [];
  for (let i = 0; i < n; ++i) vertices.push(new b2Vec2(r * Math.cos((2 * Math.PI * i) / n + 0.3), r * Math.sin((2 * Math.PI * i) / n + 0.3)));
  return new b2PolygonShape().Set(vertices);
}

function circle(r: number): b2CircleShape {
  const shape = new b2CircleShape();
  shape.m_radius = r;
  return shape;
}

/** The RGB of pixel (x, y). */
function pixelAt(image: Uint8Array, x: number, y: number): [number, number, number] {
  const i = 4 * (y * SIZE + x);
  return [image[i], image[i + 1], image[i + 2]];
}

const notBackground = (r: number, g: number, b: number) => r + g + b > 0;

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

  /**
   * Attaches `world` to a new backend, steps it once and runs `body` with a renderer (camera at
   * the origin, SCALE pixels per metre) and a target; then takes them down.
   */
  async function rendering(world: b2World, body: (renderer: GpuRenderer, texture: GPUTexture) => Promise<void>): Promise<void> {
    const backend = await WebGPUBackend.create({ context: ctx });
    await world.SetBackend(backend);
    const renderer = new GpuRenderer(backend, null);
    Object.assign(renderer.camera, { x: 0, y: 0, scale: SCALE });
    const texture = target();
    try {
      world.Step(1 / 60, 8, 3);
      await body(renderer, texture);
    } finally {
      renderer.destroy();
      texture.destroy();
      await world.SetBackend(null);
    }
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
      // The floor, the box, the ball and the bob are filled; those and the ledge outlined.
      expect(await listCounts(ctx, renderer)).toEqual({ FILL_SMALL: 4, FILL: 0, OUTLINE_SMALL: 4, OUTLINE: 1, POINT: 0 });

      const image = await pixels(ctx, texture, 'render-by-state');
      await world.Synchronize();
      // The awake dynamic bodies' fills: the box, the ball and the pendulum's bob, each where the
      // GPU has its body.
      const left = centroid(
        image.map((v, i) => (Math.floor(i / 4) % SIZE < SIZE / 2 && Math.floor(i / 4 / SIZE) < SIZE / 2 ? v : 0)),
        awakeFill,
      );
      const boxAt = project(box.GetPosition(), 0, 0);
      expect(left.n).toBeGreaterThan(300); // a 20 x 20 pixel square, its outline aside
      expect(left.x).toBeCloseTo(boxAt.x, -0.5);
      expect(left.y).toBeCloseTo(boxAt.y, -0.5);
      const right = centroid(
        image.map((v, i) => (Math.floor(i / 4) % SIZE >= SIZE / 2 ? v : 0)),
        awakeFill,
      );
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
      const onlyBox = (image: Uint8Array) =>
        centroid(
          image.map((v, i) => (Math.floor(i / 4) % SIZE < 200 && Math.floor(i / 4 / SIZE) < 180 ? v : 0)),
          awakeFill,
        );
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

  it('draws no body outside the view, and one whose origin is outside but whose shape reaches in', async () => {
    const world = new b2World(new b2Vec2(0, 0));
    // The view spans x in [-12.8, 12.8] m. Beyond: a box 7 m out. Reaching in: a 4 m box whose
    // origin is 1.2 m out and whose left side is 0.8 m in.
    const outside = staticBody(world, 20, 0, box(1));
    const reaching = staticBody(world, 14, 0, box(2));
    await rendering(world, async (renderer, texture) => {
      renderer.colourBy = 'body';
      renderer.setBodyColour(outside, 0xff0000);
      renderer.setBodyColour(reaching, 0x0000ff);
      await renderer.drawTo(texture);
      expect(await listCounts(ctx, renderer)).toEqual({ FILL_SMALL: 1, FILL: 0, OUTLINE_SMALL: 1, OUTLINE: 0, POINT: 0 });
      const image = await pixels(ctx, texture, 'render-cull');
      const blue = centroid(image, (r, g, b) => r === 0 && g === 0 && b > 0);
      expect(blue.n).toBeGreaterThan(8 * 30); // the 8 columns of the box in view, 40 rows tall
      expect(blue.x).toBeGreaterThanOrEqual(SIZE - 8);
      expect(centroid(image, (r) => r > 0).n).toBe(0);

      // The culled box is there to be drawn: the camera over it draws it.
      renderer.camera.x = 20;
      await renderer.drawTo(texture);
      const red = centroid(await pixels(ctx, texture, 'render-cull-panned'), (r, g, b) => r > 0 && g === 0 && b === 0);
      expect(red.n).toBeGreaterThan(300);
      expect(red.x).toBeCloseTo(SIZE / 2, -0.5);
    });
  }, 120_000);

  it(`draws a body narrower than ${RENDER_POINT_PIXELS} pixels on screen as one pixel of its colour at its centre, and zoomed in filled and outlined`, async () => {
    const world = new b2World(new b2Vec2(0, 0));
    // 0.1 m square: 1 pixel wide at SCALE (1.6 pixels across its bounding circle), centred on the
    // centre of pixel (128, 127).
    staticBody(world, 0.05, 0.05, box(0.05));
    await rendering(world, async (renderer, texture) => {
      await renderer.drawTo(texture);
      expect(await listCounts(ctx, renderer)).toEqual({ FILL_SMALL: 0, FILL: 0, OUTLINE_SMALL: 0, OUTLINE: 0, POINT: 1 });
      const image = await pixels(ctx, texture, 'render-point');
      // The static colour (0.5, 0.9, 0.5) in full, as the outline has it, and nothing else.
      expect(pixelAt(image, 128, 127)).toEqual([128, 230, 128]);
      expect(centroid(image, notBackground).n).toBe(1);

      Object.assign(renderer.camera, { x: 0.05, y: 0.05, scale: 20 * SCALE });
      await renderer.drawTo(texture);
      expect(await listCounts(ctx, renderer)).toEqual({ FILL_SMALL: 1, FILL: 0, OUTLINE_SMALL: 1, OUTLINE: 0, POINT: 0 });
      const zoomed = await pixels(ctx, texture, 'render-point-zoomed');
      const fill = centroid(zoomed, staticFill);
      expect(fill.n).toBeGreaterThan(300); // a 20 x 20 pixel square, its outline aside
      expect(fill.x).toBeCloseTo(SIZE / 2, -0.5);
      expect(fill.y).toBeCloseTo(SIZE / 2, -0.5);
      expect(centroid(zoomed, (r, g, b) => r === 128 && g === 230 && b === 128).n).toBeGreaterThan(60);
    });
  }, 120_000);

  it('draws every visible body of a world of several workgroups of proxies, each through its list', async () => {
    const world = new b2World(new b2Vec2(0, 0));
    // 60 x 50 bodies 4 pixels apart, each centred on a pixel centre and at most 3.6 pixels across,
    // so that a body's centre pixel is its own: boxes, circles, hexagons, and boxes too small to see.
    const COLUMNS = 60;
    const ROWS = 50;
    const kinds = [() => box(0.12), () => circle(0.15), () => regular(6, 0.15), () => box(0.03)];
    const centres: { x: number; y: number }[] = [];
    for (let j = 0; j < ROWS; ++j) {
      for (let i = 0; i < COLUMNS; ++i) {
        const x = (i - COLUMNS / 2) * 0.4 + 0.05;
        const y = (j - ROWS / 2) * 0.4 + 0.05;
        staticBody(world, x, y, kinds[(i + j) % kinds.length]());
        centres.push(project({ x, y }, 0, 0));
      }
    }
    // And a row above the view.
    for (let i = 0; i < COLUMNS; ++i) staticBody(world, i - COLUMNS / 2, 20, box(0.5));
    await rendering(world, async (renderer, texture) => {
      await renderer.drawTo(texture);
      expect(renderer.lastFrame?.proxies).toBe(COLUMNS * ROWS + COLUMNS);
      const quarter = (COLUMNS * ROWS) / 4;
      expect(await listCounts(ctx, renderer)).toEqual({ FILL_SMALL: 2 * quarter, FILL: quarter, OUTLINE_SMALL: quarter, OUTLINE: 2 * quarter, POINT: quarter });
      const image = await pixels(ctx, texture, 'render-grid');
      const missing = centres.filter((c) => !notBackground(...pixelAt(image, Math.floor(c.x), Math.floor(c.y))));
      expect(missing).toEqual([]);
    });
  }, 120_000);

  it('draws polygons of 3, 4, 5 and 8 vertices and circles filled and outlined, and edges and chains outlined', async () => {
    const world = new b2World(new b2Vec2(0, 0));
    const edge = new b2EdgeShape();
    edge.Set(new b2Vec2(-2, 0), new b2Vec2(2, 0));
    const chain = new b2ChainShape();
    chain.CreateChain([new b2Vec2(-3, -1), new b2Vec2(-1, 1), new b2Vec2(1, -1), new b2Vec2(3, 1)]);
    // Each with its own colour, its channels 0 or 255: fills a quarter of it, outlines all of it.
    const shapes: { shape: b2PolygonShape | b2CircleShape | b2EdgeShape | b2ChainShape; x: number; y: number; rgb: number; filled: boolean }[] = [
      { shape: regular(3, 2), x: -9, y: 6, rgb: 0xff0000, filled: true },
      { shape: regular(4, 2), x: -3, y: 6, rgb: 0x00ff00, filled: true },
      { shape: regular(5, 2), x: 3, y: 6, rgb: 0x0000ff, filled: true },
      { shape: regular(8, 2), x: 9, y: 6, rgb: 0xffff00, filled: true },
      { shape: circle(2), x: -8, y: -5, rgb: 0xff00ff, filled: true },
      { shape: edge, x: -1, y: -5, rgb: 0x00ffff, filled: false },
      { shape: chain, x: 7, y: -5, rgb: 0xffffff, filled: false },
    ];
    const bodies = shapes.map(({ shape, x, y }) => staticBody(world, x, y, shape));
    await rendering(world, async (renderer, texture) => {
      renderer.colourBy = 'body';
      shapes.forEach(({ rgb }, i) => renderer.setBodyColour(bodies[i], rgb));
      await renderer.drawTo(texture);
      expect(await listCounts(ctx, renderer)).toEqual({ FILL_SMALL: 3, FILL: 2, OUTLINE_SMALL: 2 + 1 + 3, OUTLINE: 3, POINT: 0 });
      const image = await pixels(ctx, texture, 'render-shapes');
      for (const { shape, x, y, rgb, filled } of shapes) {
        const channels = [(rgb >> 16) & 0xff, (rgb >> 8) & 0xff, rgb & 0xff];
        const label = `${shape.constructor.name} ${shape instanceof b2PolygonShape ? shape.m_vertexCount : ''} 0x${rgb.toString(16)}`;
        const centre = project({ x, y }, 0, 0);
        const outline = centroid(image, (r, g, b) => r === channels[0] && g === channels[1] && b === channels[2]);
        // A circle's or polygon's perimeter of 60 pixels or more, the edge's 40, the chain's three
        // diagonals 20 pixels wide each.
        expect(outline.n, label).toBeGreaterThan(filled ? 60 : 35);
        expect(Math.hypot(outline.x - centre.x, outline.y - centre.y), label).toBeLessThan(6);
        if (shape instanceof b2ChainShape) {
          for (let child = 0; child < 3; ++child) {
            const left = centre.x - 30 + 20 * child;
            const inChild = centroid(
              image.map((v, i) => (Math.floor(i / 4) % SIZE >= left && Math.floor(i / 4) % SIZE < left + 20 ? v : 0)),
              (r, g, b) => r === 255 && g === 255 && b === 255,
            );
            expect(inChild.n, `chain child ${child}`).toBeGreaterThanOrEqual(15);
          }
        }
        if (!filled) continue;
        const quarter = channels.map((c) => c / 4);
        const fill = centroid(image, (r, g, b) => [r, g, b].every((v, k) => Math.abs(v - quarter[k]) <= 4));
        expect(fill.n, label).toBeGreaterThan(250); // a triangle of circumradius 20 pixels: 520
        expect(Math.hypot(fill.x - centre.x, fill.y - centre.y), label).toBeLessThan(6);
      }
    });
  }, 120_000);
});
