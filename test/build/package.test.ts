/*
 * The package as users get it: `npm run build` and `npm pack` (test/support/bundles.ts), the
 * tarball installed by npm into a new project, then used the ways users reported broken:
 * - TypeScript: an app of `webphysics` and `webphysics/gpu` type-checks under the tsconfig.json
 *   of `tsc --init` (module NodeNext) and under Node16 and Bundler resolution, with and without
 *   skipLibCheck, with nothing else installed (the GPU types come from the package's dependency
 *   @webgpu/types) and beside Dawn's own `webgpu` types;
 * - `require('webphysics')` from a CommonJS file;
 * - `webphysics/gpu` in Node, which finds Dawn (the `webgpu` package) when it is installed;
 * - esbuild, Vite, webpack and Rollup bundle a page of both entries with no options beyond the
 *   entry and the output, and the bundled page steps a world on JavaScript and then on WebGPU in
 *   headless Chromium (SwiftShader), without console errors;
 * - the README's first programs, as a reader copies them: the ES module (the ```js block after
 *   `<!-- readme-program: esm -->`) run by Node in the app, and the classic-script page (the ```html
 *   block after `<!-- readme-program: script -->`) loading the installed dist/box2d.js in headless
 *   Chromium. Each prints what the comment on its console.log line says it prints.
 */

