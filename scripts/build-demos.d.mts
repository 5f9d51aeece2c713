// Types for scripts/build-demos.mjs.
import type { BuildContext } from 'esbuild';

export const repoRoot: string;
export const defaultOutDir: string;
/** Build the testbed page into outDir (default demos/dist); with watch, keep rebuilding. */
export function buildDemos(outDir?: string, options?: { watch?: boolean }): Promise<BuildContext | null>;
