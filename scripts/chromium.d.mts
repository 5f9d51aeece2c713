// Types for scripts/chromium.mjs.

/** The Chromium or Chrome executable; throws, saying how to get one, when there is none. */
export function chromiumPath(): string;
/** The flags that make Chromium run offline, without a display, in a fresh profile (with WebGPU on SwiftShader when asked). */
export function chromiumArgs(options?: { webgpu?: boolean }): string[];
