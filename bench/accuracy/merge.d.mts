// Types for bench/accuracy/merge.mjs.
import type { AccuracyRun } from './run.mjs';

export function mergeStudies(base: AccuracyRun, extras: AccuracyRun[]): AccuracyRun;
