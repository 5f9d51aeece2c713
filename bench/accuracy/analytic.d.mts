// Types for bench/accuracy/analytic.mjs (plain JavaScript so the study runs without a build).

export function freeFall(y0: number, v0: number, g: number, dt: number, n: number): { steps: { y: number; v: number }; exact: { y: number; v: number } };
export function agm(a: number, b: number): number;
export function pendulumPeriod(length: number, g: number, amplitude: number): number;
export function bounceHeights(h0: number, restitution: number, count: number): number[];
export function slidingDistance(v0: number, mu: number, g: number): number;
export function projectileRange(v: number, theta: number, g: number): number;
