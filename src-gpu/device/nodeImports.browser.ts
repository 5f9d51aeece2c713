/*
 * ./nodeImports.ts in the browser build of webphysics/gpu (dist/webphysics-gpu.mjs, which the
 * package's `browser` and `default` conditions select): the same functions without a Node import.
 * requestGpu() reaches them only where `process.versions.node` exists, i.e. when this build was
 * loaded in Node by mistake; loadDawn() then reports the message below.
 */

import type { IcdSearchEnv } from './node';

const kBrowserBuild = "this is the browser build of webphysics/gpu; Node's `node` export condition selects the build that loads Dawn";

export function importPackage(name: string): Promise<unknown> {
  return Promise.reject(new Error(`cannot load ${name}: ${kBrowserBuild}`));
}

export function nodeSearchEnv(): Promise<IcdSearchEnv> {
  return Promise.reject(new Error(`cannot probe the file system for Vulkan drivers: ${kBrowserBuild}`));
}
