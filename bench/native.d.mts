// Types for bench/native.mjs (plain JavaScript so `node bench/processes.mjs` needs no build).
import type { Scene } from './scenes.mjs';

export const NATIVE_ENGINES: Record<string, { name: string; build: 'float32' | 'float64' }>;
export function box2dIncludeDir(dir: string): string;
export function float64Source(text: string): string;
export function nativeSceneText(scene: Scene, steps: number): string;
export function buildNative(dir: string, log?: (line: string) => void): Promise<{ float32: string; float64: string }>;
