// WebPhysics (this package), loaded from the esbuild bundle the harness builds at the start of the
// run (what users get from dist/webphysics.mjs), or from the bundle given as `ours`.
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { repoRoot } from './common.mjs';
import { createBox2D221World } from './box2d221.mjs';

export default {
  id: 'webphysics',
  name: 'WebPhysics',
  family: 'Box2D 2.2.1, TypeScript',
  version: JSON.parse(readFileSync(path.join(repoRoot, 'package.json'), 'utf8')).version,
  notes: [],

  async load({ oursBundle }) {
    return import(pathToFileURL(oursBundle).href);
  },

  supports() {
    return null;
  },

  create(B, scene, { sleep }) {
    return createBox2D221World(B, scene, { sleep });
  },
};
