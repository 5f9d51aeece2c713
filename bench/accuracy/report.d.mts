// Types for bench/accuracy/report.mjs.
import type { AccuracyResult, AccuracyRun, AccuracyScene } from './run.mjs';

export const MEASURE_UNITS: Record<string, string>;
export function labelOf(run: AccuracyRun, result: AccuracyResult): string;
export function paretoFront(results: AccuracyResult[], measure: string): AccuracyResult[];
export function paretoSvg(scene: AccuracyScene, measure: string, run: AccuracyRun): string;
export function accuracyMarkdown(run: AccuracyRun): string;