import { execFileSync } from 'node:child_process';
import { copyFileSync, existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { nodeResolve } from '@rollup/plugin-node-resolve';
import { build as esbuild } from 'esbuild';
import { rollup } from 'rollup';
import { build as vite, createLogger } from 'vite';
import webpack from 'webpack';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { startServer } from '../../scripts/serve.mjs';
import { collectErrors, launchChromium } from '../browser/chromium';
import type { LaunchedBrowser } from '../browser/chromium';
import { packPackage, repoRoot } from '../support/bundles';
import type { PackedPackage } from '../support/bundles';
import { tsc, typeCheck } from '../support/typescript';

let packed: PackedPackage;
let root = '';
let app = '';

beforeAll(() => {
  packed = packPackage();
  root = mkdtempSync(path.join(tmpdir(), 'webphysics-package-'));
  app = path.join(root, 'app');
  mkdirSync(app);
  writeFileSync(path.join(app, 'package.json'), JSON.stringify({ name: 'app', private: true, type: 'module' }));
  // The tarball itself is local; its dependency @webgpu/types comes from npm's cache when it is there.
  execFileSync('npm', ['install', '--prefer-offline', '--no-audit', '--no-fund', packed.tarball], { cwd: app, stdio: 'pipe' });
  execFileSync(process.execPath, [tsc, '--init'], { cwd: app, stdio: 'pipe' });
}, 180_000);

afterAll(() => {
  packed?.remove();
  if (root !== '') rmSync(root, { recursive: true, force: true });
});

/** Makes the repository's Dawn (`webgpu`, a dev dependency) installed in the app, as `npm install webgpu` would. */
function installDawn(): void {
  const link = path.join(app, 'node_modules/webgpu');
  if (!existsSync(link)) symlinkSync(path.join(repoRoot, 'node_modules/webgpu'), link, 'dir');
}

/** Runs a script of the app with Node; its stdout parsed as JSON. */
function runNode(file: string, source: string): any {
  writeFileSync(path.join(app, file), source);
  return JSON.parse(execFileSync(process.execPath, [file], { cwd: app, encoding: 'utf8' }));
}

describe('the packed package', () => {
  it('holds the builds, the declarations without maps, and every file its exports name', () => {
    for (const file of [
      'dist/webphysics.mjs',
      'dist/webphysics.cjs',
      'dist/webphysics-gpu.mjs',
      'dist/webphysics-gpu.node.mjs',
      'dist/box2d.js',
      'dist/cli.mjs',
      'dist/types/index.d.ts',
      'dist/types/gpu/index.d.ts',
      'bin/webphysics.mjs',
      'scenes/pyramid.scene.json',
    ]) {
      expect(packed.files).toContain(file);
    }
    expect(packed.files.filter((f) => f.endsWith('.d.ts.map') || f.startsWith('src'))).toEqual([]);
    const pkg = JSON.parse(readFileSync(path.join(app, 'node_modules/webphysics/package.json'), 'utf8'));
    const targets: string[] = [];
    const walk = (value: unknown): void => {
      if (typeof value === 'string') targets.push(value.replace(/^\.\//, ''));
      else if (typeof value === 'object' && value !== null) Object.values(value).forEach(walk);
    };
    walk(pkg.exports);
    expect(targets.length).toBeGreaterThan(8);
    expect(targets.filter((t) => !packed.files.includes(t))).toEqual([]);
    // The JavaScript source maps carry their sources, since src/ is not shipped.
    for (const map of packed.files.filter((f) => f.endsWith('.map'))) {
      const { sources, sourcesContent } = JSON.parse(readFileSync(path.join(app, 'node_modules/webphysics', map), 'utf8'));
      expect(sourcesContent?.length, map).toBe(sources.length);
    }
    // The browser build of webphysics/gpu leaves nothing for a bundler to resolve.
    expect(readFileSync(path.join(app, 'node_modules/webphysics/dist/webphysics-gpu.mjs'), 'utf8')).not.toMatch(/\bimport\s*\(|node:/);
  });
});

/** An app of both entries; the @ts-expect-error lines fail if a type resolved to `any`. */
const kApp = `import { b2World, b2Vec2, b2BodyDef, b2_dynamicBody, b2PolygonShape } from 'webphysics';
import type { b2Body } from 'webphysics';
import { WebGPUBackend, requestGpu, GpuUnavailableError } from 'webphysics/gpu';

const world = new b2World(new b2Vec2(0, -10));
const def = new b2BodyDef();
def.type = b2_dynamicBody;
const body: b2Body = world.CreateBody(def);
const box = new b2PolygonShape();
box.SetAsBox(1, 1);
body.CreateFixture(box, 1);
// @ts-expect-error: a number is not a body definition
world.CreateBody(42);
const context = await requestGpu();
const device: GPUDevice = context.device;
// @ts-expect-error: a number is not a GPUBuffer
const buffer: GPUBuffer = 3;
await world.SetBackend(await WebGPUBackend.create({ context }));
console.log(device.label, buffer, body.GetPosition().y, GpuUnavailableError.name);
`;

describe('TypeScript against the installed package', () => {
  const settings: [string, Record<string, unknown>][] = [
    ['NodeNext (tsc --init)', {}],
    ['Node16', { module: 'node16', moduleResolution: 'node16' }],
    ['Bundler', { module: 'esnext', moduleResolution: 'bundler' }],
  ];
  for (const [name, options] of settings) {
    for (const skipLibCheck of [true, false]) {
      it(`type-checks an app of webphysics and webphysics/gpu under ${name}, skipLibCheck ${skipLibCheck}`, () => {
        writeFileSync(path.join(app, 'app.ts'), kApp);
        const config = { extends: './tsconfig.json', compilerOptions: { ...options, skipLibCheck, noEmit: true }, files: ['app.ts'] };
        expect(typeCheck(app, `${name.split(' ')[0]}-${skipLibCheck}`, config)).toBe('');
      });
    }
  }

  it('type-checks a CommonJS file that requires webphysics under NodeNext', () => {
    writeFileSync(
      path.join(app, 'cjs-app.cts'),
      `import webphysics = require('webphysics');
const world = new webphysics.b2World(new webphysics.b2Vec2(0, -10));
// @ts-expect-error: a number is not a body definition
world.CreateBody(42);
export = world.GetBodyCount();
`,
    );
    const config = { extends: './tsconfig.json', compilerOptions: { skipLibCheck: false, noEmit: true }, files: ['cjs-app.cts'] };
    expect(typeCheck(app, 'cjs', config)).toBe('');
  });

  it("type-checks an app that hands webphysics/gpu a GPU from Dawn's webgpu package", () => {
    installDawn();
    writeFileSync(
      path.join(app, 'dawn-app.ts'),
      `import { create } from 'webgpu';
import { requestGpu } from 'webphysics/gpu';
const context = await requestGpu({ gpu: create([]) });
const device: GPUDevice = context.device;
console.log(device.label);
`,
    );
    const config = { extends: './tsconfig.json', compilerOptions: { skipLibCheck: false, noEmit: true }, files: ['dawn-app.ts'] };
    expect(typeCheck(app, 'dawn', config)).toBe('');
  });
});

describe('Node and the installed package', () => {
  it("require('webphysics') loads the CommonJS build and runs a world", () => {
    const result = runNode(
      'drop.cjs',
      `const { b2World, b2Vec2, b2BodyDef, b2_dynamicBody, b2PolygonShape } = require('webphysics');
const world = new b2World(new b2Vec2(0, -10));
const def = new b2BodyDef();
def.type = b2_dynamicBody;
def.position.Set(0, 4);
const body = world.CreateBody(def);
const box = new b2PolygonShape();
box.SetAsBox(1, 1);
body.CreateFixture(box, 1);
for (let i = 0; i < 60; i++) world.Step(1 / 60, 8, 3);
console.log(JSON.stringify({ resolved: require.resolve('webphysics'), y: body.GetPosition().y }));
`,
    );
    expect(result.resolved).toBe(path.join(app, 'node_modules/webphysics/dist/webphysics.cjs'));
    expect(result.y).toBeCloseTo(4 - (10 * 61) / (2 * 60), 12);
  });

  const kRequestGpu = `const { requestGpu } = await import('webphysics/gpu');
const resolved = import.meta.resolve('webphysics/gpu');
try {
  const context = await requestGpu();
  console.log(JSON.stringify({ resolved, source: context.adapterInfo.source }));
  context.destroy();
} catch (error) {
  console.log(JSON.stringify({ resolved, error: error.name + ': ' + error.message }));
}
`;

  it('webphysics/gpu in Node says to install webgpu when it is missing, and finds Dawn once it is installed', () => {
    const link = path.join(app, 'node_modules/webgpu');
    rmSync(link, { force: true });
    const without = runNode('gpu.mjs', kRequestGpu);
    expect(without.resolved).toMatch(/\/node_modules\/webphysics\/dist\/webphysics-gpu\.node\.mjs$/);
    expect(without.error).toMatch(/^GpuUnavailableError: .*npm install webgpu/);
    installDawn();
    const withDawn = runNode('gpu.mjs', kRequestGpu);
    expect(withDawn.error).toBeUndefined();
    expect(withDawn.source).toMatch(/^dawn/);
  });
});

/** The page: a box dropped for 60 steps on JavaScript, then 5 more on the WebGPU backend. */
const kPage = `import { b2World, b2Vec2, b2BodyDef, b2_dynamicBody, b2PolygonShape } from 'webphysics';
import { WebGPUBackend } from 'webphysics/gpu';

async function run() {
  const world = new b2World(new b2Vec2(0, -10));
  const def = new b2BodyDef();
  def.type = b2_dynamicBody;
  def.position.Set(0, 4);
  const body = world.CreateBody(def);
  const box = new b2PolygonShape();
  box.SetAsBox(1, 1);
  body.CreateFixture(box, 1);
  for (let i = 0; i < 60; i++) world.Step(1 / 60, 8, 3);
  const js = body.GetPosition().y;
  const backend = await WebGPUBackend.create();
  await world.SetBackend(backend);
  for (let i = 0; i < 5; i++) await world.StepAsync(1 / 60, 8, 3);
  return { js, gpu: body.GetPosition().y, adapter: backend.ctx.adapterInfo.source };
}
window.result = run().catch((error) => ({ error: String(error && error.stack || error) }));
`;
const kHtml = '<!doctype html><meta charset="utf-8"><link rel="icon" href="data:,"><script type="module" src="./main.js"></script>\n';

/** Bundle-size advice, which is all the bundlers may warn about. */
const kSizeAdvice = /Some chunks are larger than|AssetsOverSizeLimitWarning|EntrypointsOverSizeLimitWarning|NoAsyncChunksWarning/;

/** Each bundler builds page/main.js (and Vite page/index.html) into `out`; resolves to its warnings. */
const bundlers: Record<string, (page: string, out: string) => Promise<string[]>> = {
  async esbuild(page, out) {
    const result = await esbuild({ entryPoints: [path.join(page, 'main.js')], bundle: true, outdir: out, logLevel: 'silent' });
    copyFileSync(path.join(page, 'index.html'), path.join(out, 'index.html'));
    return result.warnings.map((w) => w.text);
  },
  async vite(page, out) {
    const warnings: string[] = [];
    const logger = createLogger('warn');
    logger.warn = (message) => void warnings.push(message);
    logger.warnOnce = logger.warn;
    await vite({ root: page, configFile: false, logLevel: 'warn', customLogger: logger, build: { outDir: out } });
    return warnings;
  },
  async webpack(page, out) {
    const stats = await new Promise<webpack.Stats>((resolve, reject) =>
      webpack({ mode: 'production', entry: path.join(page, 'main.js'), output: { path: out } }, (error, result) =>
        error || !result ? reject(error) : resolve(result),
      ),
    );
    if (stats.hasErrors()) throw new Error(stats.toString({ all: false, errors: true }));
    copyFileSync(path.join(page, 'index.html'), path.join(out, 'index.html'));
    return stats.compilation.warnings.map((w) => `${w.name}: ${w.message}`);
  },
  async rollup(page, out) {
    const warnings: string[] = [];
    const bundle = await rollup({ input: path.join(page, 'main.js'), plugins: [nodeResolve()], onwarn: (w) => void warnings.push(w.message) });
    await bundle.write({ file: path.join(out, 'main.js') });
    await bundle.close();
    copyFileSync(path.join(page, 'index.html'), path.join(out, 'index.html'));
    return warnings;
  },
};

describe('bundlers and the browser', () => {
  let chromium: LaunchedBrowser;
  let page = '';

  beforeAll(async () => {
    page = path.join(app, 'page');
    mkdirSync(page, { recursive: true });
    writeFileSync(path.join(page, 'main.js'), kPage);
    writeFileSync(path.join(page, 'index.html'), kHtml);
    chromium = await launchChromium({ webgpu: true });
  }, 60_000);

  afterAll(async () => {
    await chromium?.close();
  });

  for (const [name, bundle] of Object.entries(bundlers)) {
    it(`${name} bundles webphysics and webphysics/gpu with no options, and the page runs both in Chromium`, async () => {
      const out = path.join(page, `dist-${name}`);
      const warnings = await bundle(page, out);
      expect(warnings.filter((w) => !kSizeAdvice.test(w))).toEqual([]);
      // No Node module left in the output, even one a bundler let through as external.
      for (const file of readdirSync(out, { recursive: true, encoding: 'utf8' }).filter((f) => f.endsWith('.js'))) {
        expect(readFileSync(path.join(out, file), 'utf8'), file).not.toMatch(/["']node:[a-z]/);
      }
      const server = await startServer({ root: out, port: 0 });
      const tab = await chromium.browser.newPage();
      try {
        const errors = collectErrors(tab);
        await tab.goto(server.url, { waitUntil: 'load' });
        await tab.waitForFunction(() => (window as { result?: unknown }).result !== undefined);
        const result = await tab.evaluate(() => (window as unknown as { result: Promise<Record<string, unknown>> }).result);
        expect(result.error).toBeUndefined();
        expect(result.js).toBeCloseTo(4 - (10 * 61) / (2 * 60), 12);
        // Five more steps of free fall, in float32 on the GPU.
        expect(result.gpu).toBeCloseTo(4 - (10 * 65 * 66) / (2 * 3600), 5);
        expect(result.adapter).toBe('navigator');
        expect(errors).toEqual([]);
      } finally {
        await tab.close();
        await server.close();
      }
    });
  }
});

/** The first fenced block of `language` right after the line `<!-- readme-program: name -->` in the README. */
function readmeProgram(name: string, language: string): string {
  const lines = readFileSync(path.join(repoRoot, 'README.md'), 'utf8').split('\n');
  for (let i = 0; i + 1 < lines.length; i++) {
    if (lines[i].trim() !== `<!-- readme-program: ${name} -->` || lines[i + 1].trim() !== `\`\`\`${language}`) continue;
    const end = lines.findIndex((line, j) => j > i + 1 && line.trim() === '```');
    if (end < 0) throw new Error(`README.md: the ${language} block after <!-- readme-program: ${name} --> is not closed`);
    return lines.slice(i + 2, end).join('\n') + '\n';
  }
  throw new Error(`README.md has no \`\`\`${language} block right after a line <!-- readme-program: ${name} -->`);
}

/**
 * What the program says it prints: the numbers that open the comment on its console.log line
 * (`console.log(p.x.toFixed(2), ...); // 0.00 1.01 0.00, as ...` -> ['0.00', '1.01', '0.00']).
 */
function statedOutput(program: string): string[] {
  const line = program.split('\n').find((l) => /console\.log\(/.test(l) && /\/\/\s*-?\d/.test(l));
  if (line === undefined) throw new Error('the program has no console.log line whose comment says what it prints');
  return line
    .slice(line.lastIndexOf('//') + 2)
    .match(/^(\s*-?\d+(\.\d+)?,?)+/)![0]
    .match(/-?\d+(\.\d+)?/g)!;
}

/** The last numbers of a printed line, as many as `stated` has. */
function lastNumbers(line: string, stated: string[]): string[] {
  return (line.match(/-?\d+(\.\d+)?/g) ?? []).slice(-stated.length);
}

describe("the README's first programs, against the installed package", () => {
  it('the ES module (node hello.mjs) prints what the README says', () => {
    const program = readmeProgram('esm', 'js');
    expect(program).toMatch(/from 'webphysics'/);
    const stated = statedOutput(program);
    writeFileSync(path.join(app, 'readme-hello.mjs'), program);
    const printed = execFileSync(process.execPath, ['readme-hello.mjs'], { cwd: app, encoding: 'utf8' }).trim().split('\n');
    expect(printed.length).toBeGreaterThan(0);
    expect(lastNumbers(printed[printed.length - 1], stated)).toEqual(stated);
  });

  it('the classic-script page (Box2DWeb style) runs on the installed dist/box2d.js in Chromium and logs what the README says', async () => {
    const program = readmeProgram('script', 'html');
    const stated = statedOutput(program);
    // The page's script src names the package's classic bundle; served from the app, it is the installed file.
    let bundles = 0;
    const html = program.replace(/(<script\s+src=")([^"]*)(")/g, (whole, open: string, src: string, close: string) => {
      const file = /(?:^|\/)(box2d(?:\.min)?\.js)$/.exec(src)?.[1];
      if (file === undefined) return whole;
      bundles++;
      return `${open}/node_modules/webphysics/dist/${file}${close}`;
    });
    expect(bundles).toBe(1);
    expect(existsSync(path.join(app, 'node_modules/webphysics/dist/box2d.js'))).toBe(true);
    writeFileSync(path.join(app, 'readme-script.html'), html);
    // The browser's request for /favicon.ico, which the page does not name, answered (not a 404 to count as an error).
    writeFileSync(path.join(app, 'favicon.ico'), '');
    const chromium = await launchChromium();
    const server = await startServer({ root: app, port: 0 });
    try {
      const tab = await chromium.browser.newPage();
      const errors = collectErrors(tab);
      const logged: string[] = [];
      tab.on('console', (message) => {
        if (message.type() === 'log') logged.push(message.text());
      });
      await tab.goto(new URL('readme-script.html', server.url).href, { waitUntil: 'load' });
      const deadline = Date.now() + 30_000;
      while (logged.length === 0 && errors.length === 0 && Date.now() < deadline) await new Promise((resolve) => setTimeout(resolve, 50));
      expect(errors).toEqual([]);
      expect(logged.length).toBeGreaterThan(0);
      expect(lastNumbers(logged[0], stated)).toEqual(stated);
      await tab.close();
    } finally {
      await server.close();
      await chromium.close();
    }
  }, 60_000);
});
