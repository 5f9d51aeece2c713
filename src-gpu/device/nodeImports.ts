/*
 * The Node modules the WebGPU backend loads in Node: Dawn (the `webgpu` package) and the file
 * system, to look for Vulkan drivers. Only ./node.ts imports this file, and only Node's code path
 * calls it. The browser build of webphysics/gpu puts ./nodeImports.browser.ts in its place
 * (scripts/build.mjs), so a bundler never has `node:*` or Dawn to resolve.
 */

import type { IcdSearchEnv } from './node';

/** import() of a package, resolved from the importing bundle (Dawn: `webgpu` beside webphysics). */
export function importPackage(name: string): Promise<unknown> {
  return import(/* @vite-ignore */ name);
}

/** The real environment, home folder and file system probes. */
export async function nodeSearchEnv(): Promise<IcdSearchEnv> {
  const fs = await import('node:fs');
  const os = await import('node:os');
  return {
    env: process.env,
    exists: (p) => fs.existsSync(p),
    list: (p) => {
      try {
        return fs.readdirSync(p);
      } catch {
        return [];
      }
    },
    home: os.homedir(),
  };
}
