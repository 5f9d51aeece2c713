// Types for bench/memory.mjs.
export function fullGC(): void;
export function usedHeap(): number;
export function retainedHeap(): number;
export function measureAllocation(fn: () => void): { bytes: number; gcCount: number; scavenges: number; majors: number; gcMs: number };
