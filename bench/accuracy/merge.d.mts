// Types for bench/accuracy/merge.mjs.
import type { AccuracyRun } from './run.mjs';

export function mergeLimits(base: AccuracyRun, extras: AccuracyRun[]): AccuracyRun;
