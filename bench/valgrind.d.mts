// Types for bench/valgrind.mjs.
export function eventTotals(text: string): Record<string, number>;
export function costsByCodeObject(callgrindText: string, perfMapText: string): { events: string[]; costs: Map<string, number[]> };
