/*
 * The published type declarations: scripts/build-types.mjs writes dist/types into a temporary
 * package (with the repository's package.json, so its `exports` and `types` are the ones
 * resolved), and small TypeScript apps in test/api/fixtures/types compile against it: one on the
 * ES module, one on the Box2D namespace object, and one page script on the classic bundle's
 * global Box2D. Each has @ts-expect-error lines, so the declarations must be real types, not
 * `any`. test/build/package.test.ts checks the packed package under other module settings.
 */

import { execFileSync } from 'node:child_process';
import { copyFileSync, mkdirSync, mkdtempSync, rmSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { repoRoot } from '../support/bundles';
import { typeCheck } from '../support/typescript';

let root = '';

beforeAll(() => {
  root = mkdtempSync(path.join(tmpdir(), 'webphysics-types-'));
  const pkg = path.join(root, 'node_modules/webphysics');
  mkdirSync(pkg, { recursive: true });
  copyFileSync(path.join(repoRoot, 'package.json'), path.join(pkg, 'package.json'));
  execFileSync(process.execPath, [path.join(repoRoot, 'scripts/build-types.mjs'), path.join(pkg, 'dist')], { cwd: repoRoot });
  const app = path.join(root, 'app');
  mkdirSync(app);
  symlinkSync(path.join(root, 'node_modules'), path.join(app, 'node_modules'), 'dir');
  for (const file of ['es-app.ts', 'namespace-app.ts', 'script-app.ts']) {
    copyFileSync(path.join(repoRoot, 'test/api/fixtures/types', file), path.join(app, file));
  }
}, 120_000);

afterAll(() => {
  rmSync(root, { recursive: true, force: true });
});

/** Type-check `files` of the app with a strict browser-app configuration; tsc's output, '' if clean. */
function typeCheckApp(files: string[]): string {
  return typeCheck(path.join(root, 'app'), files[0], {
    compilerOptions: {
      target: 'ES2022',
      module: 'ESNext',
      moduleResolution: 'Bundler',
      lib: ['ES2022', 'DOM'],
      types: [],
      strict: true,
      noEmit: true,
      skipLibCheck: false,
    },
    files,
  });
}

describe('the type declarations in dist/types', () => {
  it("type an ES module app that imports 'webphysics', with 2.2.1 and 2.1a calls", () => {
    expect(typeCheckApp(['es-app.ts'])).toBe('');
  });

  it('type an app that uses the Box2D namespace object, its members usable as types', () => {
    expect(typeCheckApp(['namespace-app.ts'])).toBe('');
  });

  it('type a page script using the global Box2D of box2d.js through webphysics/global', () => {
    expect(typeCheckApp(['script-app.ts'])).toBe('');
  });

  it('reject code that misuses the API', () => {
    const bad = path.join(root, 'app', 'bad-app.ts');
    writeFileSync(bad, "import { b2World, b2Vec2 } from 'webphysics';\nnew b2World(new b2Vec2(0, 10)).CreateBody(42);\n");
    expect(typeCheckApp(['bad-app.ts'])).toMatch(/bad-app\.ts\(2,\d+\): error TS2345/);
  });
});
