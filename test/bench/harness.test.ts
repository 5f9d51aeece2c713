// Smoke test of the benchmark harness (bench/): one small scene, our engine and one peer, quick mode.
// No timing assertions: speed is what `npm run bench` measures, never a unit test.
import { mkdirSync, mkdtempSync, readFileSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { cpuCaches, describeCaches, runBench, worldHeapBytes, type BenchResults } from '../../bench/run.mjs';
import { makeScene, SCENE_IDS } from '../../bench/scenes.mjs';
import { measureAllocation } from '../../bench/memory.mjs';
import { loadBox2DWeb } from '../../bench/engines/box2dweb.mjs';
import { readGoldenJson } from '../support/golden';

let outDir = '';
let results: BenchResults;

beforeAll(async () => {
  outDir = mkdtempSync(path.join(tmpdir(), 'webphysics-bench-test-'));
  results = await runBench({
    quick: true,
    scenes: ['bench2d'],
    engines: ['webphysics', 'planck'],
    sleep: 'off',
    allocPreroll: 5,
    outDir,
    log: null,
    print: null,
  });
});

afterAll(() => {
  rmSync(outDir, { recursive: true, force: true });
});

describe('runBench in quick mode', () => {
  it('writes a run file, latest.json with the same content, and an SVG chart', () => {
    const files = readdirSync(outDir);
    const runFile = files.find((f) => /^\d{4}-\d\d-\d\dT.*-quick\.json$/.test(f));
    expect(runFile).toBeDefined();
    expect(readFileSync(path.join(outDir, 'latest.json'), 'utf8')).toBe(readFileSync(path.join(outDir, runFile!), 'utf8'));
    const svg = readFileSync(path.join(outDir, 'bench2d.svg'), 'utf8');
    expect(svg.startsWith('<svg')).toBe(true);
    expect(svg).toContain('WebPhysics');
    expect(svg).toContain('planck');
  });

  it('records the machine, the engines and their versions', () => {
    const json = JSON.parse(readFileSync(path.join(outDir, 'latest.json'), 'utf8')) as BenchResults;
    expect(json.schema).toBe('webphysics-bench/1');
    expect(json.machine.node).toBe(process.version);
    expect(json.machine.cpus).toBeGreaterThan(0);
    expect(json.machine.caches).toEqual(cpuCaches());
    expect(json.engines.map((e) => e.id)).toEqual(['webphysics', 'planck']);
    for (const e of json.engines) {
      expect(e.loadError).toBeNull();
      expect(e.version).toMatch(/^\d+\.\d+\.\d+/);
    }
  });

  it('times every step of every round for both engines, with memory figures', () => {
    const scene = results.scenes[0];
    expect(scene.id).toBe('bench2d');
    expect(scene.results).toHaveLength(2);
    for (const r of scene.results) {
      expect(r.status).toBe('ok');
      expect(r.sleep).toBe(false);
      const t = r.timing!;
      expect(t.samples).toBe(scene.protocol.steps * scene.protocol.rounds);
      expect(t.medianMs).toBeGreaterThan(0);
      expect(t.p95Ms).toBeGreaterThanOrEqual(t.medianMs);
      expect(t.stepsPerSecond).toBeGreaterThan(0);
      expect(t.roundMedians).toHaveLength(scene.protocol.rounds);
      expect(Number.isFinite(r.memory!.allocBytesPerStep)).toBe(true);
      expect(r.memory!.allocBytesPerStep).toBeGreaterThanOrEqual(0);
      expect(r.memory!.worldBytes).toBeGreaterThan(0);
      expect(r.counts!.bodies).toBe(scene.bodies);
      expect(r.counts!.contacts).toBeGreaterThan(0);
    }
    expect(scene.results.find((r) => r.engine === 'webphysics')!.ratioToOurs).toBe(1);
  });

  it('finds that the pyramid simulates and settles in both engines', () => {
    const preroll = results.scenes[0].protocol;
    for (const r of results.scenes[0].results) {
      expect(r.check, r.engine).not.toBeNull();
      expect(r.check!.ok, `${r.engine}: ${r.check!.detail}`).toBe(true);
      // --alloc-preroll's steps run between the timed rounds and the allocation window.
      expect(preroll.allocPreroll).toBe(5);
      expect(r.counts!.steps).toBe(preroll.preroll + preroll.steps + preroll.allocPreroll + preroll.allocSteps);
    }
  });
});

describe('bench scenes', () => {
  it('lays out the bench2d pyramid exactly as the golden bench2d-pyramid scene', () => {
    type Body = { type: number; position: { x: number; y: number }; fixture: { density: number; polygon?: { box?: { hx: number } } }[] };
    const golden = readGoldenJson<{ body: Body[] }>('scenes/bench2d-pyramid.scene.json');
    const boxes = golden.body.filter((b) => b.type === 2);
    const scene = makeScene('bench2d')!;
    const ours = scene.bodies.filter((b) => b.type === 'dynamic');
    expect(ours).toHaveLength(820);
    expect(ours.map((b) => [b.x, b.y])).toEqual(boxes.map((b) => [b.position.x, b.position.y]));
    for (const b of boxes) expect(b.fixture[0].density).toBe(5);
  });

  it('builds every scene with bodies and a sanity check', () => {
    for (const id of SCENE_IDS) {
      const scene = makeScene(id, { quick: true });
      if (scene === null) continue; // mixed-rain without the golden folder
      expect(scene.bodies.length, id).toBeGreaterThan(0);
      expect(scene.track.length, id).toBeGreaterThan(0);
    }
  });
});

describe('bench memory measurement', () => {
  it('counts the bytes of a known allocation within 10%', () => {
    const n = 2000;
    const keep: number[][] = [];
    const { bytes } = measureAllocation(() => {
      for (let i = 0; i < n; i++) {
        const a = new Array<number>(1000).fill(0.5); // a FixedDoubleArray of 8,000 bytes + headers
        if (i % 100 === 0) keep.push(a);
      }
    });
    expect(keep.length).toBe(20);
    expect(bytes / n).toBeGreaterThan(8000 * 0.9);
    expect(bytes / n).toBeLessThan(8000 * 1.1);
  });

  it('gives no world heap where the built world does not weigh more than the empty one', () => {
    expect(worldHeapBytes(5_000_000, 3_000_000)).toBe(2_000_000);
    expect(worldHeapBytes(3_000_000, 3_000_000)).toBeNull();
    expect(worldHeapBytes(20_000_000, 46_000_000)).toBeNull();
  });
});

describe('Box2DWeb 2.1a loader', () => {
  it('runs a world from the box2dweb package and leaves Object.defineProperty alone', () => {
    const defineProperty = Object.defineProperty;
    const Box2D = loadBox2DWeb();
    expect(Object.defineProperty).toBe(defineProperty);
    const { b2Vec2 } = Box2D.Common.Math;
    const { b2World, b2BodyDef, b2Body, b2FixtureDef } = Box2D.Dynamics;
    const world = new b2World(new b2Vec2(0, -10), true);
    const bd = new b2BodyDef();
    bd.type = b2Body.b2_dynamicBody;
    bd.position.Set(0, 4);
    const body = world.CreateBody(bd);
    const fd = new b2FixtureDef();
    fd.shape = new Box2D.Collision.Shapes.b2PolygonShape();
    fd.shape.SetAsBox(1, 1);
    fd.density = 1;
    body.CreateFixture(fd);
    for (let i = 0; i < 60; i++) world.Step(1 / 60, 8, 3);
    expect(body.GetPosition().y).toBeLessThan(0);
  });
});

describe('the machine record', () => {
  it("reads the first CPU's data caches from sysfs, skipping instruction caches and unreadable entries, and says them in words", () => {
    const dir = mkdtempSync(path.join(tmpdir(), 'webphysics-caches-'));
    try {
      const index = (n: number, level: number, type: string, size: string, shared: string): void => {
        const d = path.join(dir, `index${n}`);
        mkdirSync(d);
        for (const [f, v] of Object.entries({ level, type, size, shared_cpu_list: shared })) writeFileSync(path.join(d, f), `${v}\n`);
      };
      index(0, 1, 'Data', '32K', '0');
      index(1, 1, 'Instruction', '32K', '0');
      index(2, 2, 'Unified', '2048K', '0');
      index(3, 3, 'Unified', '491520K', '0-1,4,6-7');
      mkdirSync(path.join(dir, 'index4'));
      writeFileSync(path.join(dir, 'uevent'), '');
      const caches = cpuCaches(dir);
      expect(caches).toEqual([
        { level: 1, kib: 32, sharedBy: 1 },
        { level: 2, kib: 2048, sharedBy: 1 },
        { level: 3, kib: 491520, sharedBy: 5 },
      ]);
      expect(describeCaches(caches)).toBe('L1 32 KiB, L2 2 MiB, L3 480 MiB shared by 5 CPUs');
    } finally {
      rmSync(dir, { recursive: true, force: true });
    }
  });

  it('has no caches where sysfs lists none, and says nothing of them', () => {
    expect(cpuCaches(path.join(tmpdir(), 'webphysics-no-such-dir'))).toEqual([]);
    expect(describeCaches([])).toBe('');
    expect(describeCaches()).toBe('');
  });
});
